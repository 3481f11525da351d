// A layer that moves with a wall and holds the particles in contact with it: their count and
// how fast they slide along it (layer_probe.h).
#include <abrade/common/closest_point.h>
#include <abrade/dem/layer_probe.h>
#include <abrade/dem/simulation.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace abrade::dem
{
  LayerProbe::LayerProbe(const Simulation &sim, std::size_t w, double t, const Vec3 &a, long e)
    : wall(w), thickness(t), axis(a.normalized()), every(std::max(1L, e))
  {
    const TriangleMesh &mesh = sim.wall(w).mesh;
    Vec3                hi;
    mesh.bounding_box(lo, hi);
    lo -= Vec3::Constant(thickness);
    hi += Vec3::Constant(thickness);
    cell = std::max(thickness, 1e-3 * (hi - lo).maxCoeff());
    nx   = long((hi[0] - lo[0]) / cell) + 1, ny = long((hi[1] - lo[1]) / cell) + 1, nz = long((hi[2] - lo[2]) / cell) + 1;
    bins.assign(nx * ny * nz, {});
    for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
      {
        const auto &tri = mesh.triangles[t];
        Vec3        a0 = mesh.vertices[tri[0]], a1 = a0;
        for (int v : tri)
          a0 = a0.cwiseMin(mesh.vertices[v]), a1 = a1.cwiseMax(mesh.vertices[v]);
        a0 -= Vec3::Constant(thickness), a1 += Vec3::Constant(thickness);
        for (long k = long((a0[2] - lo[2]) / cell); k <= std::min(nz - 1, long((a1[2] - lo[2]) / cell)); ++k)
          for (long j = long((a0[1] - lo[1]) / cell); j <= std::min(ny - 1, long((a1[1] - lo[1]) / cell)); ++j)
            for (long i = long((a0[0] - lo[0]) / cell); i <= std::min(nx - 1, long((a1[0] - lo[0]) / cell)); ++i)
              bins[(k * ny + j) * nx + i].push_back(static_cast<int>(t));
      }
  }

  double LayerProbe::distance_to_surface(const Simulation &sim, const Vec3 &p) const
  {
    const long i = long((p[0] - lo[0]) / cell), j = long((p[1] - lo[1]) / cell), k = long((p[2] - lo[2]) / cell);
    if (p[0] < lo[0] || p[1] < lo[1] || p[2] < lo[2] || i >= nx || j >= ny || k >= nz)
      return std::numeric_limits<double>::infinity();
    const TriangleMesh &mesh = sim.wall(wall).mesh;
    double              best = std::numeric_limits<double>::infinity();
    for (int t : bins[(k * ny + j) * nx + i])
      {
        const auto &tri = mesh.triangles[t];
        const auto  cp  = closest_point_on_triangle(p.data(), mesh.vertices[tri[0]].data(),
                                                    mesh.vertices[tri[1]].data(), mesh.vertices[tri[2]].data());
        best = std::min(best, (p - Vec3(cp.p[0], cp.p[1], cp.p[2])).norm());
      }
    return best;
  }

  void LayerProbe::after_step(const Simulation &sim, const ContactLog &log)
  {
    if (sim.step_number() % every != 0)
      return;
    const Wall &w  = sim.wall(wall);
    const Vec3  c0 = w.motion.centre, c = w.current_centre();
    const auto &P  = sim.particles();
    Vec3        blo = Vec3::Constant(1e300), bhi = Vec3::Constant(-1e300);
    for (std::size_t v = 0; v < w.current.size(); v += 3)
      {
        const Vec3 q(&w.current[v]);
        blo = blo.cwiseMin(q), bhi = bhi.cwiseMax(q);
      }
    blo -= Vec3::Constant(thickness), bhi += Vec3::Constant(thickness);
    long   count = 0;
    double sum   = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      {
        const Vec3 x(P.x[i], P.y[i], P.z[i]);
        if (!(x.array() >= blo.array()).all() || !(x.array() <= bhi.array()).all())
          continue;
        // into the wall's reference frame
        const Vec3 ref = c0 + w.rotation.transpose() * (x - c);
        if (distance_to_surface(sim, ref) <= thickness)
          {
            ++count;
            sum += axis.dot(Vec3(P.vx[i], P.vy[i], P.vz[i]));
          }
      }
    long contacts = 0; // this step's contacts with the wall (a particle on two faces of an edge: two)
    log.for_each([&](const WallContactRecord &r) { contacts += r.wall == int(wall); });
    // every rank sees its own particles: one reduction for all (a count below 2^53 is exact)
    std::vector<double> totals{double(count), sum, double(contacts)};
    sim.parallel().sum(totals);
    count = static_cast<long>(totals[0]);
    sum   = totals[1];
    taken.push_back({sim.time(), current, count, count ? sum / count : 0.0, axis.dot(w.velocity),
                     static_cast<long>(totals[2])});
  }
} // namespace abrade::dem
