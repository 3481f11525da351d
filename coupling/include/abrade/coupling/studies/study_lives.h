#pragma once
// The lives of a study's variants (`abrade concepts` and `abrade sweep` with --lifetime-updates):
// each variant's lifetime run on the same Lifetime/Seeds, so that every update of every variant
// draws the same beds, and each life's change against the first variant's paired on them
// (lifetime/paired_life.h).
#include <abrade/coupling/lifetime/paired_life.h>
#include <abrade/coupling/studies/paired_change.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  /// A variant's life as its lifetime run left it.
  struct StudyLife
  {
    double             tonnes = 0, low = 0, high = 0; ///< [t]; 0: none (no life, no interval)
    bool               has_beds = false;              ///< life_beds.csv was there
    lifetime::LifeBeds beds;
  };

  /// The overrides that make a study's run a lifetime run of @p updates updates on the beds of
  /// @p seeds (appended to @p sets; Lifetime/Tonnes per cycle = 0: from the payload).
  std::vector<std::string> lifetime_run_sets(std::vector<std::string> sets, int updates, const std::vector<int> &seeds);

  /// The life of the lifetime run in @p dir (summary.json, life_beds.csv).
  StudyLife read_study_life(const std::string &dir);

  /// @p variant's life against @p baseline's: paired on their beds (paired_life.h) where both
  /// wrote them, else the two intervals combined on the log scale (as if independent: wider).
  PairedChange life_change(const StudyLife &variant, const StudyLife &baseline);
} // namespace abrade::coupling
