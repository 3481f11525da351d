#pragma once
// How a run ends on SIGTERM, SIGINT (Ctrl-C) and SIGHUP (a closed terminal): at once, with a line
// on stderr saying so, summary.json replaced by one whose status is "interrupted", and exit code
// 128 + the signal (143, 130, 129). Checkpoints are written aside and renamed into place, so the
// last complete one is intact whenever the signal comes, and `abrade run ... --resume` continues
// a lifetime run from it. The handler makes only async-signal-safe calls (open, write, rename,
// _exit): the summary's text is prepared while the run is set up.
#include <string>

namespace abrade::io
{
  /// Installs the handlers (again, after a library such as Gmsh installed its own).
  void install_termination_handlers();

  /// The summary.json that a signal leaves: @p path and its complete @p text.
  void prepare_interrupted_summary(const std::string &path, const std::string &text);
} // namespace abrade::io
