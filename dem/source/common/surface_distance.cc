// Signed distance with the angle-weighted pseudonormal: see surface_distance.h.
#include <abrade/common/closest_point.h>
#include <abrade/common/surface_distance.h>

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
    std::vector<std::array<long, 3>>      searched;      ///< the triangles of positive area (welded ids)
    std::vector<V3>                       face_normal;   ///< unit, per searched triangle
    std::vector<std::array<V3, 3>>        edge_normal;   ///< per searched triangle: of its edges (v0,v1), (v1,v2), (v2,v0)
    std::vector<V3>                       vertex_normal; ///< per vertex (at the welded ids)
    std::vector<std::array<bool, 3>>      edge_on_rim;   ///< per searched triangle: its edges that only it has
    std::vector<bool>                     vertex_on_rim; ///< per vertex: on such an edge
    std::vector<std::array<double, 6>>    box;           ///< per searched triangle: lo, hi

    /// A bounding-volume hierarchy of the searched triangles: nodes with the box of what they
    /// hold, a leaf the triangles order[first, first + count), an inner node its two children
    /// (the first at the next index, the second at @p second).
    struct Node
    {
      double   box[6];
      unsigned first = 0, count = 0, second = 0;
    };
    std::vector<Node>     nodes;
    std::vector<unsigned> order;

    const double *at(long v) const { return x.data() + 3 * v; }

    // the steps of the constructor
    /// The coordinates @p points taken (checked finite, -0 as +0); returns each point's welded
    /// id: points with identical coordinates are one vertex, so that the edges and vertices
    /// triangles share are known by these ids.
    std::vector<long> weld(const std::vector<double> &points);
    /// The @p triangles of positive area (as welded ids, @p welded), with their unit normals,
    /// the angle-weighted pseudonormals of their edges and vertices, and the rim (edges of one
    /// triangle only).
    void take_triangles(const std::vector<std::array<long, 3>> &triangles, const std::vector<long> &welded);
    /// The hierarchy: each node's triangles split at the median of their centres along the
    /// longest side of the centres' box, down to leaves of at most four (a depth of about
    /// log2(n / 4), far below the query's stack of 128).
    void build_hierarchy();
    /// The node of triangles order[first, first + count) and, below it, its children.
    void build_node(unsigned first, unsigned count, const std::vector<std::array<double, 3>> &centre);

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

    /// The searched triangle closest to @p q and its closest point: the hierarchy walked
    /// nearer child first, a node or a triangle whose box lies farther than the closest one
    /// found passed over (exact: none that could be closer is left out). Of equally close
    /// triangles the first found is taken: where they share the edge or vertex closest to q
    /// they give the same feature, pseudonormal and distance, and their closest points differ
    /// by round-off; on a surface's medial axis (q as far from two faces) either is right.
    std::pair<unsigned, ClosestPoint> closest_triangle(const double q[3]) const
    {
      double       best  = std::numeric_limits<double>::infinity();
      unsigned     found = 0;
      ClosestPoint at_best{};
      unsigned     stack[128];
      int          top = 0;
      stack[top++]     = 0;
      while (top > 0)
        {
          const Node &node = nodes[stack[--top]];
          if (!(box_distance2(q, node.box) < best))
            continue;
          if (node.count > 0)
            {
              for (unsigned e = node.first; e < node.first + node.count; ++e)
                {
                  const unsigned t = order[e];
                  if (!(box_distance2(q, box[t].data()) < best))
                    continue;
                  const auto        &v = searched[t];
                  const ClosestPoint p = closest_point_on_triangle(q, at(v[0]), at(v[1]), at(v[2]));
                  const double d2 = (q[0] - p.p[0]) * (q[0] - p.p[0]) + (q[1] - p.p[1]) * (q[1] - p.p[1]) +
                                    (q[2] - p.p[2]) * (q[2] - p.p[2]);
                  if (d2 < best)
                    best = d2, found = t, at_best = p;
                }
              continue;
            }
          const unsigned near_child = unsigned(&node - nodes.data()) + 1, far_child = node.second;
          const bool     swap = box_distance2(q, nodes[far_child].box) < box_distance2(q, nodes[near_child].box);
          stack[top++]        = swap ? near_child : far_child; // (the nearer one on top: walked first)
          stack[top++]        = swap ? far_child : near_child;
        }
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
    impl->n_given = triangles.size();
    impl->take_triangles(triangles, impl->weld(points));
    impl->build_hierarchy();
  }

  std::vector<long> SurfaceDistance::Impl::weld(const std::vector<double> &points)
  {
    if (points.size() % 3 != 0)
      throw std::invalid_argument("SurfaceDistance: " + std::to_string(points.size()) +
                                  " coordinates are not x,y,z triples");
    const long n_points = long(points.size() / 3);
    x                   = points;
    for (double &c : x)
      {
        if (!std::isfinite(c))
          throw std::invalid_argument("SurfaceDistance: a non-finite coordinate");
        c += 0.0; // -0 is +0, for the welding below
      }
    std::vector<long>  welded(n_points);
    std::map<V3, long> first;
    for (long v = 0; v < n_points; ++v)
      welded[v] = first.emplace(V3{x[3 * v], x[3 * v + 1], x[3 * v + 2]}, v).first->second;
    return welded;
  }

  void SurfaceDistance::Impl::take_triangles(const std::vector<std::array<long, 3>> &triangles,
                                             const std::vector<long>               &welded)
  {
    const long                           n_points = long(welded.size());
    std::map<std::pair<long, long>, V3>  edges; // sum of the unit normals of the faces on each edge
    std::map<std::pair<long, long>, int> faces_on_edge;
    vertex_normal.assign(n_points, V3{0, 0, 0});
    for (const auto &given : triangles)
      {
        std::array<long, 3> t;
        for (int k = 0; k < 3; ++k)
          {
            if (given[k] < 0 || given[k] >= n_points)
              throw std::invalid_argument("SurfaceDistance: vertex index " + std::to_string(given[k]) +
                                          " out of range (" + std::to_string(n_points) + " points)");
            t[k] = welded[given[k]];
          }
        const V3     ab = sub(at(t[1]), at(t[0])), bc = sub(at(t[2]), at(t[1])), ca = sub(at(t[0]), at(t[2]));
        const V3     n  = cross(ab, sub(at(t[2]), at(t[0])));
        const double twice_area = std::sqrt(dot(n, n));
        const double longest2   = std::max({dot(ab, ab), dot(bc, bc), dot(ca, ca)});
        if (!(twice_area > degenerate * longest2))
          continue;
        const V3 unit = {n[0] / twice_area, n[1] / twice_area, n[2] / twice_area};
        searched.push_back(t);
        face_normal.push_back(unit);
        for (int k = 0; k < 3; ++k)
          {
            const long a = t[k], b = t[(k + 1) % 3];
            add(edges[{std::min(a, b), std::max(a, b)}], unit, 1);
            ++faces_on_edge[{std::min(a, b), std::max(a, b)}];
            // the face's angle at corner k, between its two edges there
            const V3 u = sub(at(t[(k + 1) % 3]), at(t[k])), w = sub(at(t[(k + 2) % 3]), at(t[k]));
            const V3 uw = cross(u, w);
            add(vertex_normal[t[k]], unit, std::atan2(std::sqrt(dot(uw, uw)), dot(u, w)));
          }
      }
    if (searched.empty())
      throw std::invalid_argument("SurfaceDistance: no triangle of positive area among " +
                                  std::to_string(triangles.size()));
    edge_normal.resize(searched.size());
    edge_on_rim.resize(searched.size());
    vertex_on_rim.assign(n_points, false);
    for (std::size_t i = 0; i < searched.size(); ++i)
      for (int k = 0; k < 3; ++k)
        {
          const long a = searched[i][k], b = searched[i][(k + 1) % 3];
          edge_normal[i][k] = edges.at({std::min(a, b), std::max(a, b)});
          edge_on_rim[i][k] = faces_on_edge.at({std::min(a, b), std::max(a, b)}) == 1;
          if (edge_on_rim[i][k])
            vertex_on_rim[a] = vertex_on_rim[b] = true;
        }
  }

  void SurfaceDistance::Impl::build_hierarchy()
  {
    box.resize(searched.size());
    std::vector<std::array<double, 3>> centre(searched.size());
    for (std::size_t i = 0; i < searched.size(); ++i)
      {
        const auto &t = searched[i];
        auto       &b = box[i];
        for (int d = 0; d < 3; ++d)
          {
            b[d]         = std::min({at(t[0])[d], at(t[1])[d], at(t[2])[d]});
            b[d + 3]     = std::max({at(t[0])[d], at(t[1])[d], at(t[2])[d]});
            centre[i][d] = 0.5 * (b[d] + b[d + 3]);
          }
      }
    order.resize(searched.size());
    for (unsigned i = 0; i < order.size(); ++i)
      order[i] = i;
    nodes.reserve(2 * searched.size());
    build_node(0, unsigned(searched.size()), centre);
  }

  void SurfaceDistance::Impl::build_node(unsigned first, unsigned count, const std::vector<std::array<double, 3>> &centre)
  {
    const unsigned index = unsigned(nodes.size());
    nodes.emplace_back();
    double lo[3], hi[3], clo[3], chi[3];
    for (int d = 0; d < 3; ++d)
      lo[d] = clo[d] = std::numeric_limits<double>::infinity(), hi[d] = chi[d] = -lo[d];
    for (unsigned e = first; e < first + count; ++e)
      for (int d = 0; d < 3; ++d)
        {
          const unsigned t = order[e];
          lo[d] = std::min(lo[d], box[t][d]), hi[d] = std::max(hi[d], box[t][d + 3]);
          clo[d] = std::min(clo[d], centre[t][d]), chi[d] = std::max(chi[d], centre[t][d]);
        }
    for (int d = 0; d < 3; ++d)
      nodes[index].box[d] = lo[d], nodes[index].box[d + 3] = hi[d];
    if (count <= 4)
      {
        nodes[index].first = first, nodes[index].count = count;
        return;
      }
    const int axis = chi[0] - clo[0] >= chi[1] - clo[1] && chi[0] - clo[0] >= chi[2] - clo[2] ? 0
                     : chi[1] - clo[1] >= chi[2] - clo[2]                                     ? 1
                                                                                               : 2;
    const unsigned half = count / 2;
    std::nth_element(order.begin() + first, order.begin() + first + half, order.begin() + first + count,
                     [&](unsigned a, unsigned b) {
                       return centre[a][axis] < centre[b][axis] || (centre[a][axis] == centre[b][axis] && a < b);
                     });
    build_node(first, half, centre);
    nodes[index].second = unsigned(nodes.size());
    build_node(first + half, count - half, centre);
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
