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

  /// Runs @p runs, @p jobs at a time (0: one per core), with a progress line named @p what;
  /// throws RunError naming a failed run's log.
  void run_children(const std::vector<ChildRun> &runs, int jobs, const std::string &what);

  using io::CsvTable;
  /// A table a child run wrote; RunError when the run left none.
  CsvTable read_csv_table(const std::string &path);
} // namespace abrade::coupling
