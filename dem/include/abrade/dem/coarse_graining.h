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

#include <cstdint>
#include <string>
#include <vector>

namespace abrade::dem
{
  /// Applies the rules above for ratio @p f to a fill region described with the real particles
  /// (sizes, and count unless it is 0: then the solid fraction, which stays) and to the
  /// settings' skin (when it is given). Returns the count before rounding (a bed of a few
  /// particles is the caller's to refuse). Throws std::invalid_argument for f <= 0.
  double coarse_grain(double f, FillRegion &fill, Settings &settings);

  /// Multi-level coarse graining: finer particles in a box (around a tool's path), the bulk's
  /// coarser ones elsewhere, and between them layers of intermediate sizes, each a shell around
  /// the box (docs/coarse-graining.md). Two sizes that meet directly pack denser where they
  /// mix (the finer fill the coarser ones' boundary voids) and looser just inside the finer side
  /// (a wall of large spheres); sizes graded by geometric steps (Pogulis and Servin 2025, "Local
  /// particle refinement in terramechanical simulations", J. Terramechanics 120, 101083, their
  /// layers d_n = r d_(n-1)) meet as a nearly monodisperse bed at every interface.
  struct FineRegion
  {
    Vec3   lo = Vec3::Zero(), hi = Vec3::Zero(); ///< the finest particles' box
    double factor = 1;                           ///< their coarse-graining ratio
    /// Largest ratio between the factors of neighbouring levels (> 1); 0: no layer between
    /// (the finest particles meet the bulk's).
    double step = 1.25;
    /// Thickness of each transition layer in its particles' largest diameters.
    double layer_diameters = 1;
  };

  /// One level of a multi-level bed: its fill, coarse-grained by its factor, and the volume of
  /// its region (its box less the finer levels' box) [m^3].
  struct Level
  {
    FillRegion fill;
    double     factor;
    double     volume;
  };

  /// The factors of the levels from @p fine (the finest) to @p bulk (not included): @p fine and
  /// the intermediate ones, in equal ratios no larger than @p step (none for step 0 or >= bulk /
  /// fine). Throws std::invalid_argument for a step in (0, 1.05) (thousands of levels).
  std::vector<double> level_factors(double fine, double bulk, double step);

  /// The random seed of level @p level (0: the finest) of a multi-level bed whose bulk draws with
  /// @p bulk_seed: each level its own draws, all following the bed's seed.
  inline std::uint64_t level_seed(std::uint64_t bulk_seed, std::size_t level) { return bulk_seed + 1000003 * (level + 1); }

  /// Gives the bed the seed @p seed: the bulk's fill @p fill and every level of @p levels.
  void reseed(FillRegion &fill, std::vector<Level> &levels, std::uint64_t seed);

  /// Splits @p fill (described with the real particles; a fill box without region mesh) into the
  /// finer levels of @p region, finest first, each coarse-grained by its factor: the box, then a
  /// shell per intermediate factor around it (its thickness region.layer_diameters of its
  /// particles' largest diameter). Every level places its particles' centres in its region,
  /// whole in the fill box and clear of the finer levels' particles. @p fill keeps the rest
  /// (its centres out of the outermost box), described with the real particles, for the caller
  /// to coarse-grain by the bulk's factor. The real count is split by volume (with Count 0 every
  /// level keeps the solid fraction); each level draws its own random numbers. Throws
  /// std::invalid_argument when the box misses the fill box, the fill has a region mesh, a
  /// shell would be cut by a face of the fill box, or the outermost shell leaves a gap to a
  /// face narrower than a bulk particle's diameter (which no bulk centre could fill) or no
  /// room for the bulk at all.
  std::vector<Level> split_into_levels(FillRegion &fill, const FineRegion &region, double bulk_factor);

  /// The level whose footprint holds the point (@p x, @p y): the first (finest first) whose
  /// box's extent across x and y holds it, where a box that reaches a face of the fill box goes
  /// on beyond it (a particle that settled against the container's wall is still over its
  /// level); levels.size(): the bulk's (outside every box).
  std::size_t footprint_of(const std::vector<Level> &levels, double x, double y);

  /// The mass of the owned particles of @p P whose centres lie over each level's footprint,
  /// finest first, the bulk's last (levels.size() + 1 values): this rank's share. The mass per
  /// area over the fine region is what its particles weigh on a tool below the surface and what
  /// sets the bed's height there.
  std::vector<double> footprint_masses(const std::vector<Level> &levels, const ParticleStore &P);

  /// The counts of the next pour of a multi-level bed (the bulk's last): each finer level's
  /// count of this pour @p counts plus the mass its footprint lacked once settled (@p wanted -
  /// @p settled, all ranks' sums; wanted: the case's, the first pour's) in particles of the
  /// level's mean mass @p mean_mass, rounded; the bulk's count less the mass added. Where the
  /// sizes meet, the finer particles spread into the coarser ones' voids (about half a fine
  /// radius at every interface; the 0.48 m wide fine column of the knife-bed lost 3.3 % of its
  /// mass and settled 15 mm lower than the uniform bed, docs/coarse-graining.md); poured again
  /// with these counts the fine region holds more of its share. A level whose footprint held
  /// more than its share (the shells, which the finer particles spread into) keeps its count:
  /// emptier shells would take in more of the finer particles. The total mass stays.
  std::vector<long> refill_counts(const std::vector<long> &counts, const std::vector<double> &mean_mass,
                                  const std::vector<double> &wanted, const std::vector<double> &settled);

  /// An energy per particle (the settling threshold) for particles coarse-grained by @p f:
  /// x f^3, as the particle's mass.
  inline double coarse_grain_energy(double f, double energy) { return energy * f * f * f; }

  /// Parameters that stay in absolute units while the particles scale by @p f: a fixed time
  /// step (the Rayleigh time moves with f). One warning per such parameter; none for f = 1.
  std::vector<std::string> coarse_graining_warnings(double f, const Settings &settings);
} // namespace abrade::dem
