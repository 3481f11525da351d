#pragma once
// The items of a list written in a parameter ('opening, closing', 'right, left'): split at a
// separator, each trimmed, empty ones left out; and such a list written again.
#include <abrade/common/file_extension.h>

#include <algorithm>
#include <string>
#include <vector>

namespace abrade::io
{
  inline std::vector<std::string> list_items(const std::string &text, char separator)
  {
    std::vector<std::string> out;
    for (std::size_t start = 0; start <= text.size();)
      {
        const std::size_t end = std::min(text.find(separator, start), text.size());
        if (std::string item = trimmed(text.substr(start, end - start)); !item.empty())
          out.push_back(std::move(item));
        start = end + 1;
      }
    return out;
  }

  /// @p items written as a list, @p separator between them ("a, b, c").
  inline std::string list_text(const std::vector<std::string> &items, const std::string &separator = ", ")
  {
    std::string text;
    for (const auto &item : items)
      text += (text.empty() ? "" : separator) + item;
    return text;
  }
} // namespace abrade::io
