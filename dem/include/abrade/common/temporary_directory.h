#pragma once
// A temporary directory of this process's own, for code that has no run directory to write
// into (a library call, a unit test): made once with mkdtemp (a name nobody can predict, made
// with exclusive create and mode 0700, so a link planted in the temporary folder cannot
// redirect a write) and removed with what it holds when the process exits normally. Runs pass
// their own output directory instead, so that nothing is written outside it.
#include <string>

namespace abrade::io
{
  /// The directory's path (made on the first call); throws RunError if it cannot be made.
  const std::string &private_temporary_directory();
} // namespace abrade::io
