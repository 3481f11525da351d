// How far a multi-level bed's fine region reaches beyond the worn walls' paths, against the
// depth they work at (fine_region_margin.h). The knife-bed's beds showed the need: with the fine
// box 0.225 m beside the knife's faces, 0.8 times the 0.285 m its edge works at below the bed's
// surface, the force over the first half of its travel read 9 % below the uniform fine beds' (twelve
// beds each), 4 % at 1.2 times, 0.2 % above at 1.6 times; the wear and the other forces held
// within their scatter (docs/coarse-graining.md). A user sees no such bias in a single run.
#include <abrade/common/format_number.h>
#include <abrade/coupling/dem_run/fine_region_margin.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace abrade::coupling
{
  std::optional<std::pair<dem::Vec3, dem::Vec3>> swept_box(const dem::Wall &wall, const std::vector<Phase> &phases,
                                                           const int samples_per_phase)
  {
    using Kind = dem::WallMotion::Kind;
    if (wall.motion.kind != Kind::fixed && wall.motion.kind != Kind::prescribed)
      return std::nullopt; // (a free body's or a mechanism's path follows from the loads)
    dem::Wall  w = wall; // moved through the cycle as the simulation moves it, step by step
    dem::Vec3  lo = dem::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    const auto extend = [&] {
      for (std::size_t v = 0; v < w.mesh.vertices.size(); ++v)
        for (int d = 0; d < 3; ++d)
          lo[d] = std::min(lo[d], w.current[3 * v + d]), hi[d] = std::max(hi[d], w.current[3 * v + d]);
    };
    extend();
    for (const auto &[name, duration] : phases)
      {
        w.set_phase(name);
        const double dt = duration / samples_per_phase;
        for (int k = 0; k < samples_per_phase; ++k)
          w.advance(dt), extend();
      }
    return std::make_pair(lo, hi);
  }

  double bed_surface(const dem::Simulation &sim, const dem::FillRegion &fill)
  {
    const double cell = 4 * sim.largest_radius();
    const int    nx   = std::max(1, int(std::ceil((fill.box_max.x() - fill.box_min.x()) / cell)));
    const int    ny   = std::max(1, int(std::ceil((fill.box_max.y() - fill.box_min.y()) / cell)));
    const double none = -std::numeric_limits<double>::max();
    std::vector<double> top(std::size_t(nx) * ny, none);
    const auto &P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      {
        const int ix = int(std::floor((P.x[i] - fill.box_min.x()) / cell)), iy = int(std::floor((P.y[i] - fill.box_min.y()) / cell));
        if (ix >= 0 && ix < nx && iy >= 0 && iy < ny)
          top[std::size_t(iy) * nx + ix] = std::max(top[std::size_t(iy) * nx + ix], P.z[i] + P.radius[i]);
      }
    sim.parallel().max(top);
    top.erase(std::remove(top.begin(), top.end(), none), top.end());
    if (top.empty())
      return none;
    const auto middle = top.begin() + top.size() / 2;
    std::nth_element(top.begin(), middle, top.end());
    return *middle;
  }

  std::vector<FineRegionMargin> fine_region_margins(const DemCase &c, const dem::Simulation &sim, const double surface)
  {
    std::vector<FineRegionMargin> out;
    const dem::Vec3 &g = c.settings.gravity;
    if (c.finer_levels.empty() || !c.finer_levels.front().fill.centres_in || !(g.z() < 0) ||
        std::hypot(g.x(), g.y()) > 1e-9 * -g.z())
      return out;
    const auto &[fine_lo, fine_hi] = *c.finer_levels.front().fill.centres_in;
    const dem::Vec3 &fill_lo = c.fill.box_min, &fill_hi = c.fill.box_max;
    for (std::size_t k = 0; k < c.walls.size() && k < sim.n_walls(); ++k)
      {
        if (c.walls[k].wear.empty())
          continue;
        const auto path = swept_box(sim.wall(k), c.phases);
        if (!path || path->first.z() >= surface)
          continue; // (not known, or above the bed)
        FineRegionMargin nearest{c.walls[k].wall.name, 0, std::numeric_limits<double>::infinity(), surface - path->first.z()};
        for (int d = 0; d < 2; ++d)
          {
            // a face on the fill box's has no bulk beyond it (the fine particles reach the wall)
            const double tol = 1e-9 * (fill_hi[d] - fill_lo[d]);
            if (fine_lo[d] > fill_lo[d] + tol && path->first[d] - fine_lo[d] < nearest.margin)
              nearest.axis = d, nearest.margin = path->first[d] - fine_lo[d];
            if (fine_hi[d] < fill_hi[d] - tol && fine_hi[d] - path->second[d] < nearest.margin)
              nearest.axis = d, nearest.margin = fine_hi[d] - path->second[d];
          }
        if (std::isfinite(nearest.margin))
          out.push_back(nearest);
      }
    return out;
  }

  void check_fine_region_margins(const DemCase &c, const dem::Simulation &sim, io::Log &log)
  {
    if (c.finer_levels.empty())
      return;
    const double surface = bed_surface(sim, c.fill); // (collective)
    for (const auto &m : fine_region_margins(c, sim, surface))
      {
        const std::string across = std::string(1, char('x' + m.axis));
        const std::string what   = "wall " + m.wall + "'s path comes " + io::format_number(m.margin, 3) +
                                 " m from the fine region's face across " + across + "; its lowest point is " +
                                 io::format_number(m.depth, 3) + " m below the bed's surface (z = " +
                                 io::format_number(surface, 4) + " m, its columns' median top): " + io::format_number(m.margin / m.depth, 3) + " times that depth";
        if (m.margin >= fine_region_margin_in_depths * m.depth)
          log.line("Fine region: " + what);
        else
          log.warning(
            "Particles/Coarse graining/Fine region: " + what + ", under the " + io::format_number(fine_region_margin_in_depths) +
            " times below which the multi-level knife-bed's force early in the travel read 4-9 % low " +
            (m.margin < 0 ? "(and the wall meets the bulk's coarse particles) " : "") + "(docs/coarse-graining.md): widen the fine region across " +
            across + " to at least " + io::format_number(fine_region_margin_in_depths * m.depth, 3) + " m beyond the path");
      }
  }
} // namespace abrade::coupling
