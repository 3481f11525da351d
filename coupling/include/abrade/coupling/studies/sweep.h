#pragma once
// Parameter sweeps with replicate beds: `abrade sweep FILE.prm --vary "Key=v1,v2,..." [--vary
// "Key2=..."] --seeds 1,2,3`. Several --vary make a grid (every combination). Every
// (combination, seed) is one `abrade run` (single-threaded, as many at a time as there are
// cores); the settled bed of each seed is made once per combination of the varied particle
// parameters (Particles/...) and reused by the others. The runs' tables are then reduced to
// mean and standard deviation over the seeds, per combination, for one wall. With
// --lifetime-updates N each combination's life too (a lifetime run of N updates on the same
// Lifetime/Seeds for all), paired against the first combination's (study_lives.h).
#include <string>
#include <vector>

namespace abrade::coupling
{
  struct SweepOptions
  {
    std::string              parameter_file;
    struct Vary
    {
      std::string              key; ///< "Section/Sub/Key"
      std::vector<std::string> values;
    };
    std::vector<Vary>        varies; ///< the grid: the first varies slowest
    double                   edge_height = 0.04; ///< [m] the wall's "edge": wear below it
    std::vector<int>         seeds = {1, 2, 3};
    std::vector<std::string> sets;   ///< extra overrides for every run
    std::string              output;
    std::string              wall = "knife";
    int                      jobs = 0; ///< concurrent runs; 0: number of cores
    int                      lifetime_updates = 0; ///< >0: each combination's life too (on the seeds' beds)
    bool                     quiet = false;
  };

  /// Parses "Key=v1,v2,v3" and appends it to the options' varies; throws InputError.
  void parse_vary(const std::string &text, SweepOptions &options);

  /// Runs the sweep and writes DIR/study.csv, DIR/study.md, DIR/plots/*.png,
  /// DIR/surfaces/*.vtp; returns 0, or throws.
  int run_sweep(const SweepOptions &options, const std::string &abrade_executable);
} // namespace abrade::coupling
