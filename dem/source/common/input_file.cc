// Input files checked before anything reads them: present, a regular file, readable
// (input_file.h).
#include <abrade/common/error.h>
#include <abrade/common/input_file.h>

#include <cerrno>
#include <cstring>

#include <sys/stat.h>
#include <unistd.h>

namespace abrade::io
{
  void require_input_file(const std::string &path, const std::string &what)
  {
    const std::string role = what.empty() ? "" : "the " + what + " ";
    if (path.empty())
      throw InputError(what.empty() ? "input file" : what, "no file named (the name is empty)");
    struct stat s;
    // stat() follows links: ELOOP is a loop of them, ENOENT also a dangling one
    if (::stat(path.c_str(), &s) != 0)
      {
        const int e = errno;
        if (e == ELOOP)
          throw InputError(path, role + "is a loop of symbolic links");
        if (e == ENOENT || e == ENOTDIR)
          {
            struct stat l;
            if (::lstat(path.c_str(), &l) == 0 && S_ISLNK(l.st_mode))
              throw InputError(path, role + "is a symbolic link to nothing (its target does not exist)");
            throw InputError(path, (what.empty() ? "file" : what) + " not found");
          }
        throw InputError(path, "cannot look at " + role + "(" + std::strerror(e) + ")");
      }
    if (S_ISDIR(s.st_mode))
      throw InputError(path, role + "is a directory, not a file");
    if (S_ISFIFO(s.st_mode))
      throw InputError(path, role + "is a pipe (FIFO), not a file: its reader could wait forever");
    if (S_ISCHR(s.st_mode) || S_ISBLK(s.st_mode))
      throw InputError(path, role + "is a device, not a file");
    if (S_ISSOCK(s.st_mode))
      throw InputError(path, role + "is a socket, not a file");
    if (!S_ISREG(s.st_mode))
      throw InputError(path, role + "is not a regular file");
    if (::access(path.c_str(), R_OK) != 0)
      throw InputError(path, "cannot read " + role + "(" + std::strerror(errno) + ")");
  }
} // namespace abrade::io
