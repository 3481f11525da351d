// The one-line progress indicator of long loops (progress.h).
#include <abrade/common/progress.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <unistd.h>

namespace abrade::io
{
  namespace
  {
    bool quiet_flag = false;

    /// Whether what this process writes to stderr reaches a terminal: its own stderr is one, or
    /// it is rank 0 of mpirun (Open MPI says so in OMPI_COMM_WORLD_RANK) and mpirun's is one:
    /// mpirun copies a rank's stderr to its own as it comes, '\r' included, and on rank 0's node
    /// it is the rank's parent. The other ranks draw nothing (their lines would interleave).
    bool stderr_reaches_a_terminal()
    {
      if (isatty(fileno(stderr)))
        return true;
      const char *rank = std::getenv("OMPI_COMM_WORLD_RANK");
      if (!rank || std::string(rank) != "0")
        return false;
      std::error_code ec;
      const std::string launchers =
        std::filesystem::read_symlink("/proc/" + std::to_string(getppid()) + "/fd/2", ec).string();
      return !ec && (launchers.rfind("/dev/pts/", 0) == 0 || launchers.rfind("/dev/tty", 0) == 0);
    }
  } // namespace

  void ProgressLine::set_quiet(bool quiet) { quiet_flag = quiet; }
  bool ProgressLine::quiet() { return quiet_flag; }

  bool ProgressLine::enabled()
  {
    static const bool terminal = stderr_reaches_a_terminal(); // (once: it does not change)
    return !quiet_flag && terminal;
  }

  ProgressLine::ProgressLine(std::string l, double t)
    : label(std::move(l)), total(t), start(std::chrono::steady_clock::now()), last_draw(start)
  {}

  ProgressLine::~ProgressLine() { finish(); }

  std::string ProgressLine::format_duration(double s)
  {
    char      buf[32];
    const long t = static_cast<long>(s + 0.5);
    if (t >= 3600)
      std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
    else if (t >= 60)
      std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
    else
      std::snprintf(buf, sizeof buf, "%lds", t);
    return buf;
  }

  void ProgressLine::update(double done, const std::string &extra)
  {
    if (!enabled())
      return;
    const std::lock_guard<std::mutex> one_at_a_time(drawing);
    if (finished)
      return;
    const auto now = std::chrono::steady_clock::now();
    if (drawn && now - last_draw < std::chrono::milliseconds(250))
      return;
    last_draw        = now;
    drawn            = true;
    const double f   = total > 0 ? std::min(1.0, done / total) : 0.0;
    const double el  = std::chrono::duration<double>(now - start).count();
    std::string  eta = f > 1e-6 ? format_duration(el * (1 - f) / f) : "?";
    std::fprintf(stderr, "\r%s %5.1f %%  ETA %s  %s\033[K", label.c_str(), 100 * f, eta.c_str(),
                 extra.c_str());
    std::fflush(stderr);
  }

  void ProgressLine::finish()
  {
    const std::lock_guard<std::mutex> one_at_a_time(drawing);
    if (drawn && !finished)
      std::fprintf(stderr, "\r\033[K");
    finished = true;
  }
} // namespace abrade::io
