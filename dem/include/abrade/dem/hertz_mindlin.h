#pragma once
// The Hertz-Mindlin (no slip) contact force, as EDEM and LIGGGHTS (`gran model hertz tangential
// history`) define it. One inline function serves particle-particle and particle-wall contacts;
// it allocates nothing and keeps the tangential history in caller-owned storage.
#include <abrade/dem/material.h>

#include <cmath>

namespace abrade::dem
{
  struct ContactForce
  {
    double normal;     ///< signed normal force along n (elastic + damping) [N]
    double ft[3];      ///< tangential force on body i [N]
    double vn;         ///< normal relative velocity v_rel . n (negative when approaching)
    double vt[3];      ///< tangential relative velocity of the contact point
    bool   sliding;    ///< Coulomb limit reached
  };

  /// Force on body i from body j.
  /// @param n       unit normal pointing from j to i
  /// @param overlap delta_n > 0
  /// @param vrel    velocity of i's contact point minus j's
  /// @param shear   tangential displacement history (3 doubles), updated in place
  inline ContactForce hertz_mindlin(const double n[3], double overlap, double r_eff, double m_eff,
                                    const double vrel[3], const PairCoefficients &c, double dt,
                                    double *shear)
  {
    ContactForce f;
    f.vn = vrel[0] * n[0] + vrel[1] * n[1] + vrel[2] * n[2];
    for (int d = 0; d < 3; ++d)
      f.vt[d] = vrel[d] - f.vn * n[d];

    // S_n = 2 E* sqrt(R* d), S_t = 8 G* sqrt(R* d); the damping needs sqrt(S m*), computed as
    // sqrt(2 E*) (resp. sqrt(8 G*)) times one common sqrt(sqrt(R* d) m*)
    const double sqrt_rd = std::sqrt(r_eff * overlap);
    const double s_t     = 8 * c.g_star * sqrt_rd;
    const double f_el    = (4.0 / 3.0) * c.e_star * sqrt_rd * overlap;
    const double w       = c.damping > 0 ? c.damping * std::sqrt(sqrt_rd * m_eff) : 0.0;
    f.normal             = f_el - w * c.sqrt_2e * f.vn;

    // Rotate the history into the current tangent plane, keeping its magnitude: project, then
    // rescale by sqrt(|s|^2 / |s_projected|^2) = sqrt(1 + r) with r = sn^2 / |s_projected|^2.
    // The normal turns little in one step, so r is tiny and the series is exact to round-off.
    const double sn = shear[0] * n[0] + shear[1] * n[1] + shear[2] * n[2];
    if (sn != 0)
      {
        const double m0 = shear[0] * shear[0] + shear[1] * shear[1] + shear[2] * shear[2];
        const double m1 = m0 - sn * sn;
        if (m1 > 0)
          {
            const double r     = sn * sn / m1;
            const double scale = r < 1e-5 ? 1 + r * (0.5 - 0.125 * r) : std::sqrt(1 + r);
            for (int d = 0; d < 3; ++d)
              shear[d] = (shear[d] - sn * n[d]) * scale;
          }
        else
          shear[0] = shear[1] = shear[2] = 0;
      }
    for (int d = 0; d < 3; ++d)
      shear[d] += f.vt[d] * dt;

    // Spring force, Coulomb-limited; damping only while sticking (as LIGGGHTS does).
    const double fs[3]     = {-s_t * shear[0], -s_t * shear[1], -s_t * shear[2]};
    const double fs2       = fs[0] * fs[0] + fs[1] * fs[1] + fs[2] * fs[2];
    const double f_coulomb = c.friction * std::abs(f.normal);
    f.sliding              = fs2 > f_coulomb * f_coulomb;
    if (f.sliding)
      {
        const double ratio = f_coulomb / std::sqrt(fs2);
        for (int d = 0; d < 3; ++d)
          {
            f.ft[d] = fs[d] * ratio;
            shear[d] *= ratio;
          }
      }
    else
      {
        const double ct = w * c.sqrt_8g;
        for (int d = 0; d < 3; ++d)
          f.ft[d] = fs[d] - ct * f.vt[d];
      }
    return f;
  }
} // namespace abrade::dem
