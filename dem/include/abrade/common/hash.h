#pragma once
// A stable 64-bit FNV-1a hash (hex string) of a text: the parameter hash in summary.json.
#include <cstdint>
#include <string>

namespace abrade::io
{
  inline std::string fnv1a_hex(const std::string &text)
  {
    std::uint64_t h = 14695981039346656037ULL;
    for (unsigned char c : text)
      {
        h ^= c;
        h *= 1099511628211ULL;
      }
    static const char *digits = "0123456789abcdef";
    std::string        out(16, '0');
    for (int i = 15; i >= 0; --i, h >>= 4)
      out[i] = digits[h & 15];
    return out;
  }
} // namespace abrade::io
