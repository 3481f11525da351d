// The front of one update's wear as a continuous union of balls (worn_front.h).
#include <abrade/fem/worn_front.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace abrade::fem
{
  namespace
  {
    double dot(const double *u, const double *v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; }

    /// min over s in [0, L] of sqrt(w^2 + (s - s0)^2) - (dA + k s) on the edge A + s e / L:
    /// convex in s, its stationary point s0 + k w / sqrt(1 - k^2) (|k| < 1) clamped to the edge.
    double edge_distance(const double *x, const double *A, const double *B, double dA, double dB, double *foot)
    {
      const double e[3] = {B[0] - A[0], B[1] - A[1], B[2] - A[2]}, w[3] = {x[0] - A[0], x[1] - A[1], x[2] - A[2]};
      const double L = std::sqrt(dot(e, e));
      if (!(L > 0))
        {
          std::copy_n(A, 3, foot);
          return std::sqrt(dot(w, w)) - std::max(dA, dB);
        }
      // (w2, the squared distance from the edge's line, from the perpendicular itself: |w|^2 -
      // s0^2 lost its digits near the line, and f fell below |x - box| - d_max, the bound by
      // which WornFront passes triangles over)
      const double s0 = dot(w, e) / L, k = (dB - dA) / L;
      const double perpendicular[3] = {w[0] - s0 / L * e[0], w[1] - s0 / L * e[1], w[2] - s0 / L * e[2]};
      const double w2 = dot(perpendicular, perpendicular);
      double       s;
      if (k >= 1)
        s = L;
      else if (k <= -1)
        s = 0;
      else
        s = std::clamp(s0 + k * std::sqrt(w2) / std::sqrt(1 - k * k), 0.0, L);
      for (int c = 0; c < 3; ++c)
        foot[c] = A[c] + s / L * e[c];
      return std::sqrt(w2 + (s - s0) * (s - s0)) - (dA + k * s);
    }
  } // namespace

  SweptTriangle::SweptTriangle(const double *a, const double *b, const double *c, double da, double db, double dc)
  {
    std::copy_n(a, 3, corner[0]), std::copy_n(b, 3, corner[1]), std::copy_n(c, 3, corner[2]);
    depth[0] = da, depth[1] = db, depth[2] = dc;
    d_max    = std::max({da, db, dc});
    for (int q = 0; q < 3; ++q)
      bounds[q] = std::min({a[q], b[q], c[q]}), bounds[q + 3] = std::max({a[q], b[q], c[q]});
    for (int q = 0; q < 3; ++q)
      e1[q] = b[q] - a[q], e2[q] = c[q] - a[q];
    d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2);
    det = d00 * d11 - d01 * d01;
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    const double area2 = std::sqrt(dot(n, n));
    flat               = !(det > 1e-12 * d00 * d11) || !(area2 > 0);
    if (flat)
      return;
    for (int q = 0; q < 3; ++q)
      normal[q] = n[q] / area2;
    // g . e1 = db - da, g . e2 = dc - da
    const double r1 = db - da, r2 = dc - da;
    alpha = (d11 * r1 - d01 * r2) / det;
    beta  = (d00 * r2 - d01 * r1) / det;
    gg    = alpha * alpha * d00 + 2 * alpha * beta * d01 + beta * beta * d11;
  }

  std::array<double, 6> SweptTriangle::box() const
  {
    return {bounds[0], bounds[1], bounds[2], bounds[3], bounds[4], bounds[5]};
  }

  double SweptTriangle::distance(const double *x, double *foot) const
  {
    if (!flat && gg < 1)
      {
        const double w[3] = {x[0] - corner[0][0], x[1] - corner[0][1], x[2] - corner[0][2]};
        const double h    = std::abs(dot(w, normal));
        // barycentric coordinates (u along e1, v along e2) of the foot x' and of the stationary point
        const double w1 = dot(w, e1), w2 = dot(w, e2);
        const double u = (d11 * w1 - d01 * w2) / det, v = (d00 * w2 - d01 * w1) / det;
        const double r = h / std::sqrt(1 - gg);
        const double up = u + r * alpha, vp = v + r * beta;
        if (up >= 0 && vp >= 0 && up + vp <= 1)
          {
            for (int c = 0; c < 3; ++c)
              foot[c] = corner[0][c] + up * e1[c] + vp * e2[c];
            const double d_foot = depth[0] + u * (depth[1] - depth[0]) + v * (depth[2] - depth[0]);
            return h * std::sqrt(1 - gg) - d_foot;
          }
      }
    double best = std::numeric_limits<double>::infinity();
    for (int e = 0; e < 3; ++e)
      {
        double       p[3];
        const double f = edge_distance(x, corner[e], corner[(e + 1) % 3], depth[e], depth[(e + 1) % 3], p);
        if (f < best)
          best = f, std::copy_n(p, 3, foot);
      }
    return best;
  }

  WornFront::WornFront(const io::PolyData &s, const std::vector<double> &depth, double margin)
  {
    double largest = 0;
    for (const auto &t : s.triangles)
      {
        const double d0 = depth[t[0]], d1 = depth[t[1]], d2 = depth[t[2]];
        if (std::max({d0, d1, d2}) <= 0)
          continue;
        worn.emplace_back(&s.points[3 * t[0]], &s.points[3 * t[1]], &s.points[3 * t[2]], std::max(d0, 0.0),
                          std::max(d1, 0.0), std::max(d2, 0.0));
        largest = std::max(largest, worn.back().largest_depth());
      }
    cell = largest + margin;
    // (f_T's round-off: a few units in the last place of the coordinates)
    double extent = 0;
    for (const double c : s.points)
      extent = std::max(extent, std::abs(c));
    guard = 1e-12 * (extent + cell);
    for (unsigned q = 0; q < worn.size(); ++q)
      {
        const auto b = worn[q].box();
        long       lo[3], hi[3];
        for (int c = 0; c < 3; ++c)
          lo[c] = long(std::floor(b[c] / cell)), hi[c] = long(std::floor(b[c + 3] / cell));
        for (long i = lo[0]; i <= hi[0]; ++i)
          for (long j = lo[1]; j <= hi[1]; ++j)
            for (long k = lo[2]; k <= hi[2]; ++k)
              cells[key(i, j, k)].push_back(q);
      }
  }

  double WornFront::distance(const double *x, double *on_front, double *gradient) const
  {
    // A triangle is listed in every cell its box overlaps, so that one seen in an earlier cell
    // of the 27 is skipped (a second look could not lower the minimum), as is one whose box
    // rules it out. Each thread marks what it has seen with the number of its query.
    thread_local std::vector<std::uint64_t> seen;
    thread_local std::uint64_t              query = 0;
    if (seen.size() < worn.size())
      seen.resize(worn.size(), 0);
    ++query;
    double     best = std::numeric_limits<double>::infinity(), foot[3] = {0, 0, 0}, p[3];
    const long i0 = long(std::floor(x[0] / cell)), j0 = long(std::floor(x[1] / cell)), k0 = long(std::floor(x[2] / cell));
    for (long i = i0 - 1; i <= i0 + 1; ++i)
      for (long j = j0 - 1; j <= j0 + 1; ++j)
        for (long k = k0 - 1; k <= k0 + 1; ++k)
          if (const auto it = cells.find(key(i, j, k)); it != cells.end())
            for (const unsigned q : it->second)
              {
                if (seen[q] == query)
                  continue;
                seen[q] = query;
                if (worn[q].exceeds(x, best, guard))
                  continue;
                const double f = worn[q].distance(x, p);
                if (f < best)
                  best = f, std::copy_n(p, 3, foot);
              }
    if (std::isfinite(best))
      {
        const double to[3] = {x[0] - foot[0], x[1] - foot[1], x[2] - foot[2]};
        const double r     = std::sqrt(dot(to, to));
        for (int c = 0; c < 3; ++c)
          on_front[c] = r > 0 ? x[c] - best * to[c] / r : x[c];
        if (gradient)
          for (int c = 0; c < 3; ++c)
            gradient[c] = r > 0 ? to[c] / r : 0;
      }
    return best;
  }
} // namespace abrade::fem
