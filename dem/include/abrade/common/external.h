#pragma once
// Running external programs: quoting for the shell, and gnuplot for the PNG plots (the data
// and the .gp script stay beside the PNG, so a failed plot loses nothing).
#include <string>
#include <vector>

namespace abrade::io
{
  /// @p s in single quotes for /bin/sh.
  std::string shell_quote(const std::string &s);

  /// Runs `gnuplot SCRIPT` in @p directory (where the script writes its PNGs), its output going
  /// to SCRIPT.log there. On failure (gnuplot missing, or an error in the script) prints one
  /// warning naming the script, unless @p quiet. Returns whether it succeeded.
  bool run_gnuplot(const std::string &directory, const std::string &script, bool quiet = false);

  /// The same for a run's declared pictures: @p outputs (relative to @p directory) must be there
  /// afterwards, not empty. Where gnuplot is not installed, one warning (the data and scripts
  /// stay); where it ran and a picture is missing (a full disk), a RunError naming the picture
  /// and what gnuplot said.
  void run_gnuplot_for(const std::string &directory, const std::string &script, const std::vector<std::string> &outputs);
} // namespace abrade::io
