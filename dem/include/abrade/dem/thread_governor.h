#pragma once
// How many of a simulation's threads work on its steps: the governor picks the team size from
// what the machine gives, measured as it runs.
//
// A step's work is cut into a fixed number of shares (Settings::threads, "the threads"); the
// shares and the order in which their results are summed fix the arithmetic, so a run gives
// the same bits whatever number of threads works on them (the team). On a quiet machine every
// share gets its own thread. On a busy one, where another process holds a core, the thread that
// shares that core is descheduled for milliseconds at a time and the others wait for it at each
// of the step's synchronisation points: on two cores with one busy, two threads ran the
// knife-bed at 0.4x the speed of one (docs/benchmarks.md, "A busy machine").
//
// The governor measures the wall time per step over windows of about 50 ms. Every so often it
// runs one window with one thread fewer (or more) and keeps that team when its steps were more
// than 5 % faster than those of the window just before. The first trial comes after 8 windows;
// a trial that loses doubles the wait until the next one (up to 64 windows, about 3 s, so
// trials cost a few per cent at most); a trial that wins is followed soon by another in the
// same direction.
//
// A team smaller than the shares works share s on thread s % team, so a team of T takes
// ceil(S / T) shares' time per step: with 16 shares and one busy core the governor keeps 15
// threads, which work at the speed of 8 (one share each would need more shares than threads, a
// force buffer each; not done). A lifetime run's cycles are many short simulations, each
// shorter than the first wait on a busy machine: one governor goes from each to the next
// (carry_on()). It has no clock of its
// own: the caller gives it each step's wall time, so it is tested with made-up timings.
namespace abrade::dem
{
  class ThreadGovernor
  {
  public:
    /// A team of up to @p threads threads (>= 1); @p adaptive false keeps all of them working.
    explicit ThreadGovernor(int threads = 1, bool adaptive = true);

    /// The number of threads to work on the next step (1 .. threads()).
    int team() const { return current_team; }
    int threads() const { return max_team; }
    /// Records a step of @p seconds (wall time) worked by team() threads. Returns true when
    /// team() changed (a trial begins or ends with another team).
    bool record_step(double seconds);
    /// Stops adapting and works with @p team threads from now on (tests, benchmarks).
    void pin(int team);
    /// Goes on in a new simulation (Settings::governor): a trial under way is dropped (its
    /// window mixed two simulations' steps), the kept team works on, and the next window
    /// measures the new simulation's steps before any trial. What was learnt stays: the kept
    /// team and the wait between trials.
    void carry_on();
    /// The number of times the team kept after a trial differed from the one before it.
    long changes() const { return kept_changes; }

    /// Tuning (public for the tests): the window length [s], the fewest steps in a window, the
    /// margin a trial must win by, and the longest wait between trials [windows].
    static constexpr double window_seconds   = 0.05;
    static constexpr long   window_min_steps = 4;
    static constexpr double margin           = 0.05;
    static constexpr int    longest_wait     = 64;
    /// Windows before the first trial (0.4 s): a short run (a lifetime cycle's phase) pays for
    /// no trials; a busy machine is found 0.4 s into a run.
    static constexpr int    first_wait       = 8;

  private:
    int    max_team;
    bool   adaptive;
    int    current_team;   ///< the team working now (the kept one, or a trial's)
    int    kept_team;      ///< the team the trials are measured against
    bool   in_trial   = false;
    int    direction  = -1; ///< the next trial: one thread fewer (-1) or more (+1)
    int    wait       = first_wait; ///< windows between trials
    int    until_trial = first_wait;
    double reference  = 0;  ///< seconds per step of the kept team's last window
    long   steps      = 0;  ///< in the current window
    double seconds    = 0;
    long   kept_changes = 0;
  };
} // namespace abrade::dem
