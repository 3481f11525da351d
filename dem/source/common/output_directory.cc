// The run's output directory: claimed (locked, refused when it holds another run's files or
// links out of it), and the paths inside it (output_directory.h).
#include <abrade/common/error.h>
#include <abrade/common/output_directory.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
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

    /// The first symbolic link in @p root or in the subdirectories abrade writes (walked
    /// whole), "" if none. Other folders of the user's in the directory are not entered
    /// (`--output .` in a home directory must not walk all of it).
    std::string first_link_inside(const std::string &root)
    {
      namespace fs = std::filesystem;
      static const std::set<std::string> ours = {"part",     "knife",      "checkpoint", "beds",  "particles", "walls",
                                                 "report",   "plots",      "runs",  "surfaces",  "lifetime",
                                                 "compare", "calibration"};
      std::error_code ec;
      for (fs::directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end; !ec && it != end;
           it.increment(ec))
        {
          if (it->is_symlink(ec))
            return it->path().string();
          const std::string name = it->path().filename().string();
          if (!it->is_directory(ec) || (!ours.count(name) && name.rfind(".rank-", 0) != 0))
            continue;
          for (fs::recursive_directory_iterator sub(it->path(), fs::directory_options::skip_permission_denied, ec),
               sub_end;
               !ec && sub != sub_end; sub.increment(ec))
            if (sub->is_symlink(ec))
              return sub->path().string();
        }
      return "";
    }
  } // namespace

  std::string part_folder(const std::string &run)
  {
    namespace fs = std::filesystem;
    std::error_code ec;
    return fs::is_directory(run + "/knife", ec) && !fs::exists(run + "/part", ec) ? "knife" : "part";
  }

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
    const int failed = ::flock(fd, LOCK_EX | LOCK_NB) == 0 ? 0 : errno;
    if (failed != 0 && failed != EWOULDBLOCK)
      // a file system without locks (NFS mounted nolock, Lustre noflock): the run goes on, said
      std::cerr << "warning: " << root_path << ": the file system cannot lock the output directory ("
                << std::strerror(failed) << "): a second run on it would not be refused" << std::endl;
    if (failed == EWOULDBLOCK)
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
