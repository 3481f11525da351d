#pragma once
// What a contact sub-model reads and writes (contact_law.h). Plain scalars, so that the batched
// pair kernel vectorises the composed law.
#include <cmath>

namespace abrade::dem
{
  /// One contact, as the particle-pair and the particle-wall paths both present it. Body i is
  /// the particle the force acts on; body j its partner (a particle or a wall).
  struct ContactState
  {
    double nx, ny, nz;   ///< unit normal from j to i
    double overlap;      ///< delta_n > 0 [m]
    double r_eff, m_eff; ///< R* = ri rj / (ri + rj) (a wall: ri), m* likewise (a wall: mi)
    double vx, vy, vz;   ///< velocity of i's contact point minus j's [m/s]
    // read only by the sub-models that declare they need them (see contact_law.h)
    double wx, wy, wz;      ///< angular velocity of i minus j's [rad/s] (rolling)
    double rolling_inertia; ///< effective rolling inertia [kg m^2] (rolling)
    double area;            ///< contact area pi a^2 from the spheres' intersection [m^2] (cohesion)
  };

  /// The composed law's answer for one contact.
  struct ContactResponse
  {
    double normal;          ///< signed normal force on i along n: repulsion minus cohesion [N]
    double repulsion;       ///< elastic + damping part of it (Coulomb and rolling limits use it) [N]
    double ftx, fty, ftz;   ///< tangential force on i [N]
    double vn;              ///< normal relative velocity (negative when approaching) [m/s]
    double vtx, vty, vtz;   ///< sliding velocity of the contact point [m/s]
    double rolling_limit;   ///< constant-torque rolling: mu_r |F_n|, times each body's radius [N]
    double mx, my, mz;      ///< torque rolling models put on i (j gets the opposite) [N m]
  };

  /// A solid sphere's moment of inertia about a point of its surface, I + m r^2 = 1.4 m r^2
  /// (what rolls about a contact point).
  inline double rolling_inertia_of_sphere(double mass, double radius) { return 1.4 * mass * radius * radius; }

  /// Turns a history vector (s0, s1, s2) into the current tangent plane of normal n, keeping its
  /// magnitude: project, then rescale by sqrt(|s|^2 / |s_projected|^2) = sqrt(1 + r) with
  /// r = sn^2 / |s_projected|^2. The normal turns little in one step, so r is tiny and the series
  /// is exact to round-off. A history along n alone is lost. Branch-free.
  [[gnu::always_inline]] inline void rotate_into_tangent_plane(double &s0, double &s1, double &s2, double nx, double ny, double nz)
  {
    const double sn    = s0 * nx + s1 * ny + s2 * nz;
    const double m0    = s0 * s0 + s1 * s1 + s2 * s2;
    const double m1    = m0 - sn * sn;
    const double rr    = m1 > 0 ? sn * sn / m1 : 0.0;
    const double scale = rr < 1e-5 ? 1 + rr * (0.5 - 0.125 * rr) : std::sqrt(1 + rr);
    const bool   lost  = sn != 0 && !(m1 > 0);
    s0                 = lost ? 0.0 : (s0 - sn * nx) * scale;
    s1                 = lost ? 0.0 : (s1 - sn * ny) * scale;
    s2                 = lost ? 0.0 : (s2 - sn * nz) * scale;
  }
} // namespace abrade::dem
