// Edge flips and in-plane smoothing on the flat pieces of a surface (surface_tidy.h).
#include <abrade/fem/surface_tidy.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace abrade::fem
{
  namespace
  {
    using Vec = std::array<double, 3>;

    Vec point(const io::PolyData &s, long v) { return {s.points[3 * v], s.points[3 * v + 1], s.points[3 * v + 2]}; }
    Vec sub(const Vec &a, const Vec &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    Vec cross(const Vec &a, const Vec &b)
    {
      return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    double dot(const Vec &a, const Vec &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    double norm(const Vec &a) { return std::sqrt(dot(a, a)); }

    /// Twice the area times the unit normal.
    Vec normal(const Vec &a, const Vec &b, const Vec &c) { return cross(sub(b, a), sub(c, a)); }

    /// The smallest angle of a triangle [radian] (0 for a degenerate one).
    double smallest_angle(const Vec &a, const Vec &b, const Vec &c)
    {
      auto at = [](const Vec &o, const Vec &p, const Vec &q) {
        const Vec    u = sub(p, o), w = sub(q, o);
        const double n = norm(u) * norm(w);
        return n > 0 ? std::acos(std::clamp(dot(u, w) / n, -1.0, 1.0)) : 0.0;
      };
      return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
    }

    double smallest_angle(const io::PolyData &s, const std::array<long, 3> &t)
    {
      return smallest_angle(point(s, t[0]), point(s, t[1]), point(s, t[2]));
    }

    bool coplanar(const Vec &m, const Vec &n, double cos_flat)
    {
      const double mn = norm(m) * norm(n);
      return mn > 0 && dot(m, n) >= cos_flat * mn;
    }

    double smallest_angle_of(const io::PolyData &s)
    {
      double least = M_PI;
      for (const auto &t : s.triangles)
        least = std::min(least, smallest_angle(s, t));
      return least * 180 / M_PI;
    }

    /// One pass of edge flips; returns how many.
    std::size_t flip_pass(io::PolyData &s, double cos_flat, double max_move)
    {
      // the flipped pair may bend as much as the pair did, or as a flat one may
      auto cos_flat_or = [&](const Vec &n1, const Vec &n2) {
        const double n = norm(n1) * norm(n2);
        return std::min(cos_flat, n > 0 ? dot(n1, n2) / n : 1.0);
      };
      std::map<std::pair<long, long>, std::vector<std::size_t>> edges;
      for (std::size_t k = 0; k < s.triangles.size(); ++k)
        for (int e = 0; e < 3; ++e)
          {
            const long a = s.triangles[k][e], b = s.triangles[k][(e + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back(k);
          }
      std::vector<bool> touched(s.triangles.size(), false);
      std::size_t       flips = 0;
      for (const auto &[edge, pair] : edges)
        {
          if (pair.size() != 2 || touched[pair[0]] || touched[pair[1]])
            continue;
          auto &t1 = s.triangles[pair[0]], &t2 = s.triangles[pair[1]];
          // t1 = (a, b, c) with the edge a -> b; t2 has it b -> a, its third corner d
          int e1 = 0;
          while (!((t1[e1] == edge.first && t1[(e1 + 1) % 3] == edge.second) ||
                   (t1[e1] == edge.second && t1[(e1 + 1) % 3] == edge.first)))
            ++e1;
          const long a = t1[e1], b = t1[(e1 + 1) % 3], c = t1[(e1 + 2) % 3];
          long       d = -1;
          for (const long v : t2)
            if (v != a && v != b)
              d = v;
          if (d < 0 || d == c || edges.count({std::min(c, d), std::max(c, d)}))
            continue; // the new edge would be there twice
          const Vec pa = point(s, a), pb = point(s, b), pc = point(s, c), pd = point(s, d);
          const Vec n1 = normal(pa, pb, pc), n2 = normal(pb, pa, pd);
          // the flip moves the surface through the tetrahedron (a, b, c, d): by its volume over
          // the pair's area on average, nothing where the pair is flat, a hair where it is a
          // needle lying across an edge
          const double volume = std::abs(dot(sub(pb, pa), cross(sub(pc, pa), sub(pd, pa)))) / 6;
          const double area   = 0.5 * (norm(n1) + norm(n2));
          if (!(area > 0) || 3 * volume / area > max_move)
            continue;
          // the flipped pair (c, a, d) and (d, b, c): both must face the way the pair did
          const Vec m1 = normal(pc, pa, pd), m2 = normal(pd, pb, pc), mean = {n1[0] + n2[0], n1[1] + n2[1], n1[2] + n2[2]};
          if (!coplanar(m1, mean, 0.0) || !coplanar(m2, mean, 0.0) || !coplanar(m1, m2, cos_flat_or(n1, n2)))
            continue;
          const double before = std::min(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
          const double after  = std::min(smallest_angle(pc, pa, pd), smallest_angle(pd, pb, pc));
          if (after <= before * (1 + 1e-9))
            continue;
          t1 = {c, a, d};
          t2 = {d, b, c};
          touched[pair[0]] = touched[pair[1]] = true;
          ++flips;
        }
      return flips;
    }

    /// One pass of in-plane moves of vertices with a flat star; returns how many.
    std::size_t smooth_pass(io::PolyData &s, double cos_flat)
    {
      const std::size_t                     n = s.points.size() / 3;
      std::vector<std::vector<std::size_t>> star(n);
      for (std::size_t k = 0; k < s.triangles.size(); ++k)
        for (const long v : s.triangles[k])
          star[v].push_back(k);
      std::size_t moves = 0;
      for (std::size_t v = 0; v < n; ++v)
        {
          if (star[v].size() < 3)
            continue;
          // flat star: every triangle within the angle of the first; the plane's normal
          const auto &t0 = s.triangles[star[v][0]];
          const Vec   n0 = normal(point(s, t0[0]), point(s, t0[1]), point(s, t0[2]));
          bool        flat = norm(n0) > 0;
          std::set<long> ring;
          for (const std::size_t k : star[v])
            {
              const auto &t = s.triangles[k];
              flat          = flat && coplanar(normal(point(s, t[0]), point(s, t[1]), point(s, t[2])), n0, cos_flat);
              for (const long w : t)
                if (w != long(v))
                  ring.insert(w);
            }
          // a vertex on the rim of a flat piece is a corner of its outline: it stays
          if (!flat || ring.size() != star[v].size())
            continue;
          const Vec p = point(s, long(v));
          Vec       mean{0, 0, 0};
          for (const long w : ring)
            for (int c = 0; c < 3; ++c)
              mean[c] += s.points[3 * w + c] / double(ring.size());
          // into the vertex's plane (the neighbours lie in it within the flatness)
          const Vec    unit = {n0[0] / norm(n0), n0[1] / norm(n0), n0[2] / norm(n0)};
          const double off  = dot(sub(mean, p), unit);
          const Vec    q    = {mean[0] - off * unit[0], mean[1] - off * unit[1], mean[2] - off * unit[2]};
          double       before = M_PI, after = M_PI;
          bool         keeps  = true;
          for (const std::size_t k : star[v])
            {
              std::array<Vec, 3> corner = {point(s, s.triangles[k][0]), point(s, s.triangles[k][1]),
                                           point(s, s.triangles[k][2])};
              before = std::min(before, smallest_angle(corner[0], corner[1], corner[2]));
              for (int c = 0; c < 3; ++c)
                if (s.triangles[k][c] == long(v))
                  corner[c] = q;
              after = std::min(after, smallest_angle(corner[0], corner[1], corner[2]));
              keeps = keeps && coplanar(normal(corner[0], corner[1], corner[2]), n0, cos_flat);
            }
          if (!keeps || after <= before * (1 + 1e-9))
            continue;
          for (int c = 0; c < 3; ++c)
            s.points[3 * v + c] = q[c];
          ++moves;
        }
      return moves;
    }
  } // namespace

  TidyReport tidy_flat_regions(io::PolyData &s, double flat_degrees, double max_move)
  {
    TidyReport r;
    r.smallest_angle_before = smallest_angle_of(s);
    const double cos_flat   = std::cos(flat_degrees * M_PI / 180);
    for (int pass = 0; pass < 10; ++pass)
      {
        const std::size_t flips = flip_pass(s, cos_flat, max_move);
        const std::size_t moves = smooth_pass(s, cos_flat);
        r.flips += flips, r.moves += moves;
        if (flips + moves == 0)
          break;
      }
    r.smallest_angle_after = smallest_angle_of(s);
    return r;
  }
} // namespace abrade::fem
