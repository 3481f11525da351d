#include <abrade/common/error.h>
#include <abrade/common/output_directory.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <map>
#include <mutex>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

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

  namespace
  {
    /// The lock files this process holds, by canonical directory: a second claim of one (a
    /// command that calls another's code on the same directory) shares the first's lock, since
    /// flock() would refuse a second open file of the same process.
    std::map<std::string, std::weak_ptr<void>> &held_locks()
    {
      static std::map<std::string, std::weak_ptr<void>> held;
      return held;
    }

    /// An open lock file, closed (the lock released) with the last claim that shares it.
    struct LockFile
    {
      explicit LockFile(int fd) : fd(fd) {}
      ~LockFile() { ::close(fd); }
      LockFile(const LockFile &) = delete;
      LockFile &operator=(const LockFile &) = delete;
      const int fd;
    };

    /// The first symbolic link inside @p root (not following links), "" if none.
    std::string first_link_inside(const std::string &root)
    {
      namespace fs = std::filesystem;
      std::error_code ec;
      for (fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
           !ec && it != end; it.increment(ec))
        if (it->is_symlink(ec))
          return it->path().string();
      return "";
    }
  } // namespace

  void OutputDirectory::claim()
  {
    namespace fs = std::filesystem;
    static std::mutex           m;
    const std::lock_guard       g(m);
    std::error_code             ec;
    const std::string           key = fs::canonical(root_path, ec).string();
    if (ec)
      throw InputError(root_path, "cannot resolve the output directory: " + ec.message());
    if (auto held = held_locks()[key].lock())
      {
        lock = held;
        return;
      }
    const std::string lock_file = root_path + "/.abrade-lock";
    // O_NOFOLLOW: a link planted as the lock file is refused, not followed
    const int fd = ::open(lock_file.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0)
      throw InputError(lock_file, std::string("cannot create the output directory's lock file (") +
                                    std::strerror(errno) + ")");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
      {
        char          pid[32] = {};
        const ssize_t n       = ::pread(fd, pid, sizeof pid - 1, 0);
        ::close(fd);
        std::string other = n > 0 ? std::string(pid, std::size_t(n)) : "";
        other.erase(other.find_last_not_of(" \n") + 1);
        throw InputError(root_path, "another abrade run" + (other.empty() ? "" : " (pid " + other + ")") +
                                      " is writing into this output directory: wait for it to end, or "
                                      "choose another --output");
      }
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != ssize_t(pid.size()))
      {
        ::close(fd);
        throw RunError("cannot write " + lock_file + " (a full disk?)");
      }
    lock = std::make_shared<LockFile>(fd);
    held_locks()[key] = lock;
    if (const std::string link = first_link_inside(root_path); !link.empty())
      {
        std::error_code e;
        const auto      target = fs::read_symlink(link, e);
        throw InputError(link, "a symbolic link" + (e ? std::string() : " (to " + target.string() + ")") +
                                 " inside the output directory: abrade does not write through links out of "
                                 "it; remove the link, or choose another --output");
      }
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
