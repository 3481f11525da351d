#pragma once
// `abrade calibrate`: the wear coefficient W (of the run's law of Output/Wear field, Archard's
// by default), and the choice among candidate runs, from wear
// measured on knives in the field.
//
// Measurements are a table (CSV with a header): `tonnes` and `depth` (m; or `depth_mm`), and
// where: `x, y, z` in the part's frame, or `location` naming a row of a locations table
// (`name, x, y, z`). `abrade compare --reference DESIGN --tonnes T` writes such a table from a
// scan (measured_depths.csv).
//
// A run (a lifetime output folder) predicts the depth D(T) at each measured point from its knife
// series (part/part.pvd: the surface's accumulated wear depth per update, followed at the
// material point that was there on the fresh knife). Wear is proportional to W and the geometry
// evolves with the accumulated wear only, so a run made with W0 predicts D(T; W) = D(T W / W0;
// W0): the fit is one scale factor s = W / W0 by least squares over the measurements.
//
// Its 95 % interval has two parts, both reported:
//  - the fit: neighbouring measurements (the points of a scan, one gauge over several tonnages)
//    are not independent; their residuals are correlated over lengths of the particle scale. The
//    measurements are grouped in spatial blocks (cubes of Block size, default 50 mm) and the
//    variance of s is the cluster-robust one in its jackknife form (CR3), var = (G-1)/G sum_g
//    (S_g / (sum_i J_i^2 - Q_g))^2, S_g = sum_{i in g} J_i e_i, Q_g = sum_{i in g} J_i^2, with
//    J_i = d depth_i / d s, over the G blocks that carry information (J != 0), on G_eff
//    degrees of freedom, G_eff = (sum_g Q_g)^2 / sum_g Q_g^2 the blocks the information is spread
//    over (treating thousands of scan points as independent made the interval far too narrow);
//  - the DEM's replicate spread: the run's wear rate is the mean over its beds (Lifetime/Seeds),
//    whose relative standard error s_v / sqrt(n) (s_v: the beds' relative spread of the worn
//    volume, from the run's summary.json) carries to s in proportion; n - 1 degrees of freedom.
// They add in quadrature, the degrees of freedom by Welch-Satterthwaite. A run of one bed has no
// replicate part: a warning says so. The pattern agreement is
// the correlation of measured and predicted depths at the fitted scale, independent of the
// magnitude: the candidate runs (the knife SFC of a sweep, say) are ranked by it.
#include <array>
#include <string>
#include <utility>
#include <vector>

namespace abrade::field
{
  struct Measurement
  {
    std::array<double, 3> point; ///< the design point the measurement lies below
    /// Where the worn surface was measured (a scan point: columns worn_x, worn_y, worn_z, which
    /// compare writes), if known: the prediction is then looked up at the predicted surface's
    /// closest point to it. Several points of a worn surface can lie below one design point
    /// (a flat-cut tip: a line of the cut face below one point of the face), which their design
    /// point alone cannot tell apart.
    bool                  has_worn_point = false;
    std::array<double, 3> worn_point{};
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
    long                             seeds = 1;                ///< the run's beds per update
    double                           replicate_relative_sd = 0; ///< the beds' relative spread of the worn volume
    double                           smoothing_radius = 0;      ///< [m] the run's wear footprint (0: unknown)
    double                           particle_radius = 0;       ///< [m] its largest particle (0: unknown)
    double                           coarse_graining_factor = 0; ///< of its particles at the part (summary.json: a multi-level bed's finest; 0: unknown)
    std::string                      wear_field;                ///< the run's Output/Wear field (empty: unknown)
    bool                             replay = false; ///< a replay of another run's stored wear (Lifetime/Wear source = replay)
    std::vector<double>              tonnes;                   ///< per output
    std::vector<std::vector<double>> depth;                    ///< [output][point]
    /// Depth at point @p p after @p t tonnes, linear in t between outputs, extrapolated linearly
    /// from the last two beyond the last (@p extrapolated tells).
    double at(std::size_t p, double t, bool *extrapolated = nullptr) const;
  };

  RunSeries read_run(const std::string &directory, const std::vector<Measurement> &measurements);

  /// A run at footprint @p r between candidate runs at other footprints (their Smoothing radius;
  /// runs without one are left out): each output's depth interpolated in ln r (with @p in_log_r
  /// false: in r) from theirs at the same W (a run made with W0 at T tonnes is one made with
  /// W0' at T W0 / W0'), on the union of their outputs. Within [r_j, r_j+1] the blend, linear
  /// from one end to the other, of the parabolas through (j-1, j, j+1) and (j, j+1, j+2):
  /// exact at the candidates and smooth between (a parabola through the three nearest alone
  /// jumps where they change, and the fit's interval ended at the jump);
  /// one parabola in the end intervals, a line between two runs. Its W0, beds and spread are
  /// the nearest run's.
  RunSeries run_between(const std::vector<const RunSeries *> &runs, double r, bool in_log_r = true);

  struct CalibrationResult
  {
    std::string directory;
    double      scale = 1, scale_low = 1, scale_high = 1; ///< s = W / W0 and its 95 % interval
    double      se_fit = 0, se_replicates = 0;            ///< the standard error's two parts (of s)
    long        blocks = 0;                               ///< spatial blocks of the measurements
    /// the blocks the fit's information is spread over, (sum_g Q_g)^2 / sum_g Q_g^2 (Q_g: the
    /// block's sum of J^2; at most blocks): its degrees of freedom
    double      effective_blocks = 0;
    /// the fit's variance over what independent measurements would give it (the cluster-robust
    /// variance of s over RSS / (n - 1) / sum J^2): how many measurements make one independent
    /// one, as the residuals' correlation says (1: independent; a block's size: all alike)
    double      design_effect = 1;
    double      dof = 0;                                  ///< of the interval (Welch-Satterthwaite)
    double      archard_coefficient = 0, low = 0, high = 0; ///< W and its interval (0 when W0 unknown)
    double      rms_residual = 0;
    double      correlation  = 0; ///< measured vs predicted depth at the fitted scale
    bool        extrapolated = false;
    double      smoothing_radius = 0; ///< [m] the run's footprint: W holds for it (0: unknown)
    double      particle_radius = 0, coarse_graining_factor = 0; ///< the particle size it holds for (0: unknown)
    std::string wear_field;           ///< the wear field W belongs to (its law's coefficient)
  };

  /// The least-squares scale s of @p run's wear on @p measurements within [@p low, @p high]
  /// (golden sections on ln s) and the residual sum of squares there [m^2].
  std::pair<double, double> least_squares_scale(const RunSeries &run, const std::vector<Measurement> &measurements,
                                                double low, double high);

  /// Fits s for @p run; measurements are grouped in cubes of @p block [m] for the interval.
  CalibrationResult calibrate(const RunSeries &run, const std::vector<Measurement> &measurements, double block = 0.05);

  /// Two-sided 95 % Student t quantile for @p dof degrees of freedom.
  double student_t95(int dof);
} // namespace abrade::field
