// Gmsh in a child process (meshing_job.h): the parent's side (spawn, wait with a time limit,
// read what the child left) and the child's (parse the job, mesh, write the notes or the error).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/termination.h>
#include <abrade/fem/meshing_job.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <sys/personality.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#ifndef ABRADE_MESHER_DEFAULT
#  define ABRADE_MESHER_DEFAULT ""
#endif

namespace abrade::fem
{
  namespace
  {
    /// The mesher executable: $ABRADE_MESHER, else abrade-mesher beside this executable, else
    /// the one of the build tree this library was built in; empty when none exists.
    std::string mesher_executable()
    {
      namespace fs = std::filesystem;
      if (const char *e = std::getenv("ABRADE_MESHER"); e && *e)
        {
          if (!fs::exists(e))
            throw InputError("ABRADE_MESHER", std::string("no mesher executable at '") + e + "'");
          return e;
        }
      std::error_code ec;
      const fs::path  self = fs::read_symlink("/proc/self/exe", ec);
      if (!ec && fs::exists(self.parent_path() / "abrade-mesher"))
        return (self.parent_path() / "abrade-mesher").string();
      if (*ABRADE_MESHER_DEFAULT && fs::exists(ABRADE_MESHER_DEFAULT))
        return ABRADE_MESHER_DEFAULT;
      return "";
    }

    std::string number(double x)
    {
      char b[40];
      std::snprintf(b, sizeof b, "%.17g", x);
      return b;
    }

    std::string read_text(const std::string &path)
    {
      std::ifstream      in(path);
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }

    std::vector<std::string> lines_of(const std::string &text)
    {
      std::vector<std::string> out;
      std::istringstream       in(text);
      for (std::string line; std::getline(in, line);)
        if (!line.empty())
          out.push_back(line);
      return out;
    }

    /// The last lines of the child's log (what Gmsh said before it died), on one line.
    std::string log_tail(const std::string &path)
    {
      auto        lines = lines_of(read_text(path));
      std::string tail;
      for (std::size_t k = lines.size() > 3 ? lines.size() - 3 : 0; k < lines.size(); ++k)
        tail += (tail.empty() ? "" : " | ") + lines[k].substr(0, 200);
      return tail;
    }

    /// The caller's time limit, else ABRADE_MESHER_TIME_LIMIT's, else 1800 s.
    double time_limit_of(const MeshingJob &job)
    {
      double time_limit = job.time_limit;
      if (const char *e = std::getenv("ABRADE_MESHER_TIME_LIMIT"); time_limit <= 0 && e && std::atof(e) > 0)
        time_limit = std::atof(e);
      return time_limit > 0 ? time_limit : 1800;
    }

    /// Where the child works: a directory of its own beside the job's output, its real path
    /// (symbolic links resolved, as the child's getcwd() sees it) of one length, holding the
    /// input and the output under fixed names and the mesher (the input and the mesher, their
    /// links resolved, hard-linked where they can be, else copied), so that the child is given
    /// the same arguments, in the same environment, from paths of the same length, whatever
    /// the paths of the run. Gmsh's meshes depend on where its data lie in memory (HXT orders
    /// by addresses; the parent fixes the child's addresses), and Gmsh keeps the paths of its
    /// executable and its working directory in memory: an output directory of another length,
    /// the mesher installed elsewhere, or one environment variable more or less gave another
    /// mesh of the same job. Made by mkdtemp (a name no other job, process or node has), padded
    /// by nested directories of at most 60 characters (file systems that allow short names
    /// only), removed with everything in it when done; those that a run killed while it meshed
    /// left behind are removed by the next job beside them (its owner file names the host and
    /// the process).
    ///
    /// A Gmsh script (.geo: abrade convert) is run where it is instead, its own relative
    /// paths (Merge, Save) meaning what its author meant.
    struct ChildDirectory
    {
      /// The length of the real path of the directory the child works in.
      static constexpr std::size_t path_length = 240;

      ChildDirectory(const MeshingJob &job, const std::string &mesher)
        : input("input" + std::filesystem::path(job.input).extension().string())
        , output("mesh" + std::filesystem::path(job.output).extension().string())
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        if (std::filesystem::path(job.input).extension() == ".geo")
          {
            input = job.input, output = job.output, executable = mesher;
            return;
          }
        const fs::path beside = fs::canonical(fs::absolute(job.output, ec).parent_path(), ec);
        if (ec)
          throw RunError("no directory for the mesher's output " + job.output + ": " + ec.message());
        remove_stale_directories(beside);
        std::string       pattern = (beside / "abrade-mesher-XXXXXX").string();
        std::vector<char> name(pattern.begin(), pattern.end());
        name.push_back('\0');
        if (!::mkdtemp(name.data()))
          throw RunError("cannot make a directory for the mesher beside " + job.output + ": " + std::strerror(errno));
        top = path = name.data();
        try
          {
            std::ofstream(top + "/owner") << this_host() << ' ' << ::getpid() << '\n';
            while (path.size() + 1 < path_length)
              path += "/" + std::string(std::min<std::size_t>(60, path_length - path.size() - 1), '_');
            fs::create_directories(path, ec);
            if (ec)
              throw RunError("cannot make a directory for the mesher beside " + job.output + ": " + ec.message());
            if (path.size() != path_length)
              notes.push_back("the mesher's directory beside " + job.output + " is " + std::to_string(path.size()) +
                              " characters long, not " + std::to_string(path_length) +
                              ": its meshes may differ from those of another output directory");
            place(job.input, input, "the part file", true);
            place(mesher, executable, "the mesher", false);
          }
        catch (...)
          {
            fs::remove_all(top, ec);
            throw;
          }
      }
      ~ChildDirectory()
      {
        std::error_code ec;
        if (!top.empty())
          std::filesystem::remove_all(top, ec);
      }
      ChildDirectory(const ChildDirectory &)            = delete;
      ChildDirectory &operator=(const ChildDirectory &) = delete;

      /// The job as the child is given it: the fixed names, relative to the directory.
      MeshingJob job_of(const MeshingJob &job) const
      {
        MeshingJob child = job;
        child.input      = input, child.output = output;
        return child;
      }
      /// Whether the child works where the job is (a Gmsh script): the files it leaves are
      /// beside the output, which no removal of its directory takes with it.
      bool in_place() const { return path.empty(); }
      /// A file the child writes by @p name (relative to where it works).
      std::string in(const std::string &name) const { return path.empty() ? name : path + "/" + name; }
      /// The child's name for @p file replaced by the user's at the start of @p text.
      std::string users_names(std::string text, const MeshingJob &job) const
      {
        for (const auto &[child, user] : {std::pair(input, job.input), std::pair(output, job.output)})
          if (!path.empty() && text.rfind(child, 0) == 0)
            return text.replace(0, child.size(), user);
        return text;
      }

      std::string              path, top, input, output;
      std::string              executable = "./abrade-mesher";
      std::vector<std::string> notes; ///< for the job's notes
      
    private:
      static std::string this_host()
      {
        char host[256] = {};
        ::gethostname(host, sizeof host - 1);
        return host;
      }

      /// The directories of mesher jobs beside @p beside whose process has ended without
      /// removing them (a run killed while it meshed): those this host's processes made (their
      /// owner file names the host and the process), whose process is gone. (Another host's,
      /// on a shared file system, are left alone: their process cannot be asked from here.)
      static void remove_stale_directories(const std::filesystem::path &beside)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        for (const auto &entry : fs::directory_iterator(beside, ec))
          {
            const std::string name = entry.path().filename().string();
            if (name.size() != 20 || name.rfind("abrade-mesher-", 0) != 0 || !entry.is_directory(ec))
              continue;
            std::ifstream owner(entry.path() / "owner");
            std::string   host;
            long          pid = 0;
            if (owner >> host >> pid && host == this_host() && pid > 0 && ::kill(pid_t(pid), 0) != 0 && errno == ESRCH)
              fs::remove_all(entry.path(), ec);
          }
      }

      /// @p file, its links resolved, into the directory as @p name: a hard link, else a copy.
      /// (Through a symbolic link the file's own path reached the child's memory, and another
      /// mesh came from an input in a directory of another length.)
      void place(const std::string &file, const std::string &name, const std::string &what, bool users)
      {
        namespace fs = std::filesystem;
        std::error_code ec;
        const fs::path  real = fs::canonical(file, ec);
        if (!ec)
          {
            fs::create_hard_link(real, fs::path(path) / fs::path(name).filename(), ec);
            if (ec)
              fs::copy_file(real, fs::path(path) / fs::path(name).filename(), ec);
          }
        if (ec && users)
          throw InputError(file, "cannot be read (" + ec.message() + ")");
        if (ec)
          throw RunError("cannot give " + what + " " + file + " to the mesher beside its output: " + ec.message());
      }
    };

    /// The files the child leaves: its notes, its error (an input error it found), both in its
    /// directory, and its log (what Gmsh said) beside the job's output.
    struct ChildFiles
    {
      ChildFiles(const MeshingJob &job, const ChildDirectory &dir)
        : output(dir.in(dir.output)), notes(dir.in(dir.output + ".notes")), error(dir.in(dir.output + ".error"))
        , log(job.output + ".log")
      {}
      std::string output, notes, error, log;
    };

    /// The mesher's command line for @p job: the program, its input and output, and the
    /// settings in the order abrade-mesher reads them.
    std::vector<std::string> mesher_arguments(const std::string &mesher, const MeshingJob &job)
    {
      const auto &s = job.settings;
      return {mesher,
              job.input,
              job.output,
              number(job.mesh_size),
              job.again ? "1" : "0",
              job.keep_triangles ? "1" : "0",
              number(s.scale),
              number(s.max_extent),
              number(s.min_extent),
              number(s.max_volume),
              number(s.max_cells),
              s.solid.empty() ? "-" : s.solid,
              job.kind,
              number(s.classify_angle)};
    }

    /// The same environment for every job (ChildDirectory): the C locale, temporary files in
    /// its directory, the library path (a deal.II or Gmsh of one's own; empty if none). The
    /// child is no MPI rank: without the launcher's variables an MPI library it loads does not
    /// try to join the parent's job.
    std::vector<std::string> mesher_environment()
    {
      const char *libraries = std::getenv("LD_LIBRARY_PATH"); // (set or not: as many variables)
      return {"LC_ALL=C", "TMPDIR=.", std::string("LD_LIBRARY_PATH=") + (libraries ? libraries : "")};
    }

    /// @p strings as execve takes them: pointers into them, ended by a null pointer.
    std::vector<char *> c_strings(std::vector<std::string> &strings)
    {
      std::vector<char *> pointers;
      for (auto &a : strings)
        pointers.push_back(a.data());
      pointers.push_back(nullptr);
      return pointers;
    }

    /// In the forked child, only async-signal-safe calls: it dies with the run, leads a process
    /// group of its own, writes to @p log, works in @p directory with nothing of the run's open,
    /// at fixed addresses where allowed, and becomes the mesher (@p installed where the copy
    /// beside the output cannot be started).
    [[noreturn]] void become_mesher(pid_t parent, int log, const std::string &directory, char *const argv[],
                                    char *const envp[], const std::string &installed)
    {
      ::prctl(PR_SET_PDEATHSIG, SIGKILL); // dies with the run, whatever ends it
      if (::getppid() != parent)
        ::_exit(127);
      ::setpgid(0, 0); // a group of its own, which a time-out ends whole
      for (const int signal : {SIGINT, SIGTERM, SIGHUP}) // not the run's handlers (summary.json)
        ::signal(signal, SIG_DFL);
      ::dup2(log, 1);
      ::dup2(log, 2);
      auto say = [](const char *text) { [[maybe_unused]] const auto written = ::write(2, text, std::strlen(text)); };
      if (!directory.empty() && ::chdir(directory.c_str()) != 0)
        {
          say("abrade-mesher: cannot enter its directory\n");
          ::_exit(127);
        }
      const int null = ::open("/dev/null", O_RDONLY);
      if (null >= 0)
        ::dup2(null, 0);
      for (int fd = 3; fd < 1024; ++fd) // nothing of the run's (its output pipes) stays open
        ::close(fd);
      // the same mesh from the same surface, run after run: Gmsh's HXT mesher orders by memory
      // addresses (one thread, one STL: another mesh in every run, the same one with the
      // addresses fixed), so the child's are not randomised. Where that is refused (a
      // container's seccomp profile: Docker's allows only a few personas) it meshes with
      // randomised addresses and says so in its log
      const int persona = ::personality(0xffffffff);
      if (persona == -1 || ::personality(static_cast<unsigned long>(persona) | ADDR_NO_RANDOMIZE) == -1)
        say("abrade-mesher: fixed addresses refused (personality): the mesh may differ from run to run\n");
      ::execve(argv[0], argv, envp);
      // (a directory that may not hold programs, mounted noexec: the mesher where it is
      // installed, whose path then reaches its memory)
      say("abrade-mesher: its copy beside the output cannot be started (a file system mounted noexec?): "
          "started where it is installed, and its meshes may differ from those of another output directory\n");
      ::execve(installed.c_str(), argv, envp);
      say("abrade-mesher: cannot be started\n");
      ::_exit(127);
    }

    /// @p mesher started on @p job (as the child sees it: ChildDirectory::job_of) in
    /// @p directory, in a process group of its own, its output into @p log_file (@p installed:
    /// the mesher where it is installed, started where @p mesher cannot be); its process id.
    pid_t start_mesher(const std::string &mesher, const MeshingJob &job, const std::string &directory,
                       const std::string &log_file, const std::string &installed)
    {
      // everything the child needs, made before fork (after it only async-signal-safe calls)
      std::vector<std::string> args = mesher_arguments(mesher, job), env = mesher_environment();
      const std::vector<char *> argv = c_strings(args), envp = c_strings(env);
      const int log = ::open(log_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
      if (log < 0)
        throw RunError("cannot write " + log_file);

      // while it waits, SIGTERM and Ctrl-C end the run (and with it the child) at once, also
      // where OpenCASCADE's checks of a CAD file, just before, set handlers of their own
      io::install_termination_handlers();
      const pid_t parent = ::getpid();
      const pid_t pid    = ::fork();
      if (pid < 0)
        {
          ::close(log);
          throw RunError(std::string("cannot start the mesher: ") + std::strerror(errno));
        }
      if (pid == 0)
        become_mesher(parent, log, directory, argv.data(), envp.data(), installed);
      ::close(log);
      ::setpgid(pid, pid); // (also here: no race with the child's own call)
      return pid;
    }

    /// The child's exit status, once it has ended; past @p time_limit seconds its group is
    /// killed and the job refused.
    int wait_for(pid_t pid, double time_limit, const MeshingJob &job)
    {
      int        status  = 0;
      const auto started = std::chrono::steady_clock::now();
      for (auto pause = std::chrono::milliseconds(1);; pause = std::min(2 * pause, std::chrono::milliseconds(50)))
        {
          const pid_t done = ::waitpid(pid, &status, WNOHANG);
          if (done == pid)
            return status;
          if (done < 0 && errno != EINTR)
            throw RunError(std::string("lost the mesher process: ") + std::strerror(errno));
          if (std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() > time_limit)
            {
              ::kill(-pid, SIGKILL);
              ::kill(pid, SIGKILL);
              while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
                ;
              std::filesystem::remove(job.output);
              throw InputError(job.input, "Gmsh did not finish meshing it within " + io::format_number(time_limit) +
                                            " s (stopped; ABRADE_MESHER_TIME_LIMIT sets the limit)");
            }
          std::this_thread::sleep_for(pause);
        }
    }

    /// What the child's exit @p status and files say: its notes (meshed), the input error it
    /// wrote, or how it crashed with the last lines of its log.
    std::vector<std::string> outcome(int status, const MeshingJob &job, const ChildDirectory &dir,
                                     const ChildFiles &files)
    {
      if (WIFEXITED(status) && WEXITSTATUS(status) == 0 && std::filesystem::exists(files.output))
        {
          std::error_code ec;
          if (files.output != job.output)
            std::filesystem::rename(files.output, job.output, ec);
          if (ec)
            throw RunError("cannot move the mesher's output to " + job.output + ": " + ec.message());
          auto notes = lines_of(read_text(files.notes));
          if (dir.in_place())
            std::filesystem::remove(files.notes);
          // (said in its log, which goes: a note instead)
          const std::string log = read_text(files.log);
          for (const std::string said : {"fixed addresses refused", "cannot be started"})
            if (log.find(said) != std::string::npos)
              notes.push_back(lines_of(log.substr(log.rfind('\n', log.find(said)) + 1)).front());
          std::filesystem::remove(files.log);
          notes.insert(notes.end(), dir.notes.begin(), dir.notes.end());
          return notes;
        }
      if (WIFEXITED(status) && WEXITSTATUS(status) == 2 && std::filesystem::exists(files.error))
        {
          // it names the file itself, by the name it was given: the user's
          const std::string what = dir.users_names(read_text(files.error), job);
          std::filesystem::remove(files.log);
          if (dir.in_place())
            std::filesystem::remove(files.error);
          throw InputError("", what);
        }
      if (WIFEXITED(status) && WEXITSTATUS(status) == 127)
        throw RunError("the mesher could not be started for " + job.input + ": " + log_tail(files.log));
      const std::string tail = log_tail(files.log);
      const std::string how  = WIFSIGNALED(status) ? "crashed (signal " + std::to_string(WTERMSIG(status)) + ")"
                                                   : "failed (exit " + std::to_string(WEXITSTATUS(status)) + ")";
      throw InputError(job.input, "Gmsh " + how + " meshing it" + (tail.empty() ? "" : ": " + tail));
    }
  } // namespace

  std::vector<std::string> run_meshing_job(const MeshingJob &job)
  {
    const std::string mesher = mesher_executable();
    if (mesher.empty())
      {
        auto notes = run_meshing_job_here(job);
        notes.push_back("meshed in this process (abrade-mesher not found: set ABRADE_MESHER)");
        return notes;
      }
    const double time_limit = time_limit_of(job);
    std::filesystem::remove(job.output);
    const ChildDirectory dir(job, mesher);
    const ChildFiles     files(job, dir);
    for (const auto &f : {files.notes, files.error})
      std::filesystem::remove(f);
    const pid_t pid = start_mesher(dir.executable, dir.job_of(job), dir.path, files.log,
                                   std::filesystem::absolute(mesher).string());
    return outcome(wait_for(pid, time_limit, job), job, dir, files);
  }

  int meshing_job_main(int argc, char **argv)
  {
    // stdout (the log) buffered in a buffer of one size and place, whatever file system holds
    // the log: glibc sizes its own by the file's block size (4 kB on ext4, 8 kB on NFS), and
    // Gmsh's meshes depend on where its data lie in memory
    static char buffer[8192];
    std::setvbuf(stdout, buffer, _IOFBF, sizeof buffer);
    if (argc < 12 || argc > 14)
      {
        std::fprintf(stderr, "abrade-mesher: abrade's Gmsh child process (started by abrade, not by hand)\n");
        return 1;
      }
    MeshingJob job;
    job.input                  = argv[1];
    job.output                 = argv[2];
    job.mesh_size              = std::atof(argv[3]);
    job.again                  = std::string(argv[4]) == "1";
    job.keep_triangles         = std::string(argv[5]) == "1";
    job.settings.scale         = std::atof(argv[6]);
    job.settings.max_extent    = std::atof(argv[7]);
    job.settings.min_extent    = std::atof(argv[8]);
    job.settings.max_volume    = std::atof(argv[9]);
    job.settings.max_cells     = std::atof(argv[10]);
    job.settings.solid         = std::string(argv[11]) == "-" ? "" : argv[11];
    job.kind                   = argc >= 13 ? argv[12] : "volume";
    if (argc == 14)
      job.settings.classify_angle = std::atof(argv[13]);
    try
      {
        const auto    notes = run_meshing_job_here(job);
        std::ofstream out(job.output + ".notes");
        for (const auto &n : notes)
          out << n << '\n';
        return out ? 0 : 1;
      }
    catch (const InputError &e)
      {
        std::filesystem::remove(job.output);
        std::ofstream(job.output + ".error") << e.what();
        return 2;
      }
    catch (const std::exception &e) // anything else is that mesh's failure too, said as such
      {
        std::filesystem::remove(job.output);
        std::ofstream(job.output + ".error") << job.input << ": Gmsh could not mesh it: " << e.what();
        return 2;
      }
  }
} // namespace abrade::fem
