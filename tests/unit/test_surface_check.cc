// Self-intersections of a triangle surface (fem/surface_check.h): each way two triangles can
// meet (crossing with no vertex shared, crossing beside a shared vertex, folded onto each other
// across a shared edge, repeated) against a neighbour that only touches where it should.
#include <abrade/fem/surface_check.h>
#include <abrade/fem/surface_tidy.h>

#include <array>
#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

using namespace abrade;
using namespace abrade::fem;

namespace
{
  io::PolyData octahedron(double shift_x = 0)
  {
    io::PolyData s;
    s.points = {1 + shift_x, 0, 0, -1 + shift_x, 0, 0, shift_x, 1, 0, shift_x, -1, 0, shift_x, 0, 1, shift_x, 0, -1};
    // outward: (+x, +y, +z) and so on round the eight octants
    s.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
    return s;
  }

  io::PolyData join(io::PolyData a, const io::PolyData &b)
  {
    const long offset = long(a.points.size() / 3);
    a.points.insert(a.points.end(), b.points.begin(), b.points.end());
    for (const auto &t : b.triangles)
      a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    return a;
  }
} // namespace

TEST(SurfaceCheck, ClosedSurfacesApartDoNotIntersect)
{
  EXPECT_TRUE(intersecting_triangles(octahedron()).empty());
  EXPECT_TRUE(intersecting_triangles(join(octahedron(), octahedron(2.5))).empty());
}

TEST(SurfaceCheck, OverlappingSolidsCross)
{
  // the second octahedron's -x corner pokes 0.5 into the first: its four faces there cross the
  // first's four +x faces
  const auto pairs = intersecting_triangles(join(octahedron(), octahedron(1.5)));
  EXPECT_GE(pairs.size(), 4u);
  for (const auto &p : pairs)
    {
      EXPECT_LT(p[0], 8u);
      EXPECT_GE(p[1], 8u);
    }
  EXPECT_EQ(intersecting_triangles(join(octahedron(), octahedron(1.5)), 2).size(), 2u); // at most
}

TEST(SurfaceCheck, RepeatedTriangleIsAPair)
{
  auto s = octahedron();
  s.triangles.push_back(s.triangles[3]);
  const auto pairs = intersecting_triangles(s);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0][0], 3u);
  EXPECT_EQ(pairs[0][1], 8u);
}

TEST(SurfaceCheck, CrossingBesideASharedVertex)
{
  // A in z = 0; B through A's corner O: its edge opposite O pierces A at (0.3, 0.3, 0)
  io::PolyData s;
  s.points    = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.3, 0.3, 1, 0.3, 0.3, -1};
  s.triangles = {{0, 1, 2}, {0, 3, 4}};
  EXPECT_EQ(intersecting_triangles(s).size(), 1u);
  // B above A, touching it at O only
  s.points[3 * 4 + 2] = 1;
  s.points[3 * 4 + 0] = s.points[3 * 4 + 1] = 0.6;
  EXPECT_TRUE(intersecting_triangles(s).empty());
}

TEST(SurfaceCheck, FoldedAcrossASharedEdge)
{
  // the edge 0-1's second triangle folded back over the first (normals opposite) ...
  io::PolyData s;
  s.points    = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.2, 0.5, 1e-7};
  s.triangles = {{0, 1, 2}, {1, 0, 3}};
  EXPECT_EQ(intersecting_triangles(s).size(), 1u);
  // ... and unfolded, flat on the other side of the edge
  s.points[3 * 3 + 1] = -0.5;
  EXPECT_TRUE(intersecting_triangles(s).empty());
}

// Tidying the flat pieces: a cube whose faces are fans from a point a hair from one corner
// (needles of 0.0006 degree) gets triangles Gmsh can fill, and keeps its shape: every point in
// its face's plane, the volume, closed and outward.
TEST(SurfaceTidy, NeedlesOnFlatFacesBecomeTriangles)
{
  io::PolyData s;
  // faces: origin, u, v with u x v outward; each split at a point near its origin corner into a
  // fan, and its edges each in 4 pieces so the fan has many needles
  const double faces[6][9] = {{0, 0, 0, 0, 1, 0, 1, 0, 0}, {0, 0, 1, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 1, 0, 0, 0, 0, 1},
                              {0, 1, 0, 0, 0, 1, 1, 0, 0}, {0, 0, 0, 0, 0, 1, 0, 1, 0}, {1, 0, 0, 0, 1, 0, 0, 0, 1}};
  std::map<std::array<long long, 3>, long> index; // shared points by their coordinates x 4
  auto add = [&](double x, double y, double z, bool shared) {
    const std::array<long long, 3> key = {std::llround(4e6 * x), std::llround(4e6 * y), std::llround(4e6 * z)};
    if (shared)
      if (const auto it = index.find(key); it != index.end())
        return it->second;
    s.points.insert(s.points.end(), {x, y, z});
    const long k = long(s.points.size() / 3 - 1);
    if (shared)
      index[key] = k;
    return k;
  };
  for (const auto &f : faces)
    {
      auto at = [&](double a, double b) {
        return std::array<double, 3>{f[0] + a * f[3] + b * f[6], f[1] + a * f[4] + b * f[7], f[2] + a * f[5] + b * f[8]};
      };
      // the rim, counter-clockwise seen from outside: (0,0) -> (1,0) -> (1,1) -> (0,1)
      std::vector<long> rim;
      for (int k = 0; k < 16; ++k)
        {
          const int    side = k / 4, step = k % 4;
          const double t    = step / 4.0;
          const double a    = side == 0 ? t : side == 1 ? 1 : side == 2 ? 1 - t : 0;
          const double b    = side == 0 ? 0 : side == 1 ? t : side == 2 ? 1 : 1 - t;
          const auto   p    = at(a, b);
          rim.push_back(add(p[0], p[1], p[2], true));
        }
      const auto hub = at(1e-5, 1e-5);
      const long c   = add(hub[0], hub[1], hub[2], false);
      for (std::size_t k = 0; k < rim.size(); ++k)
        s.triangles.push_back({c, rim[k], rim[(k + 1) % rim.size()]});
    }
  ASSERT_TRUE(intersecting_triangles(s).empty());
  const io::PolyData before = s;
  const TidyReport   r      = tidy_flat_regions(s);
  EXPECT_LT(r.smallest_angle_before, 0.01);
  EXPECT_GT(r.smallest_angle_after, 10.0) << r.flips << " flips, " << r.moves << " moves";
  EXPECT_EQ(s.points.size(), before.points.size());
  EXPECT_EQ(s.triangles.size(), before.triangles.size());
  // every point on the cube's surface still (a coordinate at 0 or 1), the volume the cube's
  double volume = 0;
  for (std::size_t k = 0; k < s.points.size(); k += 3)
    {
      int on = 0;
      for (int c = 0; c < 3; ++c)
        on += std::abs(s.points[k + c]) < 1e-12 || std::abs(s.points[k + c] - 1) < 1e-12;
      EXPECT_GE(on, 1) << "point " << k / 3 << " left its face";
    }
  for (const auto &t : s.triangles)
    {
      const double *a = &s.points[3 * t[0]], *b = &s.points[3 * t[1]], *c = &s.points[3 * t[2]];
      volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    }
  EXPECT_NEAR(volume, 1.0, 1e-12);
  EXPECT_TRUE(intersecting_triangles(s).empty());
}
