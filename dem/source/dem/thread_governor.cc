// How many threads work on a simulation's steps, measured as it runs (thread_governor.h).
#include <abrade/dem/thread_governor.h>

#include <algorithm>

namespace abrade::dem
{
  ThreadGovernor::ThreadGovernor(int threads, bool adaptive_)
    : max_team(std::max(1, threads)), adaptive(adaptive_ && threads > 1), current_team(max_team),
      kept_team(max_team)
  {}

  void ThreadGovernor::pin(int team)
  {
    adaptive     = false;
    in_trial     = false;
    current_team = kept_team = std::clamp(team, 1, max_team);
  }

  void ThreadGovernor::carry_on()
  {
    if (in_trial)
      current_team = kept_team, in_trial = false;
    steps = 0, seconds = 0;
    until_trial = std::max(until_trial, 1);
  }

  bool ThreadGovernor::record_step(double step_seconds)
  {
    if (!adaptive)
      return false;
    ++steps, seconds += step_seconds;
    if (seconds < window_seconds || steps < window_min_steps)
      return false;
    const double per_step = seconds / double(steps);
    steps = 0, seconds = 0;

    if (!in_trial) // a window of the kept team: the reference for the next trial
      {
        reference = per_step;
        if (--until_trial > 0)
          return false;
        if (kept_team + direction < 1 || kept_team + direction > max_team)
          direction = -direction;
        current_team = kept_team + direction;
        in_trial     = true;
        return true;
      }

    // the end of a trial: keep its team if it was faster by the margin, else go back
    in_trial = false;
    const bool won = per_step < (1 - margin) * reference;
    if (won)
      {
        kept_team = current_team;
        ++kept_changes;
        wait = 1; // the next trial soon, in the same direction
      }
    else
      {
        current_team = kept_team;
        direction    = -direction;
        wait         = std::min(2 * wait, longest_wait);
      }
    until_trial = wait;
    return !won;
  }
} // namespace abrade::dem
