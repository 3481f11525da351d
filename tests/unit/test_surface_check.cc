// Self-intersections of a triangle surface (fem/surface_check.h): each way two triangles can
// meet (crossing with no vertex shared, crossing beside a shared vertex, folded onto each other
// across a shared edge, repeated) against a neighbour that only touches where it should.
#include <abrade/fem/surface_check.h>

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
