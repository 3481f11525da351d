#pragma once
// Names compared ignoring case: a string in lower case, and a file's extension in lower case
// with its dot (".stl"), what the readers dispatch on.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace abrade::io
{
  inline std::string lower_case(std::string s)
  {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
  }

  inline std::string lower_extension(const std::string &path)
  {
    return lower_case(std::filesystem::path(path).extension().string());
  }
} // namespace abrade::io
