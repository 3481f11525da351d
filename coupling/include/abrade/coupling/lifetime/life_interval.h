#pragma once
// The predicted life and its interval, from the whole trajectory of the quantity that ends life
// (docs/lifetime.md, "The life and its interval").
//
// Every update draws its wear from fresh beds (Lifetime/Seeds, each seed's bed settled anew for
// every update from a seed derived from it and the update number), so the updates' bed means
// are independent samples. In update u the quantity that ends life grows by dQ_u (the depth at
// the deepest point, the recession of the followed point, the worn mass); its beds' rates at
// the place that ends life (chosen on the beds' mean field) scatter with a relative variance
// v_u over n_u beds (relative_variance()). The beds' relative variance is
// taken to be the same in every update (the cycle is the same, the geometry changes slowly) and
// pooled:
//
//   c^2  = sum_u (n_u - 1) v_u / sum_u (n_u - 1)        dof = sum_u (n_u - 1)
//   Var(dQ_u) = c^2 dQ_u^2 / n_u                         (independent between updates)
//
// The life is one estimator L(dQ_1 .. dQ_U) of the whole trajectory (life_from_trajectory):
// the crossing of the accumulated quantity Q with the limit, linear within the update that
// crosses it; past the last update, a power law Q = Q_U (T / T_U)^b through the last point,
// its exponent the least-squares slope of ln Q over ln T on the recent half of the run (T >=
// T_U / 2; b = 1 with one update), which follows wear that slows as an edge rounds. Its
// variance is carried by the gradient (first order):
//
//   Var(L) = sum_u (dL/d dQ_u)^2 c^2 dQ_u^2 / n_u
//
// split into the beds' part with the exponent held and the extrapolation's (below); the beds'
// part is scaled by phi^2 <= 1: the place that ends life is the worst of many, whose level
// scatters less than the leading place's (place_scatter.h gives it from the run's beds at
// every place; 1 for one place). The extrapolation's part is not scaled.
// (The beds' part is what the quantity at the last point carries; the extrapolation's what the
// exponent's own scatter adds past the last point.)
// The interval is formed on ln L, so that it is never unbounded and never negative:
//
//   [L exp(-t s), L exp(t s)],  s = sqrt(Var(L)) / L,  t = t_{1-a/2, dof}
//
// tests/unit/test_life_interval.cc checks its coverage over 4,000 trajectories drawn through the
// loop's own update-size rule with a known scatter, reached and extrapolated lives alike.
// Assumed and not covered by it: a power law past the last update (a course that slows faster
// is extrapolated short, and its interval does not hold that model error); a scatter with a
// skewed scatter is under-covered a little (its low bed means come with low sample variances:
// 93.1 % at 30 % lognormal scatter), a heavier tail (a few beds of many times the mean) more,
// with three beds an update; and the deepest of many near-equal places is biased deep (the maximum
// of noisy values: a short life, the safe side) and, with phi, still stated 10-30 % wider than
// it scatters (tests/unit/test_life_interval.cc).
#include <cstddef>
#include <utility>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// One update of the quantity that ends life.
  struct UpdateRecord
  {
    double      tonnes = 0; ///< handled after the update [t]
    double      value  = 0; ///< the quantity after the update (the trajectory's value)
    std::size_t beds   = 1; ///< beds whose mean moved the part in this update
    /// the beds' sample variance of their rate at the place that ends life, relative to the
    /// square of their mean (n - 1 in the denominator; 0 for one bed; -1: the place did not
    /// wear, left out of the pool)
    double relative_variance = 0;
    /// each bed's seed (bed_seed()) and its rate at the place that ends life, in the same order:
    /// what pairs two runs on common beds (paired_life.h)
    std::vector<int>    bed_seeds = {};
    std::vector<double> bed_rates = {};
  };

  /// How a life was found on a trajectory.
  struct LifeOnTrajectory
  {
    double tonnes   = 0;     ///< 0: the quantity does not grow
    bool   reached  = false; ///< crossed within the run (interpolated linearly in the update)
    long   update   = 0;     ///< reached: the update (1-based) that crossed it
    double exponent = 1;     ///< extrapolated: the power law's exponent b
  };

  /// The life where the trajectory (@p tonnes, @p values, after each update; the fresh part,
  /// 0 t and 0, is implied) reaches @p limit. With @p exponent > 0 the extrapolation's exponent
  /// is held at that value instead of fitted.
  LifeOnTrajectory life_from_trajectory(const std::vector<double> &tonnes, const std::vector<double> &values,
                                        double limit, double exponent = 0);

  struct LifeInterval
  {
    LifeOnTrajectory life;
    double           confidence    = 0.95;
    double           dof           = 0; ///< sum of (beds - 1) over the updates; 0: no interval
    double           bed_relative_sd = 0; ///< c: one bed's rate at the place, relative
    /// phi^2: the beds' variance at the leading place scaled for the worst of many places
    /// (place_scatter.h); 1: one place, or not known
    double           place_factor  = 1;
    double           relative_sd   = 0; ///< s: of the life, all components
    double           relative_sd_beds = 0, relative_sd_extrapolation = 0; ///< the components
    double           relative_sd_calibration = 0; ///< W from abrade calibrate (add_calibration())
    double           low = 0, high = 0; ///< the interval [t]; 0: none (dof 0)
    double           relative_half_width = 0; ///< (high - low) / (2 life)
    /// per update u, the life's relative change per relative change of the update's increment
    /// dQ_u (dL/d dQ_u dQ_u / L; 0 where the update did not move the quantity), with the
    /// exponent held (the beds' part) and fitted (free); the variance above is
    /// phi^2 sum_u held_u^2 c^2 / n_u + max(0, sum_u (free_u^2 - held_u^2) c^2 / n_u). What pairs
    /// two runs' bed deviations (paired_life.h).
    std::vector<double> elasticity_held, elasticity_free;
  };

  /// The two-sided Student t quantile t_{p, dof} (Boost.Math; dof may be fractional).
  double student_t_quantile(double p, double dof);

  /// The life at @p limit of the trajectory @p updates and its interval. @p place_factor (phi^2,
  /// place_scatter.h) scales the beds' part of the variance (the exponent held) where the place
  /// that ends life is the worst of many.
  LifeInterval life_interval(double limit, const std::vector<UpdateRecord> &updates, double confidence = 0.95,
                             double place_factor = 1);

  /// @p interval with a calibrated wear coefficient's relative standard error @p relative_sd
  /// (over @p dof degrees of freedom) added as the component `calibration` (the life goes as 1/W
  /// to first order): s^2 = s_beds^2 + s_extrapolation^2 + s_calibration^2, its degrees of freedom
  /// by Welch-Satterthwaite, s^4 / ((s_beds^2 + s_extrapolation^2)^2 / dof + s_calibration^4 /
  /// dof_calibration), and the interval formed again. Without the beds' interval (one bed an
  /// update) there is none with the calibration either (the component is recorded). Assumed:
  /// the two estimates independent (a calibration fitted on the same beds as the run shares
  /// their first update's error with it; the interval is then wider than it scatters).
  LifeInterval add_calibration(LifeInterval interval, double relative_sd, double dof);

  /// The pooled relative variance c^2 of @p updates and its degrees of freedom.
  std::pair<double, double> pooled_relative_variance(const std::vector<UpdateRecord> &updates);

  /// The relative variance of @p rates: their sample variance over their mean squared (not from
  /// their logarithms, which covers a lognormal scatter better, 93.8 % against 93.1 % at 30 %,
  /// but one bed that barely wore at the place made the small case's interval +-544 %); 0 for
  /// fewer than two; -1 where their mean is not positive (no wear there, left out).
  double relative_variance(const std::vector<double> &rates);
} // namespace abrade::coupling::lifetime
