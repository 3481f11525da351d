// Signed distance with the angle-weighted pseudonormal: see surface_distance.h.
#include <abrade/common/closest_point.h>
#include <abrade/common/surface_distance.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace abrade::geometry
{
  namespace
  {
    using V3 = std::array<double, 3>;

    V3 sub(const double *u, const double *v) { return {u[0] - v[0], u[1] - v[1], u[2] - v[2]}; }
    double dot(const V3 &u, const V3 &v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }
    V3 cross(const V3 &u, const V3 &v)
    {
      return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    }
    void add(V3 &sum, const V3 &v, double weight)
    {
      for (int d = 0; d < 3; ++d)
        sum[d] += weight * v[d];
    }

    /// Twice the area at most this times the longest edge squared: degenerate.
    constexpr double degenerate = 1e-10;
  } // namespace

  struct SurfaceDistance::Impl
  {
    std::size_t                           n_given = 0;
    std::vector<double>                   x;             ///< coordinates, as given
    std::vector<std::array<long, 3>>      searched;      ///< the triangles of positive area (welded ids)
    std::vector<V3>                       face_normal;   ///< unit, per searched triangle
    std::vector<std::array<V3, 3>>        edge_normal;   ///< per searched triangle: of its edges (v0,v1), (v1,v2), (v2,v0)
    std::vector<V3>                       vertex_normal; ///< per vertex (at the welded ids)
    std::vector<std::array<bool, 3>>      edge_on_rim;   ///< per searched triangle: its edges that only it has
    std::vector<bool>                     vertex_on_rim; ///< per vertex: on such an edge
    std::vector<std::array<double, 6>>    box;           ///< per searched triangle: lo, hi

    /// The searched triangles in a uniform grid of cubic cells (edge @p cell, from @p lo, @p n
    /// cells along each axis): each listed in every cell its box overlaps (from_cell: offsets
    /// into in_cell).
    double                   cell = 1;
    std::array<double, 3>    lo{};
    std::array<long, 3>      n{};
    std::vector<std::size_t> from_cell;
    std::vector<unsigned>    in_cell;

    const double *at(long v) const { return x.data() + 3 * v; }

    /// The angle-weighted pseudonormal of a feature of searched triangle @p t.
    const V3 &pseudonormal(std::size_t t, Feature f) const
    {
      switch (f)
        {
          case face:
            return face_normal[t];
          case edge01:
          case edge12:
          case edge20:
            return edge_normal[t][f - edge01];
          default:
            return vertex_normal[searched[t][f - vertex0]];
        }
    }

    /// Whether a feature of searched triangle @p t lies on the surface's rim (an open surface's
    /// boundary): an edge that only this triangle has, or a vertex on one.
    bool on_rim(std::size_t t, Feature f) const
    {
      switch (f)
        {
          case face:
            return false;
          case edge01:
          case edge12:
          case edge20:
            return edge_on_rim[t][f - edge01];
          default:
            return vertex_on_rim[searched[t][f - vertex0]];
        }
    }

    long cell_index(double c, int axis) const
    {
      return std::clamp(long(std::floor((c - lo[axis]) / cell)), 0L, n[axis] - 1);
    }

    /// The squared distance from @p q to the box @p b (lo, hi).
    static double box_distance2(const double q[3], const double *b)
    {
      double d2 = 0;
      for (int d = 0; d < 3; ++d)
        {
          const double out = q[d] < b[d] ? b[d] - q[d] : q[d] > b[d + 3] ? q[d] - b[d + 3] : 0.0;
          d2 += out * out;
        }
      return d2;
    }

    /// The searched triangle closest to @p q and its closest point: the cells about the one
    /// nearest q in shells (the cell, then its neighbours, ...) until a triangle is found, then
    /// every cell within that triangle's distance of q not yet looked at; a cell or a triangle
    /// whose box lies farther than the closest one found is passed over. Of equally close
    /// triangles (a point closest to an edge or a vertex they share) the first found is taken:
    /// they give the same feature, pseudonormal and distance, their closest points differ by
    /// round-off.
    std::pair<unsigned, ClosestPoint> closest_triangle(const double q[3]) const
    {
      // each thread marks the triangles it has looked at in a query (one may lie in several
      // cells) with the number of the query
      thread_local std::vector<std::uint64_t> seen;
      thread_local std::uint64_t              query = 0;
      if (seen.size() < searched.size())
        seen.resize(searched.size(), 0);
      ++query;
      double       best  = std::numeric_limits<double>::infinity();
      unsigned     found = 0;
      ClosestPoint at_best{};
      auto         look_at = [&](long ii, long jj, long kk) {
        const double cell_box[6] = {lo[0] + ii * cell,       lo[1] + jj * cell,       lo[2] + kk * cell,
                                    lo[0] + (ii + 1) * cell, lo[1] + (jj + 1) * cell, lo[2] + (kk + 1) * cell};
        if (!(box_distance2(q, cell_box) < best))
          return;
        const std::size_t cc = std::size_t((kk * n[1] + jj) * n[0] + ii);
        for (std::size_t e = from_cell[cc]; e < from_cell[cc + 1]; ++e)
          {
            const unsigned t = in_cell[e];
            if (seen[t] == query)
              continue;
            seen[t] = query;
            if (!(box_distance2(q, box[t].data()) < best))
              continue;
            const auto        &v = searched[t];
            const ClosestPoint p = closest_point_on_triangle(q, at(v[0]), at(v[1]), at(v[2]));
            const double d2 = (q[0] - p.p[0]) * (q[0] - p.p[0]) + (q[1] - p.p[1]) * (q[1] - p.p[1]) +
                              (q[2] - p.p[2]) * (q[2] - p.p[2]);
            if (d2 < best)
              best = d2, found = t, at_best = p;
          }
      };
      const long c[3] = {cell_index(q[0], 0), cell_index(q[1], 1), cell_index(q[2], 2)};
      auto       ring = [&](long ii, long jj, long kk) {
        return std::max({std::abs(ii - c[0]), std::abs(jj - c[1]), std::abs(kk - c[2])});
      };
      // shells until one holds a triangle (the cell's neighbours at least)
      long k = 0;
      for (const long shells = std::max({n[0], n[1], n[2]}); k < shells; ++k)
        {
          for (long kk = std::max(0L, c[2] - k); kk <= std::min(n[2] - 1, c[2] + k); ++kk)
            for (long jj = std::max(0L, c[1] - k); jj <= std::min(n[1] - 1, c[1] + k); ++jj)
              for (long ii = std::max(0L, c[0] - k); ii <= std::min(n[0] - 1, c[0] + k); ++ii)
                if (ring(ii, jj, kk) == k)
                  look_at(ii, jj, kk);
          if (k >= 1 && best < std::numeric_limits<double>::infinity())
            break;
        }
      // then the cells within the closest distance found, beyond those shells
      if (!(best < std::numeric_limits<double>::infinity())) // (none: there is always one)
        throw std::logic_error("SurfaceDistance: no triangle found");
      const double r = std::sqrt(best);
      for (long kk = cell_index(q[2] - r, 2); kk <= cell_index(q[2] + r, 2); ++kk)
        for (long jj = cell_index(q[1] - r, 1); jj <= cell_index(q[1] + r, 1); ++jj)
          for (long ii = cell_index(q[0] - r, 0); ii <= cell_index(q[0] + r, 0); ++ii)
            if (ring(ii, jj, kk) > k)
              look_at(ii, jj, kk);
      return {found, at_best};
    }

    double signed_distance(const double q[3], double *closest = nullptr, bool *rim = nullptr) const
    {
      if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
        return std::numeric_limits<double>::quiet_NaN();
      const auto [id, c] = closest_triangle(q);
      if (closest)
        closest[0] = c.p[0], closest[1] = c.p[1], closest[2] = c.p[2];
      if (rim)
        *rim = on_rim(id, c.feature);
      const V3     d = sub(q, c.p);
      const double r = std::sqrt(dot(d, d));
      // inside where q - p points against the pseudonormal; on the surface (r = 0) +0
      return dot(d, pseudonormal(id, c.feature)) < 0 ? -r : r;
    }
  };

  SurfaceDistance::SurfaceDistance(const std::vector<double> &points, const std::vector<std::array<long, 3>> &triangles)
    : impl(std::make_unique<Impl>())
  {
    Impl &m   = *impl;
    m.n_given = triangles.size();
    if (points.size() % 3 != 0)
      throw std::invalid_argument("SurfaceDistance: " + std::to_string(points.size()) +
                                  " coordinates are not x,y,z triples");
    const long n_points = long(points.size() / 3);
    m.x                 = points;
    for (double &c : m.x)
      {
        if (!std::isfinite(c))
          throw std::invalid_argument("SurfaceDistance: a non-finite coordinate");
        c += 0.0; // -0 is +0, for the welding below
      }

    // vertices with identical coordinates are one vertex: the edges and vertices that triangles
    // share are known by these ids
    std::vector<long>  weld(n_points);
    std::map<V3, long> first;
    for (long v = 0; v < n_points; ++v)
      weld[v] = first.emplace(V3{m.x[3 * v], m.x[3 * v + 1], m.x[3 * v + 2]}, v).first->second;

    // the triangles of positive area, their unit normals and the pseudonormals
    std::map<std::pair<long, long>, V3>  edges; // sum of the unit normals of the faces on each edge
    std::map<std::pair<long, long>, int> faces_on_edge;
    m.vertex_normal.assign(n_points, V3{0, 0, 0});
    for (const auto &given : triangles)
      {
        std::array<long, 3> t;
        for (int k = 0; k < 3; ++k)
          {
            if (given[k] < 0 || given[k] >= n_points)
              throw std::invalid_argument("SurfaceDistance: vertex index " + std::to_string(given[k]) +
                                          " out of range (" + std::to_string(n_points) + " points)");
            t[k] = weld[given[k]];
          }
        const V3     ab = sub(m.at(t[1]), m.at(t[0])), bc = sub(m.at(t[2]), m.at(t[1])), ca = sub(m.at(t[0]), m.at(t[2]));
        const V3     n  = cross(ab, sub(m.at(t[2]), m.at(t[0])));
        const double twice_area = std::sqrt(dot(n, n));
        const double longest2   = std::max({dot(ab, ab), dot(bc, bc), dot(ca, ca)});
        if (!(twice_area > degenerate * longest2))
          continue;
        const V3 unit = {n[0] / twice_area, n[1] / twice_area, n[2] / twice_area};
        m.searched.push_back(t);
        m.face_normal.push_back(unit);
        for (int k = 0; k < 3; ++k)
          {
            const long a = t[k], b = t[(k + 1) % 3];
            add(edges[{std::min(a, b), std::max(a, b)}], unit, 1);
            ++faces_on_edge[{std::min(a, b), std::max(a, b)}];
            // the face's angle at corner k, between its two edges there
            const V3 u = sub(m.at(t[(k + 1) % 3]), m.at(t[k])), w = sub(m.at(t[(k + 2) % 3]), m.at(t[k]));
            const V3 uw = cross(u, w);
            add(m.vertex_normal[t[k]], unit, std::atan2(std::sqrt(dot(uw, uw)), dot(u, w)));
          }
      }
    if (m.searched.empty())
      throw std::invalid_argument("SurfaceDistance: no triangle of positive area among " +
                                  std::to_string(triangles.size()));
    m.edge_normal.resize(m.searched.size());
    m.edge_on_rim.resize(m.searched.size());
    m.vertex_on_rim.assign(n_points, false);
    for (std::size_t i = 0; i < m.searched.size(); ++i)
      for (int k = 0; k < 3; ++k)
        {
          const long a = m.searched[i][k], b = m.searched[i][(k + 1) % 3];
          m.edge_normal[i][k] = edges.at({std::min(a, b), std::max(a, b)});
          m.edge_on_rim[i][k] = faces_on_edge.at({std::min(a, b), std::max(a, b)}) == 1;
          if (m.edge_on_rim[i][k])
            m.vertex_on_rim[a] = m.vertex_on_rim[b] = true;
        }

    // the grid: cubic cells of about the triangles' mean size (at most 64 cells per triangle
    // and 2^24 in all), each triangle in the cells its box overlaps
    std::array<double, 3> hi{};
    double                size = 0;
    m.lo.fill(std::numeric_limits<double>::infinity());
    hi.fill(-std::numeric_limits<double>::infinity());
    m.box.resize(m.searched.size());
    for (std::size_t i = 0; i < m.searched.size(); ++i)
      {
        const auto &t = m.searched[i];
        auto       &b = m.box[i];
        for (int d = 0; d < 3; ++d)
          {
            b[d]     = std::min({m.at(t[0])[d], m.at(t[1])[d], m.at(t[2])[d]});
            b[d + 3] = std::max({m.at(t[0])[d], m.at(t[1])[d], m.at(t[2])[d]});
            m.lo[d]  = std::min(m.lo[d], b[d]), hi[d] = std::max(hi[d], b[d + 3]);
          }
        size += std::max({b[3] - b[0], b[4] - b[1], b[5] - b[2]});
      }
    const double extent = std::max({hi[0] - m.lo[0], hi[1] - m.lo[1], hi[2] - m.lo[2]});
    m.cell              = std::max(size / double(m.searched.size()), 1e-9 * extent);
    auto cells_along    = [&](int d) { return long(std::floor((hi[d] - m.lo[d]) / m.cell)) + 1; };
    while (double(cells_along(0)) * double(cells_along(1)) * double(cells_along(2)) >
           std::min(64.0 * double(m.searched.size()), double(1 << 24)))
      m.cell *= 1.5;
    for (int d = 0; d < 3; ++d)
      m.n[d] = cells_along(d);
    const std::size_t n_cells   = std::size_t(m.n[0] * m.n[1] * m.n[2]);
    auto              each_cell = [&](const std::array<double, 6> &b, auto &&visit) {
      for (long kk = m.cell_index(b[2], 2); kk <= m.cell_index(b[5], 2); ++kk)
        for (long jj = m.cell_index(b[1], 1); jj <= m.cell_index(b[4], 1); ++jj)
          for (long ii = m.cell_index(b[0], 0); ii <= m.cell_index(b[3], 0); ++ii)
            visit(std::size_t((kk * m.n[1] + jj) * m.n[0] + ii));
    };
    m.from_cell.assign(n_cells + 1, 0);
    for (const auto &b : m.box)
      each_cell(b, [&](std::size_t c) { ++m.from_cell[c + 1]; });
    for (std::size_t c = 0; c < n_cells; ++c)
      m.from_cell[c + 1] += m.from_cell[c];
    m.in_cell.resize(m.from_cell[n_cells]);
    std::vector<std::size_t> fill(m.from_cell.begin(), m.from_cell.end() - 1);
    for (unsigned i = 0; i < m.searched.size(); ++i)
      each_cell(m.box[i], [&](std::size_t c) { m.in_cell[fill[c]++] = i; });
  }

  SurfaceDistance::~SurfaceDistance()                                     = default;
  SurfaceDistance::SurfaceDistance(SurfaceDistance &&) noexcept            = default;
  SurfaceDistance &SurfaceDistance::operator=(SurfaceDistance &&) noexcept = default;

  double SurfaceDistance::signed_distance(const double q[3], bool &on_rim, double closest[3]) const
  {
    return impl->signed_distance(q, closest, &on_rim);
  }

  double SurfaceDistance::signed_distance(const double q[3]) const { return impl->signed_distance(q); }

  std::size_t SurfaceDistance::n_triangles() const { return impl->n_given; }

  std::vector<double> wear_depth(const SurfaceDistance &design, const std::vector<double> &points,
                                 std::vector<double> *feet)
  {
    if (points.size() % 3 != 0)
      throw std::invalid_argument("wear_depth: " + std::to_string(points.size()) + " coordinates are not x,y,z triples");
    std::vector<double>    depth(points.size() / 3);
    if (feet)
      feet->assign(points.size(), std::numeric_limits<double>::quiet_NaN());
    for (std::size_t i = 0; i < depth.size(); ++i)
      depth[i] = -design.impl->signed_distance(points.data() + 3 * i, feet ? feet->data() + 3 * i : nullptr);
    return depth;
  }
} // namespace abrade::geometry
