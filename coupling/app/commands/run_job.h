#pragma once
// The job of a parameter file, run (commands/run.cc): abrade run, and abrade preview (the part
// job of a case).
#include "../command_line.h"

namespace abrade::app
{
  /// Runs @p cl's job into its output directory; 0 when done (a failure throws).
  int run_job(const CommandLine &cl);
} // namespace abrade::app
