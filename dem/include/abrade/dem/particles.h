#pragma once
// Particle state as a structure of arrays (one contiguous array per component), as LAMMPS and
// DEM-Engine keep it: the force kernels stream through x, y, z, radius without touching data
// they do not need, and a reorder is one permutation applied to every array.
#include <cstdint>
#include <vector>

namespace abrade::dem
{
  struct ParticleStore
  {
    std::vector<double>       x, y, z;          ///< position [m]
    std::vector<double>       vx, vy, vz;       ///< velocity [m/s]
    std::vector<double>       wx, wy, wz;       ///< angular velocity [rad/s]
    std::vector<double>       fx, fy, fz;       ///< force [N]
    std::vector<double>       tx, ty, tz;       ///< torque [N m]
    /// rolling-resistance torque of the step's contacts, sum of mu_r |F_n| R [N m]: it slows the
    /// particle's spin and never reverses it (applied in the kicks, not as a torque vector)
    std::vector<double>       rolling;
    std::vector<double>       radius, mass;     ///< [m], [kg]
    std::vector<double>       inv_mass, inv_inertia;
    std::vector<int>          material;         ///< index into the simulation's materials
    std::vector<std::int64_t> id;               ///< stable identifier (survives reordering)

    std::size_t n_ghost = 0;       ///< ghost copies at the end of the arrays
    std::size_t n_distributed = 0; ///< particles before this index are spread over the ranks

    /// Particles owned here.
    std::size_t size() const { return x.size() - n_ghost; }
    /// Owned particles and ghosts.
    std::size_t n_local() const { return x.size(); }
    /// Mass of the particles whose centre lies above height @p z [kg] (a grab's payload).
    double mass_above(double z_min) const
    {
      double m = 0;
      for (std::size_t i = 0; i < size(); ++i)
        if (z[i] > z_min)
          m += mass[i];
      return m;
    }

    /// Appends a particle at rest; returns its index. No ghosts may be present.
    std::size_t add(std::int64_t id, double x, double y, double z, double radius, double density,
                    int material);

    /// Reorders (and possibly drops) particles: new particle k is old particle order[k].
    void permute(const std::vector<std::size_t> &order, int threads = 1);
    void clear();
    /// Keeps the first @p n entries of every array (drops the ghosts when n = size()), or
    /// extends them with zeros; n_ghost is reset.
    void resize_arrays(std::size_t n);
    /// Reorders entries first, first + 1, ...: new entry first + k is old entry first + order[k].
    void permute_range(std::size_t first, const std::vector<std::size_t> &order);

    /// Values per particle in pack() / unpack() records.
    static constexpr int record_size = 22;
    /// Appends particle @p i (every array) to @p out.
    void pack(std::size_t i, std::vector<double> &out) const;
    /// Appends the particle packed at @p in; returns its index.
    std::size_t unpack(const double *in);

  private:
    template <typename F>
    void for_each_array(F &&f);
  };
} // namespace abrade::dem
