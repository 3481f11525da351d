#pragma once
// Reading a parameter file with deal.II's ParameterHandler, with errors a user can act on.
//
// Some subsections depend on the file itself (one "Wall NAME" subsection per name in "Walls"),
// so a file is read twice: a first lenient pass reads only those lists, then every parameter is
// declared and the file is read strictly. Every problem becomes an abrade::InputError with a
// one-line message naming the file, the line and the key. `include FILE` lines are expanded in
// place (relative to the including file, nested to any depth; a file that includes itself,
// directly or through others, is an error naming the chain), and every message names the file
// and line a parameter really comes from.
#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  struct DeclarationLists;

  /// "Section/Sub/Key=value" overrides from the command line.
  struct Override
  {
    std::vector<std::string> path; ///< subsections
    std::string              key, value, text;
  };
  Override parse_override(const std::string &text);

  class ParameterFile
  {
  public:
    /// Reads @p file (or the embedded default case when @p file is empty) and applies the
    /// overrides. Throws InputError.
    ParameterFile(const std::string &file, const std::vector<std::string> &overrides);

    /// Declares everything with the default lists (for `abrade params`).
    ParameterFile();

    dealii::ParameterHandler       &handler() { return prm; }
    const std::string              &file_name() const { return file; }
    /// @p path as named in this file: a relative path is relative to the file's directory (as is
    /// when the parameters came from no file, e.g. the embedded default case).
    std::string                     path_beside(const std::string &path) const;
    /// Where a key is set in the file ("file:line"), or just the file name.
    std::string locate(const std::vector<std::string> &path, const std::string &key) const;
    /// An InputError naming where @p key was set.
    [[noreturn]] void fail(const std::vector<std::string> &path, const std::string &key,
                           const std::string &message) const;
    /// The full parameter set (defaults included) as .prm text.
    std::string canonical_text();
    /// What makes a run the run it is: the canonical text less where it is written (a run moved
    /// to another directory, or named by another spelling of its own, resumes as itself).
    std::string identity_text();
    /// The files read: the parameter file and every file it includes (none for the default case).
    std::vector<std::string> files_read() const;
    /// What the reading decided that a user may want to know (a base case's entries left out).
    const std::vector<std::string> &notes() const { return notes_; }

  private:
    /// The walls listed: at most 1,000, names that can be file names, and each listed in the
    /// file's (or --set's) Walls has its 'Wall NAME' subsection.
    void check_wall_list(const DeclarationLists &lists, const std::vector<Override> &overrides) const;

    dealii::ParameterHandler prm;
    std::string              file;
    std::string              text; ///< the file's content, its includes expanded in place
    /// the file and line each line of text comes from (includes expanded)
    std::vector<std::pair<std::string, int>> origin;
    std::vector<std::string>                 notes_;
    std::vector<Override>                    overrides; ///< the --set overrides, in order
  };

  /// The embedded default case used by `abrade run` without a file.
  const std::string &default_case_text();
} // namespace abrade::coupling
