#pragma once
// End of life from the wear trajectory. Each criterion is a quantity that grows with the handled
// tonnes (the largest wear depth, the recession of a followed point, the worn mass) and a limit.
// The tonnes to end of life are where the first criterion reaches its limit:
//
//  - within the run: interpolated linearly inside the update that crossed it. The loop applies a
//    constant wear rate per cycle within one update, so every point's depth grows linearly in
//    tonnes there; the interpolation is the model's own answer, not an approximation of it.
//  - past the last update: extrapolated by the trajectory's recent course, a power law through
//    the last point (life_interval.h: wear that slows as an edge rounds, or speeds up, shows in
//    its exponent; with one update it is the update's rate).
//
// Pure arithmetic on the trajectory (no mesh, no DEM): tests/unit/test_lifetime_steps.cc checks it
// against exact crossings of linear and accelerating wear.
#include <limits>
#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  struct Criterion
  {
    std::string name;  ///< "maximum depth", ...
    double      limit; ///< the quantity's end-of-life value; <= 0: not a criterion
  };

  /// The trajectory after one update (or the fresh part: tonnes 0, values 0).
  struct TrajectoryPoint
  {
    double              tonnes;
    std::vector<double> values; ///< one per criterion
  };

  struct EndOfLife
  {
    static constexpr std::size_t none = std::numeric_limits<std::size_t>::max();
    double      tonnes       = 0;     ///< predicted tonnes to end of life; 0: no wear, no prediction
    std::size_t criterion    = none;  ///< the criterion that ends life first
    bool        reached      = false; ///< crossed within the run (interpolated)
    bool        extrapolated = false; ///< past the last update, by the recent course's power law
    double      exponent     = 1;     ///< extrapolated: the power law's exponent
    long        update       = 0;     ///< reached: the update (1-based) within which it was crossed
  };

  /// The tonnes where the segment (t0, v0) - (t1, v1) reaches @p limit (v0 < limit <= v1).
  double crossing(double t0, double v0, double t1, double v1, double limit);

  /// The end of life of @p trajectory (its first point is the fresh part) under @p criteria.
  EndOfLife end_of_life(const std::vector<Criterion> &criteria, const std::vector<TrajectoryPoint> &trajectory);

  /// What end_of_life() found, in words for the log and summary.json ("maximum depth reached
  /// within update 4 (interpolated)", "extrapolated from the last update's rate", ...).
  std::string describe(const EndOfLife &e, const std::vector<Criterion> &criteria);
} // namespace abrade::coupling::lifetime
