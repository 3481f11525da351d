#pragma once
// Names compared ignoring case: a string in lower case, and a file's extension in lower case
// with its dot (".stl"), what the readers dispatch on; a word without the blanks around it.
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

  /// @p s without its leading and trailing blanks (spaces, tabs, line ends).
  inline std::string trimmed(const std::string &s)
  {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
      return "";
    return s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
  }

  inline std::string lower_extension(const std::string &path)
  {
    return lower_case(std::filesystem::path(path).extension().string());
  }
} // namespace abrade::io
