#pragma once
// Rolling resistance as an elastic-plastic spring-dashpot (EPSD, Ai, Chen, Rotter and Ooi 2011,
// "Assessment of rolling resistance models in discrete element simulations", Powder Technology
// 206, model C; LIGGGHTS' `rolling_friction epsd`): a rolling spring torque M_k that grows with
// the relative rolling rotation,
//
//   M_k <- M_k - k_r w_t dt,   k_r = 2.25 k_n mu_r^2 R*^2,   |M_k| <= mu_r R* |F_n|,
//
// with w_t the relative angular velocity (w_i - w_j) in the tangent plane (twisting excluded),
// k_n = 4/3 E* sqrt(R* delta) the Hertz normal stiffness F_el / delta (as LIGGGHTS' kn) and
// F_n the repulsive normal force; and, while the spring is below its limit, a viscous torque
// M_d = -eta_r 2 sqrt(I_r k_r) w_t with I_r = 1 / (1/(I_i + m_i r_i^2) + 1/(I_j + m_j r_j^2))
// (a wall: I_i + m_i r_i^2). The spring's torque is kept in the contact's history and turned
// into the current tangent plane each step, as the tangential spring is. Unlike the constant
// torque, a particle at rest under a tangential load below the limit is held by the spring:
// it neither rolls nor chatters.
#include <abrade/dem/contact_models/contact_state.h>
#include <abrade/dem/material.h>
#include <abrade/dem/parameter_section.h>

#include <cmath>

namespace abrade::dem::contact_models
{
  struct EpsdRolling
  {
    static constexpr const char *name = "epsd";
    static constexpr const char *documentation =
      "elastic-plastic spring-dashpot (Ai et al. 2011, model C; LIGGGHTS' epsd): a rolling spring "
      "k_r = 2.25 k_n mu_r^2 R*^2 limited to mu_r R* |F_n|, damped by Rolling damping ratio below the limit";
    static constexpr int  history        = 3; ///< the spring's torque on i
    static constexpr bool needs_rotation = true;

    static void declare_parameters(ParameterSection &p)
    {
      p.declare_number("Rolling damping ratio", 0.3, 0, 10,
                       "[-] Rolling model epsd: eta_r, the rolling dashpot's fraction of its critical damping "
                       "2 sqrt(I_r k_r) (Ai et al. 2011 use 0.3). Range: [0, 10].");
    }
    static void parse_parameters(const ParameterSection &p, Interaction &i)
    {
      i.rolling_damping = p.number("Rolling damping ratio");
    }

    [[gnu::always_inline]] static inline void evaluate(const ContactState &s, const PairCoefficients &c, double dt, double *h,
                                ContactResponse &r)
    {
      const double wn  = s.wx * s.nx + s.wy * s.ny + s.wz * s.nz;
      const double wtx = s.wx - wn * s.nx, wty = s.wy - wn * s.ny, wtz = s.wz - wn * s.nz;
      const double k_n = (4.0 / 3.0) * c.e_star * std::sqrt(s.r_eff * s.overlap);
      const double k_r = 2.25 * k_n * c.rolling_friction * c.rolling_friction * s.r_eff * s.r_eff;

      double m0 = h[0], m1 = h[1], m2 = h[2];
      rotate_into_tangent_plane(m0, m1, m2, s.nx, s.ny, s.nz);
      m0 -= k_r * wtx * dt, m1 -= k_r * wty * dt, m2 -= k_r * wtz * dt;
      const double limit    = c.rolling_friction * s.r_eff * std::abs(r.repulsion);
      const double m2sum    = m0 * m0 + m1 * m1 + m2 * m2;
      const bool   at_limit = m2sum > limit * limit;
      const double ratio    = at_limit ? limit / std::sqrt(m2sum) : 1.0;
      m0 *= ratio, m1 *= ratio, m2 *= ratio;
      const double c_r = at_limit ? 0.0 : c.rolling_damping * 2 * std::sqrt(s.rolling_inertia * k_r);
      r.mx = m0 - c_r * wtx, r.my = m1 - c_r * wty, r.mz = m2 - c_r * wtz;
      h[0] = m0, h[1] = m1, h[2] = m2;
      r.rolling_limit = 0;
    }
  };
} // namespace abrade::dem::contact_models
