// Temporary directories that remove themselves (temporary_directory.h).
#include <abrade/common/error.h>
#include <abrade/common/temporary_directory.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

namespace abrade::io
{
  namespace
  {
    std::string &made()
    {
      static std::string path;
      return path;
    }

    void remove_made()
    {
      std::error_code ec;
      std::filesystem::remove_all(made(), ec);
    }
  } // namespace

  const std::string &private_temporary_directory()
  {
    static std::once_flag once;
    std::call_once(once, [] {
      std::error_code   ec;
      const std::string base = std::filesystem::temp_directory_path(ec).string();
      std::string       pattern = (ec ? std::string("/tmp") : base) + "/abrade-XXXXXX";
      std::vector<char> name(pattern.begin(), pattern.end());
      name.push_back('\0');
      if (!::mkdtemp(name.data()))
        throw RunError("cannot make a temporary directory " + pattern + " (" + std::strerror(errno) + ")");
      made() = name.data();
      std::atexit(remove_made);
    });
    if (made().empty())
      throw RunError("no temporary directory (making it failed before)");
    return made();
  }
} // namespace abrade::io
