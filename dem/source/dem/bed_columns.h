#pragma once
// A bed as read from a file, column by column, and the checks every bed read from a file passes
// before its particles replace a simulation's: abrade's bed files (generation.cc) and the tables
// and dumps of other codes (bed_import.cc).
#include <abrade/dem/simulation.h>

#include <array>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace abrade::dem
{
  struct BedColumns
  {
    std::vector<double>       x, y, z, vx, vy, vz, wx, wy, wz, radius, mass;
    std::vector<int>          material;
    std::vector<std::int64_t> id;

    std::size_t size() const { return x.size(); }
    /// The columns of doubles, in the order of a bed file.
    std::array<std::vector<double> *, 11> doubles()
    {
      return {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &radius, &mass};
    }
    std::array<const std::vector<double> *, 11> doubles() const
    {
      return {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &radius, &mass};
    }
    void resize(std::size_t n)
    {
      for (auto *c : doubles())
        c->assign(n, 0.0);
      material.assign(n, 0);
      id.assign(n, 0);
    }
  };

  /// Replaces the particles of @p sim with those of @p bed, after checking that there is at
  /// least one, that every value is finite, radii are 1 um to 10 m, masses positive, materials
  /// known, positions inside Simulation/Domain and ids unique; InputError naming @p path and
  /// the particle (@p name_of gives its name: a line of the file, or its index and id).
  void replace_particles(Simulation &sim, const std::string &path, const BedColumns &bed,
                         const std::function<std::string(std::size_t)> &name_of);
} // namespace abrade::dem
