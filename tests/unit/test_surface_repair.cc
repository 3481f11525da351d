// Overlapping facets repaired before meshing (fem/surface_repair.h). A closed box whose top is
// tessellated as a fan from a point outside it (two of the fan's facets face down, on top of
// the others: Gmsh stops with "overlapping facets" on it) comes back with the top triangulated
// from its outline: the same volume (divergence theorem, 1e-15), every edge between two facets
// of opposite direction, no coplanar neighbours facing opposite ways, the outside point gone.
// A flap folded back (a facet and its mirror hanging off an edge) is dropped. A box without
// folds comes back as it was (its points welded).
#include <abrade/fem/surface_repair.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>

using namespace abrade;

namespace
{
  using P = std::array<double, 3>;

  /// One facet per three points, repeated per facet as an STL has them.
  io::PolyData facets(const std::vector<std::array<P, 3>> &triangles)
  {
    io::PolyData d;
    for (const auto &t : triangles)
      {
        const long base = long(d.points.size() / 3);
        for (const auto &p : t)
          d.points.insert(d.points.end(), p.begin(), p.end());
        d.triangles.push_back({base, base + 1, base + 2});
      }
    return d;
  }

  /// 0.2 x 0.1 x 0.05 box; its top as two triangles, or as a fan from (0.3, 0.05, 0.05).
  std::vector<std::array<P, 3>> box(bool fan)
  {
    const double L = 0.2, W = 0.1, H = 0.05;
    std::vector<std::array<P, 3>> t = {
      {P{0, 0, 0}, P{0, W, 0}, P{L, W, 0}}, {P{0, 0, 0}, P{L, W, 0}, P{L, 0, 0}},
      {P{0, 0, 0}, P{L, 0, 0}, P{L, 0, H}}, {P{0, 0, 0}, P{L, 0, H}, P{0, 0, H}},
      {P{0, W, 0}, P{0, W, H}, P{L, W, H}}, {P{0, W, 0}, P{L, W, H}, P{L, W, 0}},
      {P{0, 0, 0}, P{0, 0, H}, P{0, W, H}}, {P{0, 0, 0}, P{0, W, H}, P{0, W, 0}},
      {P{L, 0, 0}, P{L, W, 0}, P{L, W, H}}, {P{L, 0, 0}, P{L, W, H}, P{L, 0, H}}};
    const std::array<P, 4> top = {P{0, 0, H}, P{L, 0, H}, P{L, W, H}, P{0, W, H}};
    if (fan)
      for (int i = 0; i < 4; ++i)
        t.push_back({P{L + 0.1, W / 2, H}, top[i], top[(i + 1) % 4]});
    else
      t.insert(t.end(), {{top[0], top[1], top[2]}, {top[0], top[2], top[3]}});
    return t;
  }

  double volume(const io::PolyData &d)
  {
    double v = 0;
    for (const auto &t : d.triangles)
      {
        const double *a = &d.points[3 * t[0]], *b = &d.points[3 * t[1]], *c = &d.points[3 * t[2]];
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
      }
    return v;
  }

  /// Every directed edge met once and its reverse once: closed and consistently oriented.
  bool closed_and_oriented(const io::PolyData &d)
  {
    std::map<std::pair<long, long>, int> count;
    for (const auto &t : d.triangles)
      for (int e = 0; e < 3; ++e)
        ++count[{t[e], t[(e + 1) % 3]}];
    for (const auto &[edge, n] : count)
      if (n != 1 || count.count({edge.second, edge.first}) == 0 || count.at({edge.second, edge.first}) != 1)
        return false;
    return true;
  }
} // namespace

TEST(SurfaceRepair, AFanFromOutsideTheFaceIsTriangulatedFromItsOutline)
{
  const io::PolyData bad = facets(box(true));
  ASSERT_NEAR(volume(bad), 0.001, 1e-15); // closed, the overlaps cancel: only Gmsh objects
  const fem::SurfaceRepair r = fem::repair_overlapping_facets(bad, 1e-12);
  EXPECT_EQ(r.folds, 2u);
  EXPECT_EQ(r.planes, 1u);
  EXPECT_NEAR(volume(r.surface), 0.001, 1e-15);
  EXPECT_TRUE(closed_and_oriented(r.surface));
  EXPECT_EQ(r.surface.points.size(), 3u * 8); // the box's corners; the fan's point gone
  const fem::SurfaceRepair again = fem::repair_overlapping_facets(r.surface, 1e-12);
  EXPECT_EQ(again.folds, 0u); // nothing left to repair
}

TEST(SurfaceRepair, AFlapFoldedBackIsDroppedAndAGoodSurfaceStays)
{
  // (a closed box and, hanging off nothing, a facet with its mirror: a flap of no area's worth)
  auto t = box(false);
  t.push_back({P{0.05, 0.05, 0.05}, P{0.1, 0.05, 0.05}, P{0.1, 0.08, 0.05}});
  t.push_back({P{0.05, 0.05, 0.05}, P{0.1, 0.08, 0.05}, P{0.1, 0.05, 0.05}});
  const fem::SurfaceRepair flap = fem::repair_overlapping_facets(facets(t), 1e-12);
  EXPECT_GE(flap.folds, 1u);
  EXPECT_EQ(flap.surface.triangles.size(), 12u); // the flap gone, the box as it was
  EXPECT_TRUE(closed_and_oriented(flap.surface));
  EXPECT_NEAR(volume(flap.surface), 0.001, 1e-15);
  const fem::SurfaceRepair good = fem::repair_overlapping_facets(facets(box(false)), 1e-12);
  EXPECT_EQ(good.folds, 0u);
  EXPECT_EQ(good.surface.triangles.size(), 12u);
  EXPECT_TRUE(closed_and_oriented(good.surface));
}

// A facet turned the wrong way round inside a flat face (its far corner on the other side of the
// shared edge from its neighbour's) overlaps nothing: not a fold, left as it is (the closed-
// surface check is the place for it), never a refusal.
TEST(SurfaceRepair, AFacetTurnedRoundIsNotAFold)
{
  auto t = box(false);
  std::swap(t.back()[1], t.back()[2]);
  const fem::SurfaceRepair r = fem::repair_overlapping_facets(facets(t), 1e-12);
  EXPECT_EQ(r.folds, 0u);
  EXPECT_EQ(r.surface.triangles.size(), 12u);
}

// The fan box turned about two axes and written in single precision, as a binary STL holds it:
// its corners lie up to ~1e-8 m off their planes, and the folds are found with the tolerance the
// STL reader uses (1e-6 of the part's size; 1e-9 of it missed them).
TEST(SurfaceRepair, FoldsOnATiltedSinglePrecisionFaceAreFound)
{
  const double a = 0.5, b = 0.3, ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  auto         t = box(true);
  for (auto &tri : t)
    for (auto &p : tri)
      {
        const P q = {ca * p[0] - sa * p[1], sa * p[0] + ca * p[1], p[2]};
        const P r = {q[0], cb * q[1] - sb * q[2], sb * q[1] + cb * q[2]};
        for (int c = 0; c < 3; ++c)
          p[c] = double(float(r[c] + 1.0)); // (1 m away from the origin, as a part's coordinates are)
      }
  const fem::SurfaceRepair r = fem::repair_overlapping_facets(facets(t), 1e-6 * 0.3);
  EXPECT_EQ(r.folds, 2u);
  EXPECT_EQ(r.planes, 1u);
  EXPECT_TRUE(closed_and_oriented(r.surface));
  EXPECT_NEAR(volume(r.surface), 0.001, 1e-9);
}
