#pragma once
// The options the run-like commands share (run, preview, params, sweep, concepts, convert,
// export-walls): one parser; each command names the options it takes and is refused the others
// (a --set given to convert would otherwise be ignored without a word). compare, calibrate and
// case parse their own (field/commands.h, case_command.h).
#include <string>
#include <vector>

namespace abrade::app
{
  struct CommandLine
  {
    std::string              command;
    std::string              file;
    std::vector<std::string> sets;
    std::string              output;
    std::string              format = "text";
    std::vector<std::string> varies;
    std::string              seeds, wall = "knife"; ///< seeds: each command has its default
    double                   edge_height = 0.04;
    int                      jobs = 0;
    bool                     quiet  = false;
    bool                     resume = false;
    std::vector<std::string> more_files; ///< concepts: the files after the first
    std::string              knives = "right_knife,left_knife";
    int                      lifetime_updates = 0;
    std::string              command_line; ///< as typed (summary.json's provenance)
  };

  /// @p args (the words after @p command) as options; an InputError names a bad one, and one
  /// that is not in @p takes ("--set", "--output", ...; "FILE": one file, "FILES": several).
  CommandLine parse(const std::string &command, const std::vector<std::string> &args, const std::string &typed,
                    const std::vector<std::string> &takes);

  /// "1,2,3" as seeds: whole numbers, 0 or more, none twice.
  std::vector<int> seed_list(const std::string &text);

  /// The output directory given in @p args: after --output or -o, or --output=DIR ("" if none).
  std::string output_option(const std::vector<std::string> &args);

  /// After a run that ended with @p rc: its report in @p directory (a failed report is a
  /// warning, not a failed run). Returns @p rc.
  int with_report(int rc, const std::string &directory);

  /// What mpirun (Open MPI, or a PMI launcher) told this process, known before MPI_Init.
  struct Launch
  {
    bool by_mpirun = false;
    int  rank = 0, size = 1;
  };
  Launch launch();
} // namespace abrade::app
