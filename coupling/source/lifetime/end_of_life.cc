// The end of life from the wear trajectory: each criterion's crossing, reached or extrapolated
// (end_of_life.h).
#include <abrade/coupling/lifetime/end_of_life.h>
#include <abrade/coupling/lifetime/life_interval.h>

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
    if (trajectory.size() < 2)
      return e;
    // each criterion's life on the whole trajectory (life_interval.h): reached ones first, then
    // the earliest
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        if (criteria[c].limit <= 0)
          continue;
        std::vector<double> tonnes, values;
        for (std::size_t u = 1; u < trajectory.size(); ++u)
          tonnes.push_back(trajectory[u].tonnes), values.push_back(trajectory[u].values[c]);
        const LifeOnTrajectory l = life_from_trajectory(tonnes, values, criteria[c].limit);
        if (!(l.tonnes > 0) && !l.reached)
          continue;
        const bool better = e.criterion == EndOfLife::none || (l.reached && !e.reached) ||
                            (l.reached == e.reached && l.tonnes < e.tonnes);
        if (better)
          {
            e.tonnes = l.tonnes, e.criterion = c, e.reached = l.reached, e.extrapolated = !l.reached;
            e.update = l.update, e.exponent = l.exponent;
          }
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
      s << "extrapolated past the last update by its recent course (power law, exponent " << e.exponent << ")";
    return s.str();
  }
} // namespace abrade::coupling::lifetime
