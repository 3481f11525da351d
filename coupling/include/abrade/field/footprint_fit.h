#pragma once
// The wear footprint fitted with W (`abrade calibrate` with candidate runs at several
// Lifetime/Smoothing radius values; docs/field.md "W and the footprint together"). A depth
// scales with both W and the footprint length r (on the knife-bed, depth rate ~ r^-0.94 at a
// constant worn volume), so one depth cannot tell them apart; the width of a measured worn
// profile can. Each candidate run (the same case at footprint r_i) is fitted its W_i
// (calibration.h). The profile P(r) = min_W RSS(r, W), the residual sum of squares at the best
// W for footprint r, is known between the candidates too: a run at r is interpolated from them
// (run_between: each depth at the same W, smooth in ln r and exact at the candidates; a
// parabola through the candidates' RSS, the first design, put r^ 4 % off and made the interval
// 4x too wide). r^ minimises P between the best candidate's neighbours, and its 95 % interval
// is the profile likelihood's
//
//   {r : P(r) <= P(r^) (1 + D F(1, nu) / (n - 2))}
//
// (F(1, nu) = t(0.975, nu)^2, nu = the best run's spatial blocks - 2, n the measurements, D the
// design effect of the fit at r^: the cluster-robust variance of its W over the one n
// independent measurements would give, clamped to [1, n / nu], i.e. how many neighbouring scan
// points make one independent measurement; with D = n / nu the level is 1 + F / nu, as if the
// blocks were the measurements), its ends where P crosses the level, widened by half the
// distance between the minima with the candidates interpolated in ln r and in r (the
// interpolation's error) or by the candidates' own error, whichever is larger (with exact
// candidates both measure the interpolation): the largest shift of r^ without one candidate, in
// turn each that enters the interpolation from beyond the best and its neighbours (the best +-
// 2) and each replay among them, wherever it sits (a replay's geometry feedback left out; the
// ProfileWithout; W given r the same way). A replay among the best and its neighbours whose
// removal leaves no minimum is named (replays_not_assessed). Where P does not cross the level within the candidates on either side
// (a single depth, or no width information) the fit is refused as not identifiable, and so
// when fewer than three footprints are given, the measurements fall into too few blocks or the
// best is the smallest or largest: W is then given for the footprint assumed, the first run's.
// W^ and its relative standard error (the fit's and the beds') are the fit's at r^;
// d ln W / d ln r along the ridge W(r) from the profile at r^ e^(+-0.05), and the life's
// relative change along it from a parabola through the three candidates' ln (L_i / s_i) (a
// candidate's life at its fitted W: L_i over its scale, the life going as 1 / W). Coverage
// checked by simulation (test_footprint_coverage, docs/field.md): 95-99 % with independent
// noise (also with the outer candidates replays whose profile is 25 % too wide, or the best's
// neighbour one 5 % too wide; W's interval then 100 %), 82-89 % with noise correlated over a
// few points.
#include <abrade/field/calibration.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

namespace abrade::field
{
  inline constexpr double z95 = 1.959963985; ///< the normal's two-sided 95 % quantile

  /// One candidate run's fit.
  struct FootprintCandidate
  {
    double r    = 0;    ///< [m] its Smoothing radius
    double rss  = 0;    ///< residual sum of squares at its fitted W [m^2]
    double w    = 0;    ///< its fitted W (or scale, for analytic runs)
    double life = 0;    ///< its predicted life at its own W [t] (0: none)
    double scale = 1;   ///< its fitted W over its own
    long   blocks = 0;  ///< spatial blocks of its fit
    long   measurements = 0;   ///< n (0: unknown: the blocks are taken as the independent units)
    double design_effect = 1;  ///< of its W fit (CalibrationResult::design_effect)
    double relative_se = 0;    ///< its W's relative standard error, the fit's and the beds' (0: unknown)
    double w_dof = 0;          ///< that standard error's degrees of freedom (CalibrationResult::dof)
    bool   replay = false;     ///< a replay (its own error: the geometry feedback it leaves out)
  };

  /// The profile at footprint r: W fitted there and the residual sum of squares (rss, w), and
  /// with full all the rest of a candidate (design effect, W's relative standard error and its
  /// degrees of freedom, blocks, measurements); in_log_r: interpolated between the candidates
  /// in ln r, else in r (the two differ by the interpolation's error).
  using Profile = std::function<FootprintCandidate(double r, bool full, bool in_log_r)>;

  /// The profile between the candidates without the one at footprint r (the candidates' own
  /// error: how far r^ moves without each one in turn).
  using ProfileWithout = std::function<Profile(double r)>;

  struct FootprintFit
  {
    bool        identifiable = false;
    std::string reason;              ///< why not, in words
    double      r = 0, r_low = 0, r_high = 0; ///< [m] r^ and its 95 % interval (the best candidate's r when not identifiable)
    double      w = 0;               ///< W at r^ (or the best candidate's)
    double      sd_log_r = 0;        ///< the standard error of ln r^ (interval / 2 t)
    double      half_interpolation = 0; ///< the interval's widening on ln r for the interpolation between the candidates
    /// the candidates' own error on ln r: the largest shift of ln r^ without one candidate
    /// (among those whose removal leaves a minimum between the rest; 0: none)
    double      candidate_sensitivity = 0;
    int         candidates_left_out   = 0; ///< how many candidates were left out in turn
    /// replays among the best and its neighbours that could not be left out (the rest then
    /// hold no minimum): their own error is not in the interval (their footprints)
    std::vector<double> replays_not_assessed;
    /// the same for W given r: the largest shift of ln W at r^ without one of those candidates
    /// (added to W given r's half-width, t(w_dof) sd_log_w)
    double      w_candidate_sensitivity = 0;
    double      dlnw_dlnr = 0;       ///< along the ridge
    double      dlnlife_dlnr = 0;    ///< the life's relative change per relative change of r along the ridge (0: no lives)
    double      dof = 0;             ///< nu
    /// W's uncertainty: sd_log_w at r^ (the relative standard error of the fit there: W given
    /// r), and W's own 95 % interval w_low ... w_high with r's uncertainty in it (along the
    /// ridge ln W = ln W^ + dlnw_dlnr ln(r / r^) + e: the half-widths of r's interval times the
    /// slope and of W's given r, t(w_dof) sd_log_w, in quadrature)
    double      sd_log_w = 0, w_dof = 0, w_low = 0, w_high = 0;
    /// the joint 95 % region: (r, W) inside when joint_distance(r, W) <= joint_level
    /// (chi-square(0.95; 2) = 5.99), its W axis W given r's half-width over 1.96
    double      joint_level = 0, joint_sd_w = 0;
  };

  /// Fits r and W from @p candidates (any order) and their @p profile between them (@p without:
  /// the profile without one candidate, for the candidates' own error; none: not assessed).
  FootprintFit fit_footprint(std::vector<FootprintCandidate> candidates, const Profile &profile,
                             const ProfileWithout &without = {});

  /// The same from candidate runs and their calibrations (calibration.h; @p lives: each run's
  /// predicted life at its own W, 0 where none): the profile between the runs from runs
  /// interpolated between the three candidates nearest (run_between), calibrated on
  /// @p measurements.
  FootprintFit fit_footprint(const std::vector<RunSeries> &runs, const std::vector<CalibrationResult> &results,
                             const std::vector<double> &lives, const std::vector<Measurement> &measurements,
                             double block);

  /// The joint region of r and W (docs/field.md "W and the footprint together"): about the
  /// ridge in (ln r, ln W), Q = (a / s_a)^2 + ((b - slope a) / s_e)^2, a = ln(r / r^),
  /// b = ln(W / W^), s_a the half-width of r's interval on a's side and s_e that of W's given
  /// r, each over 1.96 (each axis at its own degrees of freedom: r's the blocks', W's the beds'
  /// too); (r, W) lies in the 95 % region when Q <= chi-square(0.95; 2) = 5.99. It reaches
  /// 1.25 times each interval along its axis (sqrt(5.99) / 1.96): a joint region is wider than
  /// each one's interval. ln r and ln W given r are taken as independent: exact for a linear
  /// model and independent noise; with correlated noise they were correlated by -0.56, and the region covered 79 % (test_footprint_coverage).
  double joint_distance(const FootprintFit &fit, double r, double w);

  /// @p points on the joint region's boundary, as (r, W) pairs (an identifiable fit only).
  std::vector<std::array<double, 2>> joint_region_outline(const FootprintFit &fit, int points = 72);
} // namespace abrade::field
