#pragma once
// Running external programs: quoting for the shell, and gnuplot for the PNG plots (the data
// and the .gp script stay beside the PNG, so a failed plot loses nothing).
#include <string>

namespace abrade::io
{
  /// @p s in single quotes for /bin/sh.
  std::string shell_quote(const std::string &s);

  /// Runs `gnuplot SCRIPT` in @p directory (where the script writes its PNGs), its output going
  /// to SCRIPT.log there. On failure (gnuplot missing, or an error in the script) prints one
  /// warning naming the script, unless @p quiet. Returns whether it succeeded.
  bool run_gnuplot(const std::string &directory, const std::string &script, bool quiet = false);
} // namespace abrade::io
