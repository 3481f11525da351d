// How a run ends on SIGTERM, SIGINT and SIGHUP (termination.h).
#include <abrade/common/termination.h>

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

namespace abrade::io
{
  namespace
  {
    // set once while the run is set up, read only by the handler (never freed)
    const std::string *summary_path = nullptr, *summary_aside = nullptr, *summary_text = nullptr;

    constexpr int                 max_children = 256;
    std::atomic<int>              child_groups[max_children];
    std::atomic<int>              ending{0}; ///< the signal that ends this process, once caught

    /// Sends @p signal to every registered child group and waits for them (async-signal-safe:
    /// kill, waitpid, nanosleep), 10 s at most, then kills what is left.
    void end_children(int signal)
    {
      for (int tick = 0; tick < 1000; ++tick)
        {
          bool running = false;
          for (auto &g : child_groups)
            if (const int pgid = g.load(); pgid > 0)
              {
                ::kill(-pgid, signal); // every tick: a group started since is told too
                ::waitpid(pgid, nullptr, WNOHANG); // an ended leader reaped (a zombie still counts)
                if (::kill(-pgid, 0) != 0)
                  g.store(0); // nobody left in the group
                else
                  running = true;
              }
          if (!running)
            return;
          const timespec ten_ms{0, 10'000'000};
          ::nanosleep(&ten_ms, nullptr);
        }
      for (auto &g : child_groups)
        if (const int pgid = g.load(); pgid > 0)
          ::kill(-pgid, SIGKILL);
    }

    extern "C" void on_termination(int signal)
    {
      ending.store(signal); // no child run starts from now on (run_child_command)
      end_children(signal);
      static const char message[] = "\nabrade: interrupted; the last complete checkpoint is kept (a lifetime "
                                    "run continues with --resume)\n";
      [[maybe_unused]] auto written = ::write(2, message, sizeof message - 1);
      if (summary_text)
        {
          const int fd = ::open(summary_aside->c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
          if (fd >= 0)
            {
              written = ::write(fd, summary_text->data(), summary_text->size());
              ::close(fd);
              ::rename(summary_aside->c_str(), summary_path->c_str());
            }
        }
      ::_exit(128 + signal);
    }
  } // namespace

  void install_termination_handlers()
  {
    for (const int s : {SIGTERM, SIGINT, SIGHUP})
      std::signal(s, on_termination);
  }

  void register_child_group(int pgid)
  {
    for (auto &g : child_groups)
      {
        int empty = 0;
        if (g.compare_exchange_strong(empty, pgid))
          return;
      }
  }

  void unregister_child_group(int pgid)
  {
    for (auto &g : child_groups)
      {
        int was = pgid;
        g.compare_exchange_strong(was, 0);
      }
  }

  namespace
  {
    /// This process's environment without the MPI launcher's variables (Open MPI's and PMIx's,
    /// MPICH's Hydra and PMI; OPAL_PREFIX and the like, which say where Open MPI is, stay).
    std::vector<std::string> environment_outside_mpi()
    {
      std::vector<std::string> kept;
      for (char **e = environ; *e; ++e)
        {
          const std::string v = *e;
          bool              mpi = false;
          for (const char *prefix : {"OMPI_", "PMIX_", "PMI_", "HYDRA_", "MPI_LOCALRANKID", "MPI_LOCALNRANKS"})
            mpi = mpi || v.rfind(prefix, 0) == 0;
          if (!mpi)
            kept.push_back(v);
        }
      return kept;
    }
  } // namespace

  int run_child_command(const std::string &command)
  {
    // what the child needs, made before fork (after it only async-signal-safe calls); `exec`:
    // the shell becomes the command after its redirections, so the parent-death signal set
    // below is the command's own (a shell that forked it died alone, leaving it running)
    const std::string line   = "exec " + command;
    const char       *argv[] = {"sh", "-c", line.c_str(), nullptr};
    const std::vector<std::string> environment = environment_outside_mpi();
    std::vector<const char *>      envp;
    for (const auto &v : environment)
      envp.push_back(v.c_str());
    envp.push_back(nullptr);
    // the terminating signals held until the child is registered (and reset in the child): a
    // signal in between neither runs the parent's handler in the child nor misses the child
    sigset_t terminating, before;
    sigemptyset(&terminating);
    for (const int s : {SIGTERM, SIGINT, SIGHUP})
      sigaddset(&terminating, s);
    pthread_sigmask(SIG_BLOCK, &terminating, &before);
    if (ending.load() != 0) // the run is ending: no new child
      {
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        return -1;
      }
    const pid_t parent = ::getpid();
    const pid_t pid    = ::fork();
    if (pid < 0)
      {
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        return -1;
      }
    if (pid == 0)
      {
        ::setpgid(0, 0);
        ::prctl(PR_SET_PDEATHSIG, SIGTERM); // a parent killed by SIGKILL takes its children along
        if (::getppid() != parent)
          ::_exit(143);
        for (const int s : {SIGTERM, SIGINT, SIGHUP})
          std::signal(s, SIG_DFL);
        pthread_sigmask(SIG_SETMASK, &before, nullptr);
        ::execve("/bin/sh", const_cast<char *const *>(argv), const_cast<char *const *>(envp.data()));
        ::_exit(127);
      }
    ::setpgid(pid, pid); // (also here: the group exists before a signal can be forwarded to it)
    register_child_group(pid);
    pthread_sigmask(SIG_SETMASK, &before, nullptr);
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
      ;
    unregister_child_group(pid);
    return status;
  }

  void prepare_interrupted_summary(const std::string &path, const std::string &text)
  {
    // the new strings are complete before the handler can see them
    const std::string *aside = new std::string(path + ".tmp"), *p = new std::string(path), *t = new std::string(text);
    summary_path  = p;
    summary_aside = aside;
    summary_text  = t;
  }
} // namespace abrade::io
