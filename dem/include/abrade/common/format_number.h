#pragma once
// A number for a message: the shortest form with @p digits significant digits ("%.Ng": 0.001,
// 1e+09, 4497), the same in every error and log line of the project.
#include <cstdio>
#include <string>

namespace abrade::io
{
  inline std::string format_number(double x, int digits = 4)
  {
    char b[40];
    std::snprintf(b, sizeof b, "%.*g", digits, x);
    return b;
  }
} // namespace abrade::io
