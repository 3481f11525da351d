#pragma once
// A one-line progress indicator for long loops: "label  42.0 %  ETA 1m12s  <extra>".
// It redraws itself with '\r' on a terminal, at most a few times per second, and prints
// nothing when stderr is not a terminal or when quiet is set (abrade --quiet). Under mpirun
// the line is rank 0's, drawn when mpirun's own stderr is a terminal. Threads may
// update one line together (a study's pool of child runs): the line is drawn by one at a time.
#include <chrono>
#include <mutex>
#include <string>

namespace abrade::io
{
  class ProgressLine
  {
  public:
    ProgressLine(std::string label, double total);
    ~ProgressLine();

    /// Process-wide switch, set by `--quiet`.
    static void set_quiet(bool quiet);
    static bool quiet();
    static bool enabled();

    /// Reports progress @p done out of total, with an optional extra text (from any thread).
    void update(double done, const std::string &extra = "");
    /// Ends the line (called by the destructor too).
    void finish();

    /// "1h02m", "3m05s", "12s"
    static std::string format_duration(double seconds);

  private:
    std::string                           label;
    double                                total;
    std::chrono::steady_clock::time_point start, last_draw;
    bool                                  drawn    = false;
    bool                                  finished = false;
    std::mutex                            drawing; ///< (the state above, and stderr's line)
  };
} // namespace abrade::io
