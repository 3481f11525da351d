#pragma once
// Parameter sweeps with replicate beds: `abrade sweep FILE.prm --vary "Key=v1,v2,..." --seeds
// 1,2,3`. Every (value, seed) pair is one `abrade run` (single-threaded, as many at a time as
// there are cores); the settled bed of each seed is made once and reused by all values (unless
// the varied parameter is a particle parameter, which would change the bed). The runs' tables
// are then reduced to mean and standard deviation over the seeds, per value, for one wall.
#include <string>
#include <vector>

namespace abrade::coupling
{
  struct SweepOptions
  {
    std::string              parameter_file;
    std::string              key;    ///< "Section/Sub/Key"
    std::vector<std::string> values;
    std::vector<int>         seeds = {1, 2, 3};
    std::vector<std::string> sets;   ///< extra overrides for every run
    std::string              output;
    std::string              wall = "knife";
    int                      jobs = 0; ///< concurrent runs; 0: number of cores
    bool                     quiet = false;
  };

  /// Parses "Key=v1,v2,v3" into key and values; throws InputError.
  void parse_vary(const std::string &text, SweepOptions &options);

  /// Runs the sweep and writes DIR/study.csv, DIR/study.md, DIR/plots/*.png,
  /// DIR/surfaces/*.vtp; returns 0, or throws.
  int run_sweep(const SweepOptions &options, const std::string &abrade_executable);
} // namespace abrade::coupling
