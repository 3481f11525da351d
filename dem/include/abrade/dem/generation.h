#pragma once
// Filling a region with particles, reproducibly from a seed, by random sequential addition:
// each particle goes to a uniformly random position (in a box, optionally inside a closed mesh,
// clear of the walls) that overlaps no particle placed before it, as LIGGGHTS' insert/pack
// does; when random draws stall, a sweep of the free space places the rest (a solid fraction of
// up to about 0.35 of a box). A lattice would be quicker but leaves non-rotating frictional
// spheres stacked in rigid columns. A pour-and-settle run then packs them (Simulation::settle).
#include <abrade/dem/triangle_mesh.h>

#include <cstdint>
#include <random>
#include <optional>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Simulation;

  struct SizeDistribution
  {
    enum class Kind
    {
      constant,
      uniform,        ///< uniform in [min, max]
      normal          ///< normal(mean, std), truncated to [min, max]
    };
    Kind   kind   = Kind::constant;
    double radius = 0.0275; ///< constant radius / normal mean [m]
    double min    = 0, max = 0, std = 0;

    double largest() const { return kind == Kind::constant ? radius : max; }
    double sample(std::mt19937_64 &rng) const;
    /// Mean particle volume.
    double mean_volume() const;
  };

  struct FillRegion
  {
    Vec3                box_min = Vec3::Zero(), box_max = Vec3::Zero();
    const TriangleMesh *inside  = nullptr; ///< optional closed mesh: keep sites inside it
    /// Meshes (walls) the particles must not touch.
    std::vector<TriangleMesh> avoid;
    /// Boxes (lower, upper corner) the particles stay out of, whole (another fill's region);
    /// with centres_in, their centres.
    std::vector<std::pair<Vec3, Vec3>> exclude;
    /// A level of a multi-level bed around finer ones (coarse_graining.h): the centres lie in
    /// this box (and out of the excluded ones), the spheres whole in the fill box and clear of
    /// the particles already in the simulation (the finer levels'), so that the levels touch
    /// where they meet. Unset: the particles stay whole in the box, apart from the others.
    std::optional<std::pair<Vec3, Vec3>> centres_in;
    SizeDistribution    sizes;
    long                count          = 0;   ///< particles to place; 0: use solid_fraction
    double              solid_fraction = 0.3; ///< of the region volume
    std::uint64_t       seed           = 1;
    int                 material       = 0;
    Vec3                velocity       = Vec3::Zero();
  };

  /// The particles @p region asks for: its count, else its solid fraction of its region (its
  /// mesh's volume, else the box or the level's centres' box, less the excluded boxes) in
  /// particles of the mean volume. fill_region places this many (rounded).
  double expected_particles(const FillRegion &region);

  /// Adds the particles to the simulation (ids continue from the largest existing id); returns
  /// how many were added. Throws InputError when the region cannot hold them.
  long fill_region(Simulation &sim, const FillRegion &region);

  /// Point-in-closed-mesh test by ray parity (used by fill_region).
  bool inside_mesh(const TriangleMesh &mesh, const Vec3 &p);

  /// Saves the particle state (a settled bed) to a binary file, and reads it back. A bed
  /// restarts every operating cycle from the same packing without settling again. Under MPI
  /// save_bed is collective (rank 0 writes all particles, sorted by id) and every rank loads the
  /// whole file (Simulation::setup() spreads the particles over the ranks).
  void save_bed(const Simulation &sim, const std::string &path);
  /// Replaces the simulation's particles with those in @p path; throws InputError naming the
  /// file if it is not a bed file, its size does not match its count, its checksum does not
  /// match (changed or cut), or a particle has a non-finite value, a non-positive radius or
  /// mass, an unknown material or a repeated id. save_bed replaces the file at once (written
  /// aside and renamed).
  void load_bed(Simulation &sim, const std::string &path);
} // namespace abrade::dem
