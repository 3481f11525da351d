#pragma once
// Closest point on a triangle to a point, with the feature (face, edge, vertex) it lies on
// (Ericson, Real-Time Collision Detection, 5.1.5). The feature decides whether a contact that
// touches several triangles is one contact or several (see dem/source/dem/wall_contacts.h).
#include <array>
#include <cstdint>

namespace abrade::geometry
{
  /// 0: face; 1, 2, 3: edge (v0,v1), (v1,v2), (v2,v0); 4, 5, 6: vertex v0, v1, v2.
  enum Feature : std::uint8_t
  {
    face = 0,
    edge01 = 1,
    edge12 = 2,
    edge20 = 3,
    vertex0 = 4,
    vertex1 = 5,
    vertex2 = 6
  };

  struct ClosestPoint
  {
    double  p[3];
    Feature feature;
  };

  /// (Always inlined: the wall contacts call it for every candidate triangle of every step, and
  /// GCC otherwise keeps it out of line.)
  [[gnu::always_inline]] inline ClosestPoint closest_point_on_triangle(const double q[3], const double a[3],
                                                                       const double b[3], const double c[3])
  {
    auto sub = [](const double *u, const double *v, double *w) {
      w[0] = u[0] - v[0], w[1] = u[1] - v[1], w[2] = u[2] - v[2];
    };
    auto dot = [](const double *u, const double *v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    ClosestPoint r;
    auto set = [&r](const double *base, const double *dir, double t, Feature f) {
      for (int d = 0; d < 3; ++d)
        r.p[d] = base[d] + t * (dir ? dir[d] : 0.0);
      r.feature = f;
      return r;
    };
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    sub(b, a, ab), sub(c, a, ac), sub(q, a, ap);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0)
      return set(a, nullptr, 0, vertex0);
    sub(q, b, bp);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3)
      return set(b, nullptr, 0, vertex1);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
      return set(a, ab, d1 / (d1 - d3), edge01);
    sub(q, c, cp);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6)
      return set(c, nullptr, 0, vertex2);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
      return set(a, ac, d2 / (d2 - d6), edge20);
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
      {
        double bc[3];
        sub(c, b, bc);
        return set(b, bc, (d4 - d3) / ((d4 - d3) + (d5 - d6)), edge12);
      }
    const double denom = 1 / (va + vb + vc);
    const double v = vb * denom, w = vc * denom;
    for (int d = 0; d < 3; ++d)
      r.p[d] = a[d] + ab[d] * v + ac[d] * w;
    r.feature = face;
    return r;
  }

  /// Barycentric coordinates (weights of a, b, c) of @p q, a point in the plane of the triangle
  /// (a closest point, say): the values of a field linear over the triangle interpolate exactly.
  inline std::array<double, 3> barycentric(const double q[3], const double a[3], const double b[3], const double c[3])
  {
    auto cross = [](const double *u0, const double *u1, const double *v0, const double *v1, double *w) {
      double u[3], v[3];
      for (int d = 0; d < 3; ++d)
        u[d] = u1[d] - u0[d], v[d] = v1[d] - v0[d];
      w[0] = u[1] * v[2] - u[2] * v[1], w[1] = u[2] * v[0] - u[0] * v[2], w[2] = u[0] * v[1] - u[1] * v[0];
    };
    auto dot = [](const double *u, const double *v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    double n[3], na[3], nb[3];
    cross(a, b, a, c, n);   // (b - a) x (c - a)
    cross(b, c, b, q, na);  // (c - b) x (q - b)
    cross(c, a, c, q, nb);  // (a - c) x (q - c)
    const double inv = 1 / dot(n, n), la = dot(n, na) * inv, lb = dot(n, nb) * inv;
    return {la, lb, 1 - la - lb};
  }

  /// The squared distance from @p q to the box @p b (lo x, y, z, then hi x, y, z): 0 inside.
  inline double box_distance2(const double q[3], const double *b)
  {
    double d2 = 0;
    for (int d = 0; d < 3; ++d)
      {
        const double out = q[d] < b[d] ? b[d] - q[d] : q[d] > b[d + 3] ? q[d] - b[d + 3] : 0.0;
        d2 += out * out;
      }
    return d2;
  }
} // namespace abrade::geometry

namespace abrade::dem
{
  using namespace abrade::geometry;
} // namespace abrade::dem
