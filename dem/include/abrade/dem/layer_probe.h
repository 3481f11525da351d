#pragma once
// A layer probe (what the thesis, docs/physics.md, calls a "geometry bin"): a layer that moves
// with a wall and holds the particles in direct contact with it. Every few steps it counts the particles whose centre is
// within `thickness` of the wall's surface and their mean velocity along an axis, next to the
// wall's own velocity along that axis: the difference is how fast the contact layer slides
// along the wall. It also counts the contacts with the wall in that step (a particle that
// touches two faces of an edge or a corner makes two).
#include <abrade/dem/contact_log.h>
#include <abrade/dem/triangle_mesh.h>

#include <string>
#include <vector>

namespace abrade::dem
{
  class LayerProbe : public StepHook
  {
  public:
    struct Sample
    {
      double      time;
      std::string phase;
      long        count;
      double      mean_velocity; ///< of the particles in the layer, along the axis [m/s]
      double      wall_velocity; ///< of the wall's centre along the axis [m/s]
      long        contacts;      ///< contacts with the wall in that step (per particle and face it touches)
    };

    /// @p thickness: from the surface to a particle centre [m]; @p every: sample interval in steps.
    LayerProbe(const Simulation &sim, std::size_t wall, double thickness, const Vec3 &axis, long every);

    void after_step(const Simulation &sim, const ContactLog &log) override;
    void phase_changed(const Simulation &sim, const std::string &phase) override { current = phase; }
    const std::vector<Sample> &samples() const { return taken; }
    std::size_t               wall_index() const { return wall; }

  private:
    std::size_t         wall;
    double              thickness;
    Vec3                axis;
    long                every;
    std::string         current = "-";
    std::vector<Sample> taken;
    // triangles of the reference mesh binned in a grid of cells (wall frame: the wall is rigid)
    Vec3                           lo;
    double                         cell;
    long                           nx, ny, nz;
    std::vector<std::vector<int>>  bins;
    double distance_to_surface(const Simulation &sim, const Vec3 &reference_point) const;
  };
} // namespace abrade::dem
