// Signed distance with the angle-weighted pseudonormal: see surface_distance.h.
#include <abrade/common/closest_point.h>
#include <abrade/common/surface_distance.h>

#include <vtkCellArray.h>
#include <vtkGenericCell.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>

#include <algorithm>
#include <cmath>
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
    std::vector<std::array<long, 3>>      searched;      ///< the triangles of positive area (welded ids), cell i of the locator
    std::vector<V3>                       face_normal;   ///< unit, per searched triangle
    std::vector<std::array<V3, 3>>        edge_normal;   ///< per searched triangle: of its edges (v0,v1), (v1,v2), (v2,v0)
    std::vector<V3>                       vertex_normal; ///< per vertex (at the welded ids)
    std::vector<std::array<bool, 3>>      edge_on_rim;   ///< per searched triangle: its edges that only it has
    std::vector<bool>                     vertex_on_rim; ///< per vertex: on such an edge
    vtkSmartPointer<vtkPolyData>          surface;
    vtkSmartPointer<vtkStaticCellLocator> locator;

    const double *at(long v) const { return x.data() + 3 * v; }

    /// The angle-weighted pseudonormal of a feature of searched triangle @p t.
    const V3 &pseudonormal(vtkIdType t, Feature f) const
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
    bool on_rim(vtkIdType t, Feature f) const
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

    double signed_distance(const double q[3], vtkGenericCell *cell, double *closest = nullptr, bool *rim = nullptr) const
    {
      if (!std::isfinite(q[0]) || !std::isfinite(q[1]) || !std::isfinite(q[2]))
        return std::numeric_limits<double>::quiet_NaN();
      double    vtk_point[3], dist2 = 0;
      vtkIdType id    = -1;
      int       subid = 0;
      locator->FindClosestPoint(q, vtk_point, cell, id, subid, dist2);
      if (id < 0 || id >= vtkIdType(searched.size()))
        throw std::logic_error("SurfaceDistance: the cell locator found no triangle");
      // the closest point and its feature on that triangle; the distance from it, not from
      // VTK's, so that distance and sign come from the same point
      const auto        &t = searched[id];
      const ClosestPoint c = closest_point_on_triangle(q, at(t[0]), at(t[1]), at(t[2]));
      if (closest)
        closest[0] = c.p[0], closest[1] = c.p[1], closest[2] = c.p[2];
      if (rim)
        *rim = on_rim(id, c.feature);
      const V3           d = sub(q, c.p);
      const double       r = std::sqrt(dot(d, d));
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

    // the locator on a vtkPolyData of the searched triangles (cell i is searched[i]), in double
    vtkNew<vtkPoints> vtk_points;
    vtk_points->SetDataTypeToDouble();
    vtk_points->SetNumberOfPoints(n_points);
    for (long v = 0; v < n_points; ++v)
      vtk_points->SetPoint(v, m.at(v));
    vtkNew<vtkCellArray> cells;
    for (const auto &t : m.searched)
      {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, ids);
      }
    m.surface = vtkSmartPointer<vtkPolyData>::New();
    m.surface->SetPoints(vtk_points);
    m.surface->SetPolys(cells);
    m.surface->BuildCells(); // now, not lazily in a query (which may run on several threads)
    m.locator = vtkSmartPointer<vtkStaticCellLocator>::New();
    m.locator->SetDataSet(m.surface);
    m.locator->BuildLocator();
  }

  SurfaceDistance::~SurfaceDistance()                                     = default;
  SurfaceDistance::SurfaceDistance(SurfaceDistance &&) noexcept            = default;
  SurfaceDistance &SurfaceDistance::operator=(SurfaceDistance &&) noexcept = default;

  double SurfaceDistance::signed_distance(const double q[3], bool &on_rim, double closest[3]) const
  {
    thread_local const vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
    return impl->signed_distance(q, cell, closest, &on_rim);
  }

  double SurfaceDistance::signed_distance(const double q[3]) const
  {
    // VTK fills a scratch cell in a query: one per thread, so that concurrent calls share
    // nothing they write (and a call does not pay for making one: half its time)
    thread_local const vtkSmartPointer<vtkGenericCell> cell = vtkSmartPointer<vtkGenericCell>::New();
    return impl->signed_distance(q, cell);
  }

  std::size_t SurfaceDistance::n_triangles() const { return impl->n_given; }

  std::vector<double> wear_depth(const SurfaceDistance &design, const std::vector<double> &points,
                                 std::vector<double> *feet)
  {
    if (points.size() % 3 != 0)
      throw std::invalid_argument("wear_depth: " + std::to_string(points.size()) + " coordinates are not x,y,z triples");
    std::vector<double>    depth(points.size() / 3);
    if (feet)
      feet->assign(points.size(), std::numeric_limits<double>::quiet_NaN());
    vtkNew<vtkGenericCell> cell;
    for (std::size_t i = 0; i < depth.size(); ++i)
      depth[i] = -design.impl->signed_distance(points.data() + 3 * i, cell, feet ? feet->data() + 3 * i : nullptr);
    return depth;
  }
} // namespace abrade::geometry
