#pragma once
// Coarse graining: a simulated particle f times the size of the real one stands for f^3 real
// particles (f, the coarse-graining ratio, >= 1 as a rule). The rules that keep the bulk's
// behaviour (Bierwisch, Kraft, Riedel and Moseler 2009, "Three-dimensional discrete element
// models for the granular statics and dynamics of powders in cavity filling", J. Mech. Phys.
// Solids 57, 10-31; the scaling Aspherix and Rocky document for their coarse-graining models):
//
//  - lengths of the particle scale by f: radius, the size distribution's bounds and spread;
//  - the number of particles in a given region scales by f^-3, so the bulk mass stays;
//  - density, elastic moduli, Poisson's ratio, restitution and the (sliding and rolling)
//    friction coefficients stay: Hertz-Mindlin contacts between spheres scaled by f carry the
//    same stress at the same strain, and the same energy per unit volume (Bierwisch et al.), so
//    the bulk density, the angle of repose and the stresses on a tool stay;
//  - the time step follows from the scaled radius (the Rayleigh time grows with f);
//  - numerical lengths tied to the particle scale by f (the Verlet skin), and energies per
//    particle by f^3 (the settling threshold).
//
// What does not scale is the granularity itself: a tool sees f^-2 times fewer, f^2 times
// stronger contacts per area, and a layer of particles next to it is f times thicker. How much
// that moves the wear on a tool is what docs/coarse-graining.md measures.
#include <abrade/dem/generation.h>
#include <abrade/dem/simulation.h>

#include <string>
#include <vector>

namespace abrade::dem
{
  /// Applies the rules above for ratio @p f to a fill region described with the real particles
  /// (sizes, and count unless it is 0: then the solid fraction, which stays) and to the
  /// settings' skin (when it is given). Returns the count before rounding (a bed of a few
  /// particles is the caller's to refuse). Throws std::invalid_argument for f <= 0.
  double coarse_grain(double f, FillRegion &fill, Settings &settings);

  /// Multi-level coarse graining (a prototype): the part of @p fill (described with the real
  /// particles, a fill box without a region mesh) inside the box [@p lo, @p hi] becomes a fill
  /// of its own, which the caller coarse-grains by a smaller factor; @p fill keeps the rest
  /// (it excludes the box). The real count is split by volume. Returns the box's fill.
  FillRegion split_off_region(FillRegion &fill, const Vec3 &lo, const Vec3 &hi);

  /// An energy per particle (the settling threshold) for particles coarse-grained by @p f:
  /// x f^3, as the particle's mass.
  inline double coarse_grain_energy(double f, double energy) { return energy * f * f * f; }

  /// Parameters that stay in absolute units while the particles scale by @p f: a fixed time
  /// step (the Rayleigh time moves with f). One warning per such parameter; none for f = 1.
  std::vector<std::string> coarse_graining_warnings(double f, const Settings &settings);
} // namespace abrade::dem
