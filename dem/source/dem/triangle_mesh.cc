// Triangle surfaces with welded vertices: normals, areas, volume, welding and refinement
// (triangle_mesh.h).
#include <abrade/dem/triangle_mesh.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

namespace abrade::dem
{
  Vec3 TriangleMesh::normal(std::size_t t) const
  {
    const auto &tri = triangles[t];
    const Vec3  n   = (vertices[tri[1]] - vertices[tri[0]]).cross(vertices[tri[2]] - vertices[tri[0]]);
    return n.normalized();
  }

  double TriangleMesh::area(std::size_t t) const
  {
    const auto &tri = triangles[t];
    return 0.5 * (vertices[tri[1]] - vertices[tri[0]]).cross(vertices[tri[2]] - vertices[tri[0]]).norm();
  }

  double TriangleMesh::total_area() const
  {
    double a = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      a += area(t);
    return a;
  }

  double TriangleMesh::volume() const
  {
    double v = 0;
    for (const auto &t : triangles)
      v += vertices[t[0]].dot(vertices[t[1]].cross(vertices[t[2]])) / 6;
    return v;
  }

  void TriangleMesh::bounding_box(Vec3 &lo, Vec3 &hi) const
  {
    lo = Vec3::Constant(1e300);
    hi = Vec3::Constant(-1e300);
    for (const auto &v : vertices)
      {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
      }
  }

  bool TriangleMesh::is_closed() const
  {
    std::map<std::pair<int, int>, int> count;
    for (const auto &t : triangles)
      for (int e = 0; e < 3; ++e)
        ++count[std::minmax(t[e], t[(e + 1) % 3])];
    return !count.empty() &&
           std::all_of(count.begin(), count.end(), [](const auto &kv) { return kv.second == 2; });
  }

  std::size_t TriangleMesh::weld(double tol)
  {
    // Hash vertices into a grid of cell size tol; compare against the 27 neighbouring cells.
    struct Key
    {
      long i, j, k;
      bool operator<(const Key &o) const { return std::tie(i, j, k) < std::tie(o.i, o.j, o.k); }
    };
    std::map<Key, std::vector<int>> grid;
    std::vector<int>                remap(vertices.size());
    std::vector<Vec3>               kept;
    auto key = [tol](const Vec3 &p) {
      return Key{std::lround(std::floor(p[0] / tol)), std::lround(std::floor(p[1] / tol)),
                 std::lround(std::floor(p[2] / tol))};
    };
    for (std::size_t v = 0; v < vertices.size(); ++v)
      {
        const Key k     = key(vertices[v]);
        int       found = -1;
        for (long a = -1; a <= 1 && found < 0; ++a)
          for (long b = -1; b <= 1 && found < 0; ++b)
            for (long c = -1; c <= 1 && found < 0; ++c)
              {
                auto it = grid.find(Key{k.i + a, k.j + b, k.k + c});
                if (it != grid.end())
                  for (int w : it->second)
                    if ((kept[w] - vertices[v]).norm() <= tol)
                      {
                        found = w;
                        break;
                      }
              }
        if (found < 0)
          {
            found = static_cast<int>(kept.size());
            kept.push_back(vertices[v]);
            grid[k].push_back(found);
          }
        remap[v] = found;
      }
    const std::size_t removed = vertices.size() - kept.size();
    vertices.swap(kept);
    std::vector<std::array<int, 3>> tris;
    for (auto t : triangles)
      {
        for (auto &i : t)
          i = remap[i];
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
          tris.push_back(t);
      }
    triangles.swap(tris);
    return removed;
  }

  void TriangleMesh::refine(double max_edge)
  {
    const double h2 = max_edge * max_edge;
    for (int pass = 0; pass < 40; ++pass)
      {
        // Mark every edge longer than max_edge and create its midpoint once.
        std::map<std::pair<int, int>, int> midpoint;
        auto edge_key = [](int a, int b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
        for (const auto &t : triangles)
          for (int e = 0; e < 3; ++e)
            {
              const int a = t[e], b = t[(e + 1) % 3];
              if ((vertices[a] - vertices[b]).squaredNorm() > h2 && !midpoint.count(edge_key(a, b)))
                {
                  midpoint[edge_key(a, b)] = static_cast<int>(vertices.size());
                  vertices.push_back(0.5 * (vertices[a] + vertices[b]));
                }
            }
        if (midpoint.empty())
          return;
        std::vector<std::array<int, 3>> out;
        for (const auto &t : triangles)
          {
            int m[3];
            int n_marked = 0;
            for (int e = 0; e < 3; ++e)
              {
                auto it = midpoint.find(edge_key(t[e], t[(e + 1) % 3]));
                m[e]    = it == midpoint.end() ? -1 : it->second;
                n_marked += m[e] >= 0;
              }
            if (n_marked == 0)
              out.push_back(t);
            else if (n_marked == 3)
              {
                out.push_back({t[0], m[0], m[2]});
                out.push_back({m[0], t[1], m[1]});
                out.push_back({m[2], m[1], t[2]});
                out.push_back({m[0], m[1], m[2]});
              }
            else if (n_marked == 1)
              {
                const int e = m[0] >= 0 ? 0 : m[1] >= 0 ? 1 : 2;
                out.push_back({t[e], m[e], t[(e + 2) % 3]});
                out.push_back({m[e], t[(e + 1) % 3], t[(e + 2) % 3]});
              }
            else
              {
                // two marked edges: the unmarked one is u; cut off the corner opposite to it
                const int u = m[0] < 0 ? 0 : m[1] < 0 ? 1 : 2;
                const int a = t[u], b = t[(u + 1) % 3], c = t[(u + 2) % 3];
                const int mb = m[(u + 1) % 3], mc = m[(u + 2) % 3]; // on b-c and c-a
                out.push_back({mb, c, mc});
                // split quad a, b, mb, mc along its shorter diagonal
                if ((vertices[a] - vertices[mb]).squaredNorm() < (vertices[b] - vertices[mc]).squaredNorm())
                  {
                    out.push_back({a, b, mb});
                    out.push_back({a, mb, mc});
                  }
                else
                  {
                    out.push_back({a, b, mc});
                    out.push_back({b, mb, mc});
                  }
              }
          }
        triangles.swap(out);
      }
  }

  void TriangleMesh::translate(const Vec3 &d)
  {
    for (auto &v : vertices)
      v += d;
  }

  void TriangleMesh::append(const TriangleMesh &other)
  {
    const int off = static_cast<int>(vertices.size());
    vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
    for (auto t : other.triangles)
      triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
  }

  void TriangleMesh::flip()
  {
    for (auto &t : triangles)
      std::swap(t[1], t[2]);
  }

  namespace primitives
  {
    namespace
    {
      void add_quad(TriangleMesh &m, const Vec3 &a, const Vec3 &b, const Vec3 &c, const Vec3 &d)
      {
        const int o = static_cast<int>(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {a, b, c, d});
        m.triangles.push_back({o, o + 1, o + 2});
        m.triangles.push_back({o, o + 2, o + 3});
      }
    } // namespace

    TriangleMesh box_container(const Vec3 &lo, const Vec3 &hi, bool with_top)
    {
      TriangleMesh m;
      auto P = [&](int i, int j, int k) {
        return Vec3(i ? hi[0] : lo[0], j ? hi[1] : lo[1], k ? hi[2] : lo[2]);
      };
      // normals point into the box
      add_quad(m, P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 1, 0)); // floor (+z)
      add_quad(m, P(0, 0, 0), P(0, 1, 0), P(0, 1, 1), P(0, 0, 1)); // x = lo (+x)
      add_quad(m, P(1, 0, 0), P(1, 0, 1), P(1, 1, 1), P(1, 1, 0)); // x = hi (-x)
      add_quad(m, P(0, 0, 0), P(0, 0, 1), P(1, 0, 1), P(1, 0, 0)); // y = lo (+y)
      add_quad(m, P(0, 1, 0), P(1, 1, 0), P(1, 1, 1), P(0, 1, 1)); // y = hi (-y)
      if (with_top)
        add_quad(m, P(0, 0, 1), P(0, 1, 1), P(1, 1, 1), P(1, 0, 1));
      m.weld(1e-9 * (hi - lo).norm());
      return m;
    }

    TriangleMesh plate(const Vec3 &c, int axis, double a, double b, double max_edge, bool flip)
    {
      const int ia = (axis + 1) % 3, ib = (axis + 2) % 3;
      Vec3      ea = Vec3::Zero(), eb = Vec3::Zero();
      ea[ia] = 0.5 * a;
      eb[ib] = 0.5 * b;
      TriangleMesh m;
      add_quad(m, c - ea - eb, c + ea - eb, c + ea + eb, c - ea + eb);
      if (flip)
        m.flip();
      if (max_edge > 0)
        m.refine(max_edge);
      return m;
    }

    TriangleMesh chisel_knife(double L, double H, double T, double B)
    {
      const double h = T / 2;
      const Vec3   e0(-L / 2, 0, 0), e1(L / 2, 0, 0);
      const Vec3   a0(-L / 2, -h, B), a1(L / 2, -h, B), a2(L / 2, -h, H), a3(-L / 2, -h, H);
      const Vec3   b0(-L / 2, h, B), b1(L / 2, h, B), b2(L / 2, h, H), b3(-L / 2, h, H);
      TriangleMesh m;
      auto tri = [&m](const Vec3 &p, const Vec3 &q, const Vec3 &r) {
        const int o = static_cast<int>(m.vertices.size());
        m.vertices.insert(m.vertices.end(), {p, q, r});
        m.triangles.push_back({o, o + 1, o + 2});
      };
      // the triangles of shared/peers/liggghts/make_knife_stl.py, oriented outward below
      tri(a0, a3, a2), tri(a0, a2, a1);             // side -y
      tri(b0, b1, b2), tri(b0, b2, b3);             // side +y
      tri(a3, b3, b2), tri(a3, b2, a2);             // top
      tri(e0, e1, a1), tri(e0, a1, a0);             // bevel -y
      tri(e0, b0, b1), tri(e0, b1, e1);             // bevel +y
      tri(e0, a0, a3), tri(e0, a3, b3), tri(e0, b3, b0); // end -x
      tri(e1, b1, b2), tri(e1, b2, a2), tri(e1, a2, a1); // end +x
      m.weld(1e-9 * L);
      // the knife is convex: orient every triangle away from its centre
      const Vec3 centre(0, 0, (B + H) / 2);
      for (std::size_t t = 0; t < m.n_triangles(); ++t)
        {
          const auto &tri = m.triangles[t];
          const Vec3  c   = (m.vertices[tri[0]] + m.vertices[tri[1]] + m.vertices[tri[2]]) / 3;
          if (m.normal(t).dot(c - centre) < 0)
            std::swap(m.triangles[t][1], m.triangles[t][2]);
        }
      return m;
    }

    TriangleMesh clamshell_shell(double R, double W, double sector, double opening, int side, double max_edge)
    {
      // a point at angle a from straight down (towards side x), at y
      auto at = [&](double a, double y) { return Vec3(side * R * std::sin(a), y, -R * std::cos(a)); };
      const int    n_arc = std::max(2, int(std::ceil(R * sector / max_edge)));
      const int    n_w   = std::max(1, int(std::ceil(W / max_edge)));
      TriangleMesh m;
      for (int i = 0; i <= n_arc; ++i) // the bottom: (n_arc + 1) x (n_w + 1) grid
        for (int j = 0; j <= n_w; ++j)
          m.vertices.push_back(at(opening + sector * i / n_arc, -W / 2 + W * j / n_w));
      auto id = [&](int i, int j) { return i * (n_w + 1) + j; };
      for (int i = 0; i < n_arc; ++i)
        for (int j = 0; j < n_w; ++j)
          {
            m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
            m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
          }
      for (const double y : {-W / 2, W / 2}) // side plates: fans from the hinge
        {
          const int hub = int(m.vertices.size());
          m.vertices.emplace_back(0, y, 0);
          const int j = y < 0 ? 0 : n_w;
          for (int i = 0; i < n_arc; ++i)
            m.triangles.push_back({hub, id(i, j), id(i + 1, j)});
        }
      m.weld(1e-9 * R);
      m.refine(max_edge); // the side fans' long edges
      return m;
    }
  } // namespace primitives
} // namespace abrade::dem
