#pragma once
// A file's extension in lower case, with its dot (".stl"): what the readers dispatch on.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace abrade::io
{
  inline std::string lower_extension(const std::string &path)
  {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
  }
} // namespace abrade::io
