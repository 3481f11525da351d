#pragma once
// The wear footprint fitted with W (`abrade calibrate` with candidate runs at several
// Lifetime/Smoothing radius values; docs/field.md "W and the footprint together"). A depth
// scales with both W and the footprint length r (on the knife-bed, depth rate ~ r^-0.94 at a
// constant worn volume), so one depth cannot tell them apart; the width of a measured worn
// profile can. Each candidate run (the same case at footprint r_i) is fitted its W_i
// (calibration.h) and leaves a residual sum of squares RSS_i. The profile RSS(r) through the
// lowest candidate and its two neighbours, as a parabola in r (a footprint off by dr widens the
// pattern by about dr and adds (k dr)^2 to the residuals) and as one in ln r (a relative misfit),
// gives r^ as the geometric mean of their minima and the 95 % interval
//
//   {r : RSS(r) <= RSS(r^) (1 + D F(1, nu) / (n - 2))}, widened by half the two minima's
//   distance on ln r (the profile is known at the candidates only: the interpolation's error)
//
// (a profile-likelihood interval, F(1, nu) = t(0.975, nu)^2, nu = the best run's spatial
// blocks - 2, n the measurements: neighbouring scan points are not independent, and D, the
// best run's design effect (the cluster-robust variance of its W fit over the one independent
// measurements would give, at least 1), says how many of them make one independent
// measurement. With D = n / nu (every block's points alike) the level is 1 + F / nu, as if the
// blocks were the measurements; with independent noise D = 1 and every point counts. (Until
// session 25 the level was always 1 + F / nu: two scans at the same places, the second at a
// small tonnage, doubled RSS without adding blocks and made the footprint "not identifiable".)); W^ and the life's relative change
// along the ridge W(r) by the same kind of parabola through ln W_i and ln (L_i / s_i) (a candidate's life
// at its fitted W: L_i over its scale, the life going as 1 / W). The fit is refused as not
// identifiable, with W for the best candidate's r, when fewer than three footprints are given,
// the best is the smallest or largest candidate, or the interval reaches past the candidates on
// either side (a single depth, or no width information: the residuals do not rise away from the
// best r); W is then given for the footprint assumed, the first run's.
#include <string>
#include <vector>

namespace abrade::field
{
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
  };

  struct FootprintFit
  {
    bool        identifiable = false;
    std::string reason;              ///< why not, in words
    double      r = 0, r_low = 0, r_high = 0; ///< [m] r^ and its 95 % interval (the best candidate's r when not identifiable)
    double      w = 0;               ///< W at r^ (or the best candidate's)
    double      sd_log_r = 0;        ///< the standard error of ln r^ (interval / 2 t)
    double      dlnw_dlnr = 0;       ///< along the ridge
    double      dlnlife_dlnr = 0;    ///< the life's relative change per relative change of r along the ridge (0: no lives)
    double      dof = 0;             ///< nu
  };

  /// Fits r and W from @p candidates (any order).
  FootprintFit fit_footprint(std::vector<FootprintCandidate> candidates);
} // namespace abrade::field
