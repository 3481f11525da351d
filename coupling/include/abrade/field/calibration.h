#pragma once
// `abrade calibrate`: the Archard coefficient W, and the choice among candidate runs, from wear
// measured on knives in the field.
//
// Measurements are a table (CSV with a header): `tonnes` and `depth` (m; or `depth_mm`), and
// where: `x, y, z` in the knife's frame, or `location` naming a row of a locations table
// (`name, x, y, z`). `abrade compare --reference DESIGN --tonnes T` writes such a table from a
// scan (measured_depths.csv).
//
// A run (a lifetime output folder) predicts the depth D(T) at each measured point from its knife
// series (knife/knife.pvd: the surface's accumulated wear depth per update, followed at the
// material point that was there on the fresh knife). Wear is proportional to W and the geometry
// evolves with the accumulated wear only, so a run made with W0 predicts D(T; W) = D(T W / W0;
// W0): the fit is one scale factor s = W / W0 by least squares over the measurements, with a
// 95 % confidence interval from the residuals (Student t, linearised). The pattern agreement is
// the correlation of measured and predicted depths at the fitted scale, independent of the
// magnitude: the candidate runs (the knife SFC of a sweep, say) are ranked by it.
#include <array>
#include <string>
#include <vector>

namespace abrade::field
{
  struct Measurement
  {
    std::array<double, 3> point;
    double                tonnes = 0, depth = 0;
    std::string           where; ///< file:line, for messages
  };

  /// Reads a measurement table; InputError names the file, the line and the missing column.
  std::vector<Measurement> read_measurements(const std::string &path, const std::string &locations = "");

  /// A run's knife series: the tonnage of every output and the depth there at given points.
  struct RunSeries
  {
    std::string                      directory;
    double                           archard_coefficient = 0; ///< W0 from summary.json (0: unknown)
    std::vector<double>              tonnes;                   ///< per output
    std::vector<std::vector<double>> depth;                    ///< [output][point]
    /// Depth at point @p p after @p t tonnes, linear in t between outputs, extrapolated linearly
    /// from the last two beyond the last (@p extrapolated tells).
    double at(std::size_t p, double t, bool *extrapolated = nullptr) const;
  };

  RunSeries read_run(const std::string &directory, const std::vector<std::array<double, 3>> &points);

  struct CalibrationResult
  {
    std::string directory;
    double      scale = 1, scale_low = 1, scale_high = 1; ///< s = W / W0 and its 95 % interval
    double      archard_coefficient = 0, low = 0, high = 0; ///< W and its interval (0 when W0 unknown)
    double      rms_residual = 0;
    double      correlation  = 0; ///< measured vs predicted depth at the fitted scale
    bool        extrapolated = false;
  };

  CalibrationResult calibrate(const RunSeries &run, const std::vector<Measurement> &measurements);

  /// Two-sided 95 % Student t quantile for @p dof degrees of freedom.
  double student_t95(int dof);
} // namespace abrade::field
