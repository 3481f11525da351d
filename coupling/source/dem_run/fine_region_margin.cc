// How far a multi-level bed's fine region reaches beyond the worn walls' paths, against the
// depth they work at (fine_region_margin.h). The knife-bed's beds showed the need: with the fine
// box 0.225 m beside the knife's faces, 0.8 times the 0.285 m its edge works at below the bed's
// surface, the force over the first half of its travel read 9 % below the uniform fine beds'
// (twelve beds each), 4 % at 1.2 times, 0.2 % above at 1.6 times; the wear and the other forces
// held within their scatter (docs/coarse-graining.md). A user sees no such bias in a single run.
#include <abrade/common/format_number.h>
#include <abrade/coupling/dem_run/fine_region_margin.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace abrade::coupling
{
  std::optional<std::pair<dem::Vec3, dem::Vec3>> swept_box(const dem::Wall &wall, const std::vector<Phase> &phases,
                                                           const double below, const int samples_per_phase)
  {
    using Kind = dem::WallMotion::Kind;
    if (wall.motion.kind != Kind::fixed && wall.motion.kind != Kind::prescribed)
      return std::nullopt; // (a free body's or a mechanism's path follows from the loads)
    dem::Wall  w = wall; // moved through the cycle as the simulation moves it, step by step
    dem::Vec3  lo = dem::Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    // the part of the surface below the height: its vertices there and where its triangles'
    // edges cross the height (a tilted face reaches farther at the height than at its vertices)
    const auto extend = [&] {
      const auto at  = [&](int v) { return dem::Vec3(w.current[3 * v], w.current[3 * v + 1], w.current[3 * v + 2]); };
      const auto add = [&](const dem::Vec3 &p) { lo = lo.cwiseMin(p), hi = hi.cwiseMax(p); };
      for (const auto &t : w.mesh.triangles)
        for (int e = 0; e < 3; ++e)
          {
            const dem::Vec3 a = at(t[e]), b = at(t[(e + 1) % 3]);
            if (a.z() < below)
              add(a);
            if ((a.z() < below) != (b.z() < below))
              add(a + (b - a) * ((below - a.z()) / (b.z() - a.z())));
          }
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
    const double none = -std::numeric_limits<double>::max();
    const double cell = 4 * sim.largest_radius(); // (collective: the same on every rank)
    if (!(cell > 0))
      return none;
    const int nx = std::max(1, int(std::ceil((fill.box_max.x() - fill.box_min.x()) / cell)));
    const int ny = std::max(1, int(std::ceil((fill.box_max.y() - fill.box_min.y()) / cell)));
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

  namespace
  {
    /// A worn wall's nearest approach to a face of the fine region that the bulk lies beyond.
    struct Margin
    {
      int    axis   = 0; ///< across which (0: x, 1: y)
      double margin = std::numeric_limits<double>::infinity(); ///< [m] path to face (< 0: beyond it)
      double face   = 0; ///< the face's coordinate [m]
      double side   = 0; ///< -1: the lower face, +1: the upper
    };

    std::string number(double v, int digits = 3) { return io::format_number(v, digits); }

    /// "comes 0.225 m from the fine region's face at y = -0.24 m, 0.79 times the depth ..." (the
    /// log's line and the warning's start alike).
    std::string margin_text(const Margin &m, double depth, const std::string &where)
    {
      return "comes " + number(m.margin) + " m from the fine region's face at " + std::string(1, char('x' + m.axis)) + " = " +
             number(m.face, 4) + " m, " + number(m.margin / depth) + " times the depth of its lowest point below the bed's surface (" +
             number(depth) + " m; " + where + ")";
    }

    /// What a warning advises for a face too near: to move it to @p wanted, or (@p extend) to
    /// extend the fine region to the fill box's face, where a face at the wanted place (as
    /// printed) would leave its shells and a bulk particle less than the room they need beyond
    /// it (dem::split_into_levels refuses that box).
    struct Advice
    {
      bool        extend = false;
      std::string wanted;        ///< the face's place, as printed [m]
      double      room      = 0; ///< what the shells and a bulk particle need beyond it [m]
      double      fill_face = 0; ///< the fill box's face on that side [m]
    };

    /// The advice for margin @p m, @p depth below the surface; @p room: what the shells and a
    /// bulk particle need beyond the fine region's face on that side [m].
    Advice advice(const Margin &m, double depth, const dem::FillRegion &fill, double room)
    {
      const double path      = m.face - m.side * m.margin; // the path's extreme towards that face
      Advice       a;
      a.wanted    = number(path + m.side * fine_region_margin_in_depths * depth, 4);
      a.room      = room;
      a.fill_face = m.side < 0 ? fill.box_min[m.axis] : fill.box_max[m.axis];
      a.extend    = m.side * (std::stod(a.wanted) + m.side * room - a.fill_face) > 0; // (the place printed)
      return a;
    }

    /// The warning for margin @p m of @p wall, @p depth below the surface, with advice @p a.
    std::string margin_warning(const std::string &wall, const Margin &m, double depth, const std::string &where,
                               const Advice &a)
    {
      const std::string across = std::string(1, char('x' + m.axis));
      return "Particles/Coarse graining/Fine region: wall " + wall + "'s path " +
             (m.margin < 0 ? "reaches " + number(-m.margin) + " m beyond the fine region's face at " + across + " = " +
                               number(m.face, 4) + " m (the wall meets coarser particles); its lowest point is " + number(depth) +
                               " m below the bed's surface (" + where + ")"
                           : margin_text(m, depth, where)) +
             ". With 0.8 times it the multi-level knife-bed's force over the first half of the travel read 9 % below "
             "the uniform fine bed's, with 1.2 times 4 %, with 1.6 times 0.2 % above (docs/coarse-graining.md): " +
             (a.extend ? "extend the fine region to the fill box's face at " + across + " = " + number(a.fill_face, 8) +
                           " m (a face at " + a.wanted + " m would leave its shells and a bulk particle less than the " +
                           number(a.room) + " m they need)"
                       : "move the face to " + across + " = " + a.wanted + " m (" + number(fine_region_margin_in_depths, 2) +
                           " times the depth beyond the path; 1.6 times where the force early in the stroke matters)");
    }
  } // namespace

  void check_fine_region_margins(const DemCase &c, const dem::Simulation &sim, io::Log &log)
  {
    const dem::Vec3 &g = c.settings.gravity;
    if (c.finer_levels.empty() || !c.finer_levels.front().fill.centres_in || !(g.z() < 0) ||
        std::hypot(g.x(), g.y()) > 1e-9 * -g.z())
      return; // (the same on every rank)
    const double surface = bed_surface(sim, c.fill); // (collective)
    const auto &[fine_lo, fine_hi]   = *c.finer_levels.front().fill.centres_in;
    const auto &[outer_lo, outer_hi] = *c.finer_levels.back().fill.centres_in; // (the outermost shell's)
    const dem::Vec3 &fill_lo = c.fill.box_min, &fill_hi = c.fill.box_max;
    // coarser particles lie beyond a face of the fine box at v unless it is on the fill box's face
    const auto       bulk_beyond = [&](int d, double v, double fill_face) { return std::abs(v - fill_face) > 1e-9 * (fill_hi[d] - fill_lo[d]); };
    const std::string where  = "z = " + number(surface, 4) + " m, the median of the bed's columns' highest tops";
    bool              any    = false;
    std::array<bool, 6> extended{}; // the faces (x-, x+, y-, y+, z-, z+) a warning advises to extend
    for (std::size_t k = 0; k < c.walls.size() && k < sim.n_walls(); ++k)
      {
        const std::string &name = c.walls[k].wall.name;
        if (c.walls[k].wear.empty())
          continue;
        const auto path = swept_box(sim.wall(k), c.phases, surface);
        if (!path)
          {
            log.line("Fine region: wall " + name + "'s path follows the loads (not prescribed): its margin is not checked");
            continue;
          }
        if (!std::isfinite(path->first.z()))
          continue; // (never in the bed)
        any = true;
        const double depth = surface - path->first.z();
        // each side face with coarser particles beyond it (a face on the fill box's has none:
        // the fine particles reach the container): a warning for each too near, else a line
        // for the nearest
        std::vector<Margin> faces;
        for (int d = 0; d < 2; ++d)
          {
            if (bulk_beyond(d, fine_lo[d], fill_lo[d]))
              faces.push_back({d, path->first[d] - fine_lo[d], fine_lo[d], -1});
            if (bulk_beyond(d, fine_hi[d], fill_hi[d]))
              faces.push_back({d, fine_hi[d] - path->second[d], fine_hi[d], +1});
          }
        Margin nearest;
        bool   warned = false;
        for (const Margin &m : faces)
          {
            // the shells' thickness beyond this face (the outermost level's box against the
            // finest's) and a bulk particle's diameter
            const double shells = m.side < 0 ? fine_lo[m.axis] - outer_lo[m.axis] : outer_hi[m.axis] - fine_hi[m.axis];
            if (m.margin < fine_region_margin_warning * depth)
              {
                const Advice a = advice(m, depth, c.fill, shells + 2 * c.fill.sizes.largest());
                log.warning(margin_warning(name, m, depth, where, a)), warned = true;
                extended[2 * m.axis + (m.side > 0)] = extended[2 * m.axis + (m.side > 0)] || a.extend;
              }
            if (m.margin < nearest.margin)
              nearest = m;
          }
        if (!warned && std::isfinite(nearest.margin))
          log.line("Fine region: wall " + name + "'s path " + margin_text(nearest, depth, where));
        // the floor bounds the finest particles' centres: the next level's reach a diameter of
        // theirs above it
        const double next = c.finer_levels.size() > 1 ? c.finer_levels[1].fill.sizes.largest() : c.fill.sizes.largest();
        if (bulk_beyond(2, fine_lo.z(), fill_lo.z()) && path->first.z() < fine_lo.z() + 2 * next)
          log.warning("Particles/Coarse graining/Fine region: wall " + name + "'s path reaches down to z = " +
                      number(path->first.z(), 4) + " m, within a coarser particle's diameter (" + number(2 * next) +
                      " m) of the fine region's floor (z = " + number(fine_lo.z(), 4) +
                      " m): the wall meets coarser particles there; lower Fine region min's z");
      }
    // every face the warnings would extend, and the others where the shells end now: a box
    // whose shells then reach the fill box's every face leaves the bulk no room (refused)
    if (std::find(extended.begin(), extended.end(), true) != extended.end())
      {
        bool room = false;
        for (int d = 0; d < 3; ++d)
          room = room || (!extended[2 * d] && outer_lo[d] > fill_lo[d]) || (!extended[2 * d + 1] && outer_hi[d] < fill_hi[d]);
        if (!room)
          log.warning("Particles/Coarse graining/Fine region: extended to the fill box's faces as advised, the fine "
                      "region and its shells would fill the fill box, leaving the bulk's particles no room (a case "
                      "refused): fill the whole bed with the fine particles (no Fine region, Particles/Coarse graining/"
                      "Factor the fine one) or widen the fill box (Particles/Generation/Region min and max)");
      }
    if (any && bulk_beyond(2, fine_hi.z(), fill_hi.z()))
      log.warning("Particles/Coarse graining/Fine region: its top (z = " + number(fine_hi.z(), 4) +
                  " m) is below the fill box's (Particles/Generation/Region max, z = " + number(fill_hi.z(), 4) +
                  " m): the coarser particles poured above it settle over the worn walls' paths; raise Fine region max's z "
                  "to the fill box's top");
  }
} // namespace abrade::coupling
