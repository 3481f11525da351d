// Files replaced at once: written aside, then renamed over (atomic_file.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>

#include <cstdio>
#include <fstream>

namespace abrade::io
{
  void write_file_atomically(const std::string &path, const std::string &text)
  {
    const std::string aside = path + ".tmp";
    {
      std::ofstream out(aside, std::ios::binary);
      out << text;
      out.close();
      if (!out)
        {
          std::remove(aside.c_str());
          throw RunError("cannot write " + path + " (disk full, or not writable?)");
        }
    }
    if (std::rename(aside.c_str(), path.c_str()) != 0)
      {
        std::remove(aside.c_str());
        throw RunError("cannot replace " + path);
      }
  }
} // namespace abrade::io
