// The one-line progress indicator of long loops (progress.h).
#include <abrade/common/progress.h>

#include <cstdio>
#include <unistd.h>

namespace abrade::io
{
  namespace
  {
    bool quiet_flag = false;
  }

  void ProgressLine::set_quiet(bool quiet) { quiet_flag = quiet; }
  bool ProgressLine::quiet() { return quiet_flag; }

  bool ProgressLine::enabled() { return !quiet_flag && isatty(fileno(stderr)); }

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
    if (!enabled() || finished)
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
    if (drawn && !finished)
      std::fprintf(stderr, "\r\033[K");
    finished = true;
  }
} // namespace abrade::io
