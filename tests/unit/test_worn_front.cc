// The front of one update's wear (fem/worn_front.h) against a brute-force minimum: for random
// triangles, corner depths and points, min over p in T of |x - p| - d(p) found in closed form
// equals the minimum over a fine barycentric sampling of the triangle (to the sampling's
// error), its minimiser lies on the triangle and gives that value; x - f grad f lies on the
// front (f = 0 there) where the point's nearest front is a flat face's offset.
#include <abrade/fem/worn_front.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace abrade;
using namespace abrade::fem;

namespace
{
  double brute_force(const double *a, const double *b, const double *c, const double *d, const double *x, int m)
  {
    double best = 1e300;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j)
        {
          const double u = double(i) / m, v = double(j) / m, w = 1 - u - v;
          double       p[3];
          for (int q = 0; q < 3; ++q)
            p[q] = w * a[q] + u * b[q] + v * c[q];
          const double f = std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]) - (w * d[0] + u * d[1] + v * d[2]);
          best           = std::min(best, f);
        }
    return best;
  }

  /// d at a point p of the triangle (barycentric coordinates from the Gram system); the
  /// barycentric coordinates themselves must lie in [0, 1]
  double depth_at(const double *a, const double *b, const double *c, const double *d, const double *p)
  {
    double e1[3], e2[3], w[3];
    for (int q = 0; q < 3; ++q)
      e1[q] = b[q] - a[q], e2[q] = c[q] - a[q], w[q] = p[q] - a[q];
    auto         dot = [](const double *x, const double *y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    const double d00 = dot(e1, e1), d01 = dot(e1, e2), d11 = dot(e2, e2), w1 = dot(w, e1), w2 = dot(w, e2);
    const double det = d00 * d11 - d01 * d01, u = (d11 * w1 - d01 * w2) / det, v = (d00 * w2 - d01 * w1) / det;
    EXPECT_GE(u, -1e-9);
    EXPECT_GE(v, -1e-9);
    EXPECT_LE(u + v, 1 + 1e-9);
    return d[0] + u * (d[1] - d[0]) + v * (d[2] - d[0]);
  }
} // namespace

TEST(WornFront, TheClosedFormIsTheMinimumOverTheTriangle)
{
  std::mt19937                           rng(7);
  std::uniform_real_distribution<double> u(-1, 1), depth(0, 0.6);
  for (int trial = 0; trial < 400; ++trial)
    {
      double a[3], b[3], c[3], x[3], d[3] = {depth(rng), depth(rng), depth(rng)};
      for (int q = 0; q < 3; ++q)
        a[q] = u(rng), b[q] = u(rng), c[q] = u(rng), x[q] = 1.5 * u(rng);
      if (trial % 4 == 0) // some with a steep depth (|grad d| >= 1): the minimum on an edge or a corner
        d[1] += 1.5;
      const SweptTriangle t(a, b, c, d[0], d[1], d[2]);
      double              foot[3];
      const double        f = t.distance(x, foot);
      const double        g = brute_force(a, b, c, d, x, 600);
      // the sampling's error: at most the sampling step times the Lipschitz constant of
      // |x - p| - d(p) in p, 1 + |grad d| <= 1 + (largest - smallest depth) / smallest altitude
      const double ab = std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]), bc = std::hypot(c[0] - b[0], c[1] - b[1], c[2] - b[2]),
                   ca = std::hypot(a[0] - c[0], a[1] - c[1], a[2] - c[2]), longest = std::max({ab, bc, ca});
      const double n_[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                            (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                            (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
      const double altitude = std::hypot(n_[0], n_[1], n_[2]) / longest;
      const double lipschitz = 1 + (std::max({d[0], d[1], d[2]}) - std::min({d[0], d[1], d[2]})) / altitude;
      EXPECT_LE(f, g + 1e-12) << "trial " << trial << ": above a sampled value";
      EXPECT_GE(f, g - lipschitz * longest / 600) << "trial " << trial;
      // the minimiser is on the triangle and gives f
      const double n[3] = {(b[1] - a[1]) * (c[2] - a[2]) - (b[2] - a[2]) * (c[1] - a[1]),
                           (b[2] - a[2]) * (c[0] - a[0]) - (b[0] - a[0]) * (c[2] - a[2]),
                           (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])};
      const double off = ((foot[0] - a[0]) * n[0] + (foot[1] - a[1]) * n[1] + (foot[2] - a[2]) * n[2]) /
                         std::hypot(n[0], n[1], n[2]);
      EXPECT_NEAR(off, 0, 1e-12);
      EXPECT_NEAR(std::hypot(x[0] - foot[0], x[1] - foot[1], x[2] - foot[2]) - depth_at(a, b, c, d, foot), f, 1e-9)
        << "trial " << trial << ": the minimiser does not give the minimum";
    }
}

TEST(WornFront, APointOnTheFrontOfAFlatFace)
{
  // a square of two triangles in z = 0, worn by d = 0.01 + 0.2 x: above it the front is the
  // plane z = -(0.01 + 0.2 x) / sqrt(1 - 0.04) .. below (the envelope of the balls, Huygens)
  io::PolyData s;
  s.points    = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  s.triangles = {{0, 1, 2}, {0, 2, 3}};
  std::vector<double> depth = {0.01, 0.21, 0.21, 0.01};
  const WornFront     front(s, depth, 0.05);
  for (double x0 : {0.3, 0.5, 0.7})
    {
      const double x[3] = {x0, 0.5, -0.02};
      double       on[3], again[3];
      const double f = front.distance(x, on);
      EXPECT_NEAR(front.distance(on, again), 0, 1e-12) << "x - f grad f is not on the front";
      EXPECT_LT(f, 0) << "a point inside the worn layer";
    }
  // the front of the plane lies at (0.01 + 0.2 x') / sqrt(1 - 0.04) where x' is the foot of the
  // ball that reaches it: along the vertical through x = 0.5 the zero of f
  double lo = -0.5, hi = 0;
  for (int i = 0; i < 100; ++i)
    {
      const double mid = 0.5 * (lo + hi), x[3] = {0.5, 0.5, mid};
      double       on[3];
      (front.distance(x, on) < 0 ? hi : lo) = mid;
    }
  // the envelope of the balls below the plane: the plane through the line d = 0.01 + 0.2 x
  // turned by the angle asin(0.2): z = -(0.01 + 0.2 x) / sqrt(1 - 0.04)
  EXPECT_NEAR(lo, -(0.01 + 0.2 * 0.5) / std::sqrt(1 - 0.04), 1e-9);
}
