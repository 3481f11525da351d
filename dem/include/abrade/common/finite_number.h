#pragma once
// A number read from a word of a file: all of the word, a finite value. One rule for every
// reader (state files, legacy VTK, PLY, CSV tables, .pvd times): "1.5e" and "nan" are not
// numbers, a subnormal such as 1e-320 is (strtod's ERANGE on underflow is not an error here).
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

namespace abrade::io
{
  inline std::optional<double> finite_number(const std::string &word)
  {
    char        *end = nullptr;
    const double x   = std::strtod(word.c_str(), &end);
    if (word.empty() || end != word.c_str() + word.size() || !std::isfinite(x))
      return std::nullopt;
    return x;
  }

  /// A whole number read from a word: all of the word, in a long's range ("12x", "1e3" and
  /// "99999999999999999999" are not).
  inline std::optional<long> whole_number(const std::string &word)
  {
    char *end = nullptr;
    errno     = 0;
    const long x = std::strtol(word.c_str(), &end, 10);
    if (word.empty() || end != word.c_str() + word.size() || errno == ERANGE)
      return std::nullopt;
    return x;
  }
} // namespace abrade::io
