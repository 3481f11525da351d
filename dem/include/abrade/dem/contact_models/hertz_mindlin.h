#pragma once
// The normal, damping and tangential sub-models of the Hertz-Mindlin (no slip) law as EDEM and
// LIGGGHTS (`gran model hertz tangential history`) define it (docs/physics.md, section 1):
//
//  normal      F_el = 4/3 E* sqrt(R*) delta^(3/2), stiffness S_n = 2 E* sqrt(R* delta);
//  damping     F_d = -c sqrt(S_n m*) v_n and -c sqrt(S_t m*) v_t, with c from the restitution
//              (Simulation/Damping model: EDEM's -2 sqrt(5/6) beta, or calibrated so that a
//              Hertz contact rebounds with exactly e; PairCoefficients::damping);
//  tangential  S_t = 8 G* sqrt(R* delta); the spring's displacement history turned into the
//              current tangent plane each step; Coulomb-limited by mu |F_n| (the repulsive normal
//              force), damped only while sticking, as LIGGGHTS does.
//
// Written branch-free (selects), so that the batched pair kernel vectorises it.
#include <abrade/dem/contact_models/contact_state.h>
#include <abrade/dem/material.h>

#include <cmath>

namespace abrade::dem::contact_models
{
  struct HertzMindlin
  {
    static constexpr int history = 3; ///< the tangential spring's displacement

    /// Normal (elastic + damping) and tangential force of @p s into @p r; @p h: the history.
    [[gnu::always_inline]] static inline void evaluate(const ContactState &s, const PairCoefficients &c, double dt, double *h,
                                ContactResponse &r)
    {
      // (locals throughout, stored into r at the end: a select on a value read back from r
      // keeps GCC from if-converting, and the pair loop from vectorising)
      const double vn  = s.vx * s.nx + s.vy * s.ny + s.vz * s.nz;
      const double vtx = s.vx - vn * s.nx, vty = s.vy - vn * s.ny, vtz = s.vz - vn * s.nz;

      // S_n = 2 E* sqrt(R* d), S_t = 8 G* sqrt(R* d); the damping needs sqrt(S m*), computed as
      // sqrt(2 E*) (resp. sqrt(8 G*)) times one common sqrt(sqrt(R* d) m*)
      const double sqrt_rd   = std::sqrt(s.r_eff * s.overlap);
      const double s_t       = 8 * c.g_star * sqrt_rd;
      const double f_el      = (4.0 / 3.0) * c.e_star * sqrt_rd * s.overlap;
      const double w         = c.damping > 0 ? c.damping * std::sqrt(sqrt_rd * s.m_eff) : 0.0;
      const double repulsion = f_el - w * c.sqrt_2e * vn;

      double s0 = h[0], s1 = h[1], s2 = h[2];
      rotate_into_tangent_plane(s0, s1, s2, s.nx, s.ny, s.nz);
      s0 += vtx * dt, s1 += vty * dt, s2 += vtz * dt;

      // spring force, Coulomb-limited; damping only while sticking
      const double fs0 = -s_t * s0, fs1 = -s_t * s1, fs2 = -s_t * s2;
      const double fsq       = fs0 * fs0 + fs1 * fs1 + fs2 * fs2;
      const double f_coulomb = c.friction * std::abs(repulsion);
      const bool   sliding   = fsq > f_coulomb * f_coulomb;
      const double ratio     = sliding ? f_coulomb / std::sqrt(fsq) : 1.0;
      const double ct        = w * c.sqrt_8g;
      r.ftx = sliding ? fs0 * ratio : fs0 - ct * vtx;
      r.fty = sliding ? fs1 * ratio : fs1 - ct * vty;
      r.ftz = sliding ? fs2 * ratio : fs2 - ct * vtz;
      h[0]  = sliding ? s0 * ratio : s0;
      h[1]  = sliding ? s1 * ratio : s1;
      h[2]  = sliding ? s2 * ratio : s2;
      r.vn = vn, r.vtx = vtx, r.vty = vty, r.vtz = vtz;
      r.repulsion = r.normal = repulsion;
    }
  };
} // namespace abrade::dem::contact_models
