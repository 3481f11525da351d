// A closed triangle surface's folds, found and mended (triangle_folds.h).
#include <abrade/fem/triangle_folds.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <unordered_map>
#include <utility>

namespace abrade::fem::folds
{
  bool segment_crosses(const double *p, const double *q, const double *a, const double *b, const double *c)
  {
    const double d[3]  = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double h[3]  = {d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2], d[0] * e2[1] - d[1] * e2[0]};
    const double det   = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
    if (std::abs(det) < 1e-300)
      return false; // (parallel: a fold, which the turned triangles find)
    const double s[3] = {p[0] - a[0], p[1] - a[1], p[2] - a[2]};
    const double u    = (s[0] * h[0] + s[1] * h[1] + s[2] * h[2]) / det;
    const double r[3] = {s[1] * e1[2] - s[2] * e1[1], s[2] * e1[0] - s[0] * e1[2], s[0] * e1[1] - s[1] * e1[0]};
    const double v    = (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]) / det;
    const double t    = (e2[0] * r[0] + e2[1] * r[1] + e2[2] * r[2]) / det;
    constexpr double inside = 1e-9;
    return u > inside && v > inside && u + v < 1 - inside && t > inside && t < 1 - inside;
  }

  namespace
  {
    using Box = std::array<double, 6>; ///< lower x, y, z, upper x, y, z

    /// Each triangle's bounding box.
    std::vector<Box> bounding_boxes(const io::PolyData &s)
    {
      std::vector<Box> box(s.triangles.size());
      for (std::size_t k = 0; k < s.triangles.size(); ++k)
        {
          auto &b = box[k];
          for (int c = 0; c < 3; ++c)
            b[c] = std::numeric_limits<double>::infinity(), b[c + 3] = -b[c];
          for (const long v : s.triangles[k])
            for (int c = 0; c < 3; ++c)
              b[c] = std::min(b[c], s.points[3 * v + c]), b[c + 3] = std::max(b[c + 3], s.points[3 * v + c]);
        }
      return box;
    }

    /// Whether triangles @p i and @p j of @p s cross: an edge of one passes through the other.
    /// Neighbours across an edge, and triangles facing the same way (a thin fan of slivers that
    /// overlap each other by round-off, which Gmsh fills), are not a crossing of the part's two
    /// sides.
    bool cross_each_other(const io::PolyData &s, const std::vector<Box> &box, std::size_t i, std::size_t j)
    {
      auto        point = [&](long v) { return &s.points[3 * v]; };
      const auto &ti = s.triangles[i], &tj = s.triangles[j];
      int         shared = 0;
      for (const long v : ti)
        shared += std::count(tj.begin(), tj.end(), v);
      bool apart = false;
      for (int c = 0; c < 3; ++c)
        apart = apart || box[i][c] > box[j][c + 3] || box[j][c] > box[i][c + 3];
      const auto ni = normal_of(point(ti[0]), point(ti[1]), point(ti[2]));
      const auto nj = normal_of(point(tj[0]), point(tj[1]), point(tj[2]));
      if (shared >= 2 || apart || dot(ni, nj) >= 0)
        return false;
      for (int e = 0; e < 3; ++e)
        if (segment_crosses(point(ti[e]), point(ti[(e + 1) % 3]), point(tj[0]), point(tj[1]), point(tj[2])) ||
            segment_crosses(point(tj[e]), point(tj[(e + 1) % 3]), point(ti[0]), point(ti[1]), point(ti[2])))
          return true;
      return false;
    }
  } // namespace

  std::vector<std::size_t> crossing_triangles(const io::PolyData &s)
  {
    if (s.triangles.empty())
      return {};
    const std::vector<Box> box = bounding_boxes(s);
    std::vector<double>    size(box.size());
    for (std::size_t k = 0; k < box.size(); ++k)
      size[k] = std::max({box[k][3] - box[k][0], box[k][4] - box[k][1], box[k][5] - box[k][2]});
    // cells of twice the median triangle's box: a few triangles each, whatever their size
    std::nth_element(size.begin(), size.begin() + size.size() / 2, size.end());
    const double cell = 2 * size[size.size() / 2];
    if (!(cell > 0))
      return {};
    std::unordered_map<long long, std::vector<std::size_t>> grid;
    auto key = [](long i, long j, long k) { return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL); };
    auto cells_of = [&](std::size_t t, auto &&visit) {
      const auto &b = box[t];
      for (long i = long(std::floor(b[0] / cell)); i <= long(std::floor(b[3] / cell)); ++i)
        for (long j = long(std::floor(b[1] / cell)); j <= long(std::floor(b[4] / cell)); ++j)
          for (long k = long(std::floor(b[2] / cell)); k <= long(std::floor(b[5] / cell)); ++k)
            visit(key(i, j, k));
    };
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      cells_of(t, [&](long long c) { grid[c].push_back(t); });
    std::vector<char> crossing(s.triangles.size(), 0);
#pragma omp parallel for schedule(dynamic, 256)
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      {
        std::vector<std::size_t> candidates;
        cells_of(i, [&](long long c) {
          for (const std::size_t j : grid.at(c))
            if (j > i)
              candidates.push_back(j);
        });
        std::sort(candidates.begin(), candidates.end());
        candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
        for (const std::size_t j : candidates)
          if (cross_each_other(s, box, i, j))
            {
#pragma omp atomic write
              crossing[i] = 1;
#pragma omp atomic write
              crossing[j] = 1;
            }
      }
    std::vector<std::size_t> list;
    for (std::size_t k = 0; k < crossing.size(); ++k)
      if (crossing[k])
        list.push_back(k);
    return list;
  }

  std::vector<std::size_t> caps(const io::PolyData &s, double ratio, double height)
  {
    std::vector<std::size_t> list;
    for (std::size_t k = 0; k < s.triangles.size(); ++k)
      {
        const auto   &t = s.triangles[k];
        const double *p[3] = {&s.points[3 * t[0]], &s.points[3 * t[1]], &s.points[3 * t[2]]};
        double        longest2 = 0;
        for (int e = 0; e < 3; ++e)
          longest2 = std::max(longest2, (p[e][0] - p[(e + 1) % 3][0]) * (p[e][0] - p[(e + 1) % 3][0]) +
                                          (p[e][1] - p[(e + 1) % 3][1]) * (p[e][1] - p[(e + 1) % 3][1]) +
                                          (p[e][2] - p[(e + 1) % 3][2]) * (p[e][2] - p[(e + 1) % 3][2]));
        const auto n = normal_of(p[0], p[1], p[2]);
        if (longest2 == 0 || // (its corners one point)
            std::sqrt(dot(n, n)) < std::max(ratio * longest2, height * std::sqrt(longest2))) // 2 area / longest
          list.push_back(k);
      }
    return list;
  }

  std::size_t flip_with_a_neighbour(io::PolyData &s, const std::vector<std::size_t> &triangles)
  {
    if (triangles.empty())
      return 0;
    auto point = [&](long v) { return &s.points[3 * v]; };
    auto key   = [](long a, long b) { return std::make_pair(std::min(a, b), std::max(a, b)); };
    std::map<std::pair<long, long>, std::vector<std::size_t>> edges;
    for (std::size_t k = 0; k < s.triangles.size(); ++k)
      for (int e = 0; e < 3; ++e)
        edges[key(s.triangles[k][e], s.triangles[k][(e + 1) % 3])].push_back(k);
    std::vector<char> changed(s.triangles.size(), 0);
    for (const std::size_t k : triangles)
      changed[k] = 1; // (not a flip's good neighbour)
    std::size_t flips = 0;
    for (const std::size_t k : triangles)
      {
        // its edges a -> b (in the triangle's order), the longest first, and the corner c opposite
        const auto          t = s.triangles[k];
        std::array<int, 3>  order{0, 1, 2};
        std::array<double, 3> length2{};
        for (int e = 0; e < 3; ++e)
          {
            const double *p = point(t[e]), *q = point(t[(e + 1) % 3]);
            length2[e] = (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) + (q[2] - p[2]) * (q[2] - p[2]);
          }
        std::sort(order.begin(), order.end(), [&](int x, int y) { return length2[x] > length2[y]; });
        for (const int e : order)
          {
            const long  a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
            const auto &across = edges[key(a, b)];
            if (across.size() != 2)
              continue;
            const std::size_t j = across[0] == k ? across[1] : across[0];
            if (changed[j])
              continue;
            long d = -1;
            for (const long v : s.triangles[j])
              if (v != a && v != b)
                d = v;
            if (d < 0 || d == c || edges.count(key(c, d)))
              continue;
            const auto m = normal_of(point(s.triangles[j][0]), point(s.triangles[j][1]), point(s.triangles[j][2]));
            if (dot(normal_of(point(a), point(d), point(c)), m) <= 0 || dot(normal_of(point(d), point(b), point(c)), m) <= 0)
              continue;
            // (k, j) = (a, b, c), (b, a, d) become (a, d, c), (d, b, c): the edge a-d moves to k, b-c to j
            s.triangles[k] = {a, d, c};
            s.triangles[j] = {d, b, c};
            changed[j]     = 1;
            edges.erase(key(a, b));
            edges[key(c, d)] = {k, j};
            for (std::size_t &o : edges[key(a, d)])
              if (o == j)
                o = k;
            for (std::size_t &o : edges[key(b, c)])
              if (o == k)
                o = j;
            ++flips;
            break;
          }
      }
    return flips;
  }
} // namespace abrade::fem::folds
