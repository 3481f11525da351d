#include <abrade/coupling/lifetime/end_of_life.h>

#include <sstream>

namespace abrade::coupling::lifetime
{
  double crossing(double t0, double v0, double t1, double v1, double limit)
  {
    if (!(v1 > v0))
      return t1;
    return t0 + (t1 - t0) * (limit - v0) / (v1 - v0);
  }

  EndOfLife end_of_life(const std::vector<Criterion> &criteria, const std::vector<TrajectoryPoint> &trajectory)
  {
    EndOfLife e;
    // within the run: the first update in which any criterion reaches its limit; within it, the
    // criterion that reaches it at the fewest tonnes
    for (std::size_t u = 1; u < trajectory.size() && !e.reached; ++u)
      for (std::size_t c = 0; c < criteria.size(); ++c)
        {
          const double limit = criteria[c].limit;
          const auto  &a = trajectory[u - 1], &b = trajectory[u];
          if (limit <= 0 || !(b.values[c] >= limit))
            continue;
          const double t = a.values[c] >= limit ? a.tonnes : crossing(a.tonnes, a.values[c], b.tonnes, b.values[c], limit);
          if (!e.reached || t < e.tonnes)
            e.tonnes = t, e.criterion = c, e.reached = true, e.update = long(u);
        }
    if (e.reached || trajectory.size() < 2)
      return e;
    // past the run: each criterion at the rate of the last update; the first to reach its limit
    const auto &a = trajectory[trajectory.size() - 2], &b = trajectory.back();
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        const double rate = (b.values[c] - a.values[c]) / (b.tonnes - a.tonnes);
        if (criteria[c].limit <= 0 || !(rate > 0) || !(b.tonnes > a.tonnes))
          continue;
        const double t = b.tonnes + (criteria[c].limit - b.values[c]) / rate;
        if (!e.extrapolated || t < e.tonnes)
          e.tonnes = t, e.criterion = c, e.extrapolated = true;
      }
    return e;
  }

  std::string describe(const EndOfLife &e, const std::vector<Criterion> &criteria)
  {
    std::ostringstream s;
    if (e.criterion == EndOfLife::none)
      return "no criterion grows: no prediction";
    s << criteria[e.criterion].name << " (" << criteria[e.criterion].limit << ") ";
    if (e.reached)
      s << "reached within update " << e.update << " (interpolated linearly within it)";
    else
      s << "extrapolated from the last update's rate";
    return s.str();
  }
} // namespace abrade::coupling::lifetime
