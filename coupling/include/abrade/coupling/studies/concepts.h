#pragma once
// Knife concepts compared on one operating cycle (`abrade concepts BASELINE.prm OTHER.prm ...`):
// every concept file (a complete case, typically including a common grab case and changing
// subsection Part) runs once per bed seed, all from the same settled beds; the knives' wear per
// phase and the payload per cycle are reduced to mean and spread over the seeds, and every
// concept is compared with the first (the baseline). Optionally each concept's knife life is
// predicted too (the lifetime job on the same case, a few updates).
#include <string>
#include <vector>

namespace abrade::coupling
{
  struct ConceptOptions
  {
    std::vector<std::string> files;                              ///< the first is the baseline
    std::vector<int>         seeds  = {1, 2};
    std::vector<std::string> knives = {"right_knife", "left_knife"}; ///< walls whose wear counts
    std::vector<std::string> sets;                               ///< overrides for every run
    std::string              output;
    int                      jobs             = 0;
    int                      lifetime_updates = 0;               ///< 0: no lifetime runs
    bool                     quiet            = false;
  };

  /// Runs the comparison; writes DIR/concepts.csv, DIR/concepts.md, DIR/wear.png and, with
  /// lifetime runs, DIR/lifetime/NAME/ and DIR/lifetime.png. Returns 0 or throws.
  int run_concepts(const ConceptOptions &options, const std::string &abrade_executable);
} // namespace abrade::coupling
