#include <abrade/common/error.h>
#include <abrade/common/output_directory.h>

#include <filesystem>

namespace abrade::io
{
  OutputDirectory::OutputDirectory(std::string root, std::string shared)
    : root_path(std::move(root)), shared_path(shared.empty() ? root_path : std::move(shared))
  {
    std::error_code ec;
    std::filesystem::create_directories(root_path, ec);
    if (ec)
      throw InputError(root_path, "cannot create output directory: " + ec.message());
  }

  std::string OutputDirectory::subdirectory(const std::string &name) const
  {
    const std::string p = file(name);
    std::error_code   ec;
    std::filesystem::create_directories(p, ec);
    if (ec)
      throw RunError("cannot create " + p + ": " + ec.message());
    return p;
  }
} // namespace abrade::io
