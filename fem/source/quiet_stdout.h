#pragma once
// OpenCASCADE's STEP writer prints a coloured transfer report to standard output, which no
// option of Gmsh turns off; the callers that write STEP files run it with standard output
// pointed at /dev/null (stdout is abrade's own: progress lines, results).
#include <cstdio>
#include <iostream>

#include <fcntl.h>
#include <unistd.h>

namespace abrade::fem
{
  template <typename F>
  void with_stdout_silenced(F &&f)
  {
    std::cout.flush();
    std::fflush(stdout);
    const int saved = ::dup(1), null = ::open("/dev/null", O_WRONLY);
    if (saved >= 0 && null >= 0)
      ::dup2(null, 1);
    auto restore = [&] {
      std::fflush(stdout);
      if (saved >= 0 && null >= 0)
        ::dup2(saved, 1);
      if (saved >= 0)
        ::close(saved);
      if (null >= 0)
        ::close(null);
    };
    try
      {
        f();
      }
    catch (...)
      {
        restore();
        throw;
      }
    restore();
  }
} // namespace abrade::fem
