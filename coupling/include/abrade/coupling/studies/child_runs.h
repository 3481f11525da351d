#pragma once
// Studies made of many `abrade run`s (sweep, concepts): child processes, as many at a time as
// asked, their output tables read back.
#include <abrade/common/csv_reader.h>

#include <map>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// One `abrade run`: its output folder and the full shell command (output to DIR.log).
  struct ChildRun
  {
    std::string dir;
    std::string command;
  };

  /// `abrade run FILE --quiet --output DIR --set ...` for the executable @p abrade; the log
  /// goes to DIR.log.
  std::string run_command(const std::string &abrade, const std::string &file, const std::string &dir,
                          const std::vector<std::string> &sets);

  /// The entries a study sets on each of its cycles, whatever the file says: seed @p seed from
  /// the settled bed @p bed, one thread, no particle or snapshot output, Job = dem (a cycle,
  /// whatever the file's own job: a lifetime case's, say).
  std::vector<std::string> study_cycle_sets(int seed, const std::string &bed);
  /// InputError (exit 2) when one of @p sets ("Section/Key=value" or a key alone, given with
  /// @p option) names
  /// an entry that study_cycle_sets() sets, or with @p lives (the study's lifetime runs)
  /// lifetime_run_sets() (study_lives.h): it would be overridden without a word.
  void refuse_study_owned_sets(const std::vector<std::string> &sets, const std::string &option, bool lives);

  /// Runs @p runs, @p jobs at a time (0: one per core), with a progress line named @p what;
  /// throws RunError naming a failed run's log.
  void run_children(const std::vector<ChildRun> &runs, int jobs, const std::string &what);

  using io::CsvTable;
  /// A table a child run wrote; RunError when the run left none.
  CsvTable read_csv_table(const std::string &path);
} // namespace abrade::coupling
