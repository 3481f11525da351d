// The worn surface built as a set (fem/eroded_surface.h) against exact answers of the front
// motion: a box worn uniformly is the inner box (flat faces at the depth, edges and corners
// sharp); a chisel worn uniformly recedes at its tip by d / sin(half angle); a face worn by a
// depth that grows linearly along it, d = d0 + k x, becomes the plane at d / sqrt(1 - k^2)
// below it (the envelope of the balls, Huygens' construction), not at d; a plate worn on both
// sides merges its fronts; a long chisel worn most at its edge gives a surface that Gmsh
// fills.
#include <abrade/common/error.h>
#include <abrade/common/surface_distance.h>
#include <abrade/common/vtk_output.h>
#include <abrade/fem/eroded_surface.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/surface_repair.h>
#include <abrade/fem/triangle_folds.h>
#include <abrade/fem/worn_front.h>

#include <deal.II/grid/tria.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <random>

using namespace abrade;
using namespace abrade::fem;

namespace
{
  /// A closed, outward triangle surface from corner points and quadrilateral/triangular faces
  /// (each face counter-clockwise seen from outside), each face split into n x n pieces so that
  /// the depth can vary over it.
  io::PolyData box(double a, double b, double c, int n)
  {
    io::PolyData s;
    // six faces: origin, u, v (u x v outward)
    const double faces[6][9] = {{0, 0, 0, 0, b, 0, a, 0, 0}, {0, 0, c, a, 0, 0, 0, b, 0}, {0, 0, 0, a, 0, 0, 0, 0, c},
                                {0, b, 0, 0, 0, c, a, 0, 0}, {0, 0, 0, 0, 0, c, 0, b, 0}, {a, 0, 0, 0, b, 0, 0, 0, c}};
    for (const auto &f : faces)
      {
        const long base = long(s.points.size() / 3);
        for (int j = 0; j <= n; ++j)
          for (int i = 0; i <= n; ++i)
            for (int q = 0; q < 3; ++q)
              s.points.push_back(f[q] + f[3 + q] * i / n + f[6 + q] * j / n);
        for (int j = 0; j < n; ++j)
          for (int i = 0; i < n; ++i)
            {
              const long p = base + j * (n + 1) + i;
              s.triangles.push_back({p, p + 1, p + n + 2});
              s.triangles.push_back({p, p + n + 2, p + n + 1});
            }
      }
    return s;
  }

  /// The highest z of the surface over (x, y) (the vertical line's intersections with the
  /// triangles); -infinity where it meets none.
  double highest_point_above(const io::PolyData &s, double x, double y)
  {
    double top = -std::numeric_limits<double>::infinity();
    for (const auto &t : s.triangles)
      {
        const double *a = &s.points[3 * t[0]], *b = &s.points[3 * t[1]], *c = &s.points[3 * t[2]];
        const double  det = (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]);
        if (det == 0)
          continue;
        const double u = ((x - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (y - a[1])) / det;
        const double v = ((b[0] - a[0]) * (y - a[1]) - (x - a[0]) * (b[1] - a[1])) / det;
        if (u >= 0 && v >= 0 && u + v <= 1)
          top = std::max(top, a[2] + u * (b[2] - a[2]) + v * (c[2] - a[2]));
      }
    return top;
  }

  /// A prism along x (0 ... length) over a convex polygon in the (y, z) plane (counter-clockwise
  /// seen from +x), its sides split into pieces of about @p step, its ends fans.
  io::PolyData prism(const std::vector<std::array<double, 2>> &polygon, double length, double step)
  {
    io::PolyData s;
    const long   nx = std::max(1L, long(std::ceil(length / step)));
    const long   m  = long(polygon.size());
    auto         add = [&](double x, double y, double z) {
      s.points.insert(s.points.end(), {x, y, z});
      return long(s.points.size() / 3 - 1);
    };
    std::vector<long> first(m + 1, 0), count(m + 1, 0);
    std::vector<std::vector<long>> ring(nx + 1); // the points around each x station
    for (long i = 0; i <= nx; ++i)
      for (long e = 0; e < m; ++e)
        {
          const auto  &a = polygon[e], &b = polygon[(e + 1) % m];
          const long   n = std::max(1L, long(std::ceil(std::hypot(b[0] - a[0], b[1] - a[1]) / step)));
          for (long k = 0; k < n; ++k)
            ring[i].push_back(add(length * i / nx, a[0] + (b[0] - a[0]) * k / n, a[1] + (b[1] - a[1]) * k / n));
        }
    const long around = long(ring[0].size());
    for (long i = 0; i < nx; ++i)
      for (long k = 0; k < around; ++k)
        {
          const long p = ring[i][k], q = ring[i][(k + 1) % around], r = ring[i + 1][(k + 1) % around],
                     t = ring[i + 1][k];
          s.triangles.push_back({p, r, t});
          s.triangles.push_back({p, q, r});
        }
    for (long i : {0L, nx})
      {
        double cy = 0, cz = 0;
        for (const auto &p : polygon)
          cy += p[0] / m, cz += p[1] / m;
        const long c = add(length * i / nx, cy, cz);
        for (long k = 0; k < around; ++k)
          if (i == 0)
            s.triangles.push_back({c, ring[i][(k + 1) % around], ring[i][k]});
          else
            s.triangles.push_back({c, ring[i][k], ring[i][(k + 1) % around]});
      }
    return s;
  }

  double signed_volume(const io::PolyData &s)
  {
    double v = 0;
    for (const auto &t : s.triangles)
      {
        const double *a = &s.points[3 * t[0]], *b = &s.points[3 * t[1]], *c = &s.points[3 * t[2]];
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
      }
    return v;
  }
  /// The volume worn from box(a, b, c, n) when its top face's points wear by d: the top slab
  /// and, on the four sides, the wedges of their top row of triangles (depth d at the top edge
  /// to 0 a row, L = c / n, below; Huygens' envelope of a depth with slope k = d / L lies
  /// d(z) / sqrt(1 - k^2) deep), by inclusion and exclusion of where they overlap (the slab and
  /// a wedge; two wedges at a vertical edge; all three at a corner).
  double worn_top_of_box(double a, double b, double c, double d, int n)
  {
    const double L = c / n, k = d / L, w = d / std::sqrt(1 - k * k); // the wedge's depth at the top
    const double wedges    = 2 * (a + b) * w * L / 2;
    const double in_slab   = 2 * (a + b) * (w / L) * (L * L - (L - d) * (L - d)) / 2;
    const double two       = 4 * w * w * L / 3;
    const double three     = 4 * (w / L) * (w / L) * (L * L * L - (L - d) * (L - d) * (L - d)) / 3;
    return a * b * d + wedges - in_slab - two + three;
  }
} // namespace

TEST(ErodedSurface, UniformWearOfABoxIsTheInnerBox)
{
  const double a = 0.10, b = 0.08, c = 0.06, d = 0.005, h = 0.002;
  const auto   s = box(a, b, c, 4);
  const auto   e = eroded_surface(s, std::vector<double>(s.points.size() / 3, d), h, 0.01);
  const double inner = (a - 2 * d) * (b - 2 * d) * (c - 2 * d);
  EXPECT_NEAR(e.volume, inner, 0.005 * inner);
  EXPECT_NEAR(signed_volume(e.surface), e.volume, 1e-12);
  // every vertex on the inner box's surface (its distance to it: the largest of the
  // coordinates' distances to the inner faces, for points inside or on it)
  double worst = 0, nearest_corner = 1;
  for (std::size_t k = 0; k < e.surface.points.size(); k += 3)
    {
      const double *x = &e.surface.points[k];
      const double  lo[3] = {d, d, d}, hi[3] = {a - d, b - d, c - d};
      double        inside = 1, corner = 0;
      for (int q = 0; q < 3; ++q)
        {
          inside = std::min({inside, x[q] - lo[q], hi[q] - x[q]});
          corner = std::max(corner, std::min(std::abs(x[q] - lo[q]), std::abs(x[q] - hi[q])));
        }
      worst          = std::max(worst, std::abs(inside));
      nearest_corner = std::min(nearest_corner, corner);
    }
  EXPECT_LT(worst, 0.1 * h) << "a vertex off the inner box";
  EXPECT_LT(nearest_corner, 0.25 * h) << "the corners are cut";
  EXPECT_EQ(e.volume_cut_off, 0);
}

TEST(ErodedSurface, ALinearlyGrowingDepthTiltsTheFaceByHuygens)
{
  // the top face (z = c) worn by d = d0 + k x, the others not at all
  const double a = 0.05, b = 0.05, c = 0.04, d0 = 0.002, k = 0.3, h = 0.0015;
  const auto   s = box(a, b, c, 10);
  std::vector<double> depth(s.points.size() / 3, 0.0);
  for (std::size_t v = 0; v < depth.size(); ++v)
    if (s.points[3 * v + 2] == c)
      depth[v] = d0 + k * s.points[3 * v];
  const auto e = eroded_surface(s, depth, h, 0.008);
  double     worst = 0;
  for (double x = 0.01; x <= 0.04; x += 0.0025)
    for (double y = 0.01; y <= 0.04; y += 0.0025)
      {
        const double z = highest_point_above(e.surface, x, y);
        worst          = std::max(worst, std::abs((c - z) - (d0 + k * x) / std::sqrt(1 - k * k)));
      }
  EXPECT_LT(worst, 0.05 * h) << "not the envelope of the balls";
}

TEST(ErodedSurface, ALayerThinnerThanTheGridIsWornWhole)
{
  // the top face worn by 0.3 mm on a grid of 1.5 mm (the first updates of an edge-concentrated
  // rate, far from the edge): every point of the worn top at 0.3 mm, none left on the design
  // (balls sampled at half a spacing, 0.75 mm apart, left the surface between them unworn)
  const double a = 0.05, b = 0.05, c = 0.04, d = 0.0003, h = 0.0015;
  const auto   s = box(a, b, c, 10);
  std::vector<double> depth(s.points.size() / 3, 0.0);
  for (std::size_t v = 0; v < depth.size(); ++v)
    if (s.points[3 * v + 2] == c)
      depth[v] = d;
  const auto e = eroded_surface(s, depth, h, 0.008);
  double     worst = 0;
  for (double x = 0.005; x <= 0.045; x += 0.001)
    for (double y = 0.005; y <= 0.045; y += 0.001)
      worst = std::max(worst, std::abs((c - highest_point_above(e.surface, x, y)) - d));
  EXPECT_LT(worst, 0.02 * d) << "the thin layer is not worn evenly";
  // the volume: at least the exact one, at most that and the chamfer marching cubes cuts along
  // every convex edge of the box, worn or not (legs of up to 3/4 of a spacing; the projection
  // puts the vertices on the edge's faces, the triangles between them still cut across it)
  const double worn = worn_top_of_box(a, b, c, d, 10);
  EXPECT_GT(a * b * c - e.volume, 0.99 * worn);
  EXPECT_LT(a * b * c - e.volume, worn + 4 * (a + b + c) * std::pow(0.75 * h, 2) / 2);
}

TEST(ErodedSurface, FrontsThatMeetMerge)
{
  // a plate 10 mm thick worn 6 mm from both faces on its left half: the left half is gone,
  // cut off cleanly, the right half stands
  const double a = 0.1, b = 0.05, c = 0.01, h = 0.001;
  const auto   s = box(a, b, c, 10);
  std::vector<double> depth(s.points.size() / 3, 0.0);
  for (std::size_t v = 0; v < depth.size(); ++v)
    if (s.points[3 * v] < 0.0401)
      depth[v] = 0.006;
  const auto e = eroded_surface(s, depth, h, 0.005);
  double     left = a;
  for (std::size_t q = 0; q < e.surface.points.size(); q += 3)
    left = std::min(left, e.surface.points[q]);
  EXPECT_GT(left, 0.04) << "material left where both fronts passed";
  EXPECT_LT(left, 0.04 + 0.006 + h);
  EXPECT_GT(e.volume, 0.5 * (a - 0.04) * b * c);
}

TEST(ErodedSurface, TheChiselWornStepByStepIsItsInnerParallelBody)
{
  // the reference knife's cross-section (30 mm plate, double bevel 40 mm high, 0.4 m long, here
  // 0.2 m high): a convex prism, whose inner parallel body at distance D is the intersection of
  // its faces' half-spaces moved in by D, so every point of the worn surface lies exactly D
  // below the design. Three updates of 2.5 mm, each from the last one's surface, at the
  // spacing the lifetime loop takes (2 mm) and its triangle length (6.7 mm)
  const std::vector<std::array<double, 2>> section = {{0, 0}, {0.015, 0.04}, {0.015, 0.2}, {-0.015, 0.2}, {-0.015, 0.04}};
  const double length = 0.4, d = 0.0025, h = 0.002;
  io::PolyData surface = prism(section, length, 0.02);
  ASSERT_NEAR(signed_volume(surface), length * (0.03 * 0.16 + 0.5 * 0.03 * 0.04), 1e-12);
  // the design's planes: n . x <= offset
  std::vector<std::array<double, 4>> planes = {{-1, 0, 0, 0}, {1, 0, 0, length}};
  for (std::size_t e = 0; e < section.size(); ++e)
    {
      const auto &a = section[e], &b = section[(e + 1) % section.size()];
      const double ny = b[1] - a[1], nz = -(b[0] - a[0]), norm = std::hypot(ny, nz);
      planes.push_back({0, ny / norm, nz / norm, (ny * a[0] + nz * a[1]) / norm});
    }
  for (int update = 1; update <= 3; ++update)
    {
      const auto e = eroded_surface(surface, std::vector<double>(surface.points.size() / 3, d), h, 0.02 / 3);
      surface      = e.surface;
      double worst = 0;
      for (std::size_t k = 0; k < surface.points.size(); k += 3)
        {
          double depth = 1;
          for (const auto &p : planes)
            depth = std::min(depth, p[3] - (p[0] * surface.points[k] + p[1] * surface.points[k + 1] +
                                            p[2] * surface.points[k + 2]));
          worst = std::max(worst, std::abs(depth - update * d));
        }
      // the corners cut between vertices are carried into the next update: 0.03, 0.07, 0.11 mm
      // (0.056 h) at the tip's trihedral corners after one, two, three updates
      EXPECT_LT(worst, 0.02 * h * update + 0.01 * h) << "update " << update << ": a vertex off the inner parallel body";
      // decimated to about the asked length in every update (a check that rejected every
      // decimation at the chisel's 37-degree tip left the marching cubes' 10x more triangles)
      EXPECT_LT(surface.triangles.size(), 12000u) << "update " << update << ": not decimated";
    }
}

TEST(ErodedSurface, ALongChiselWornAtItsEdgeIsDecimatedUnfoldedAndFilled)
{
  // A 1 m chisel (the reference knife's section, 0.3 m high) worn most at its edge and more
  // towards one end, d = 12 mm exp(-z / 50 mm) (1 + x) / 2, at the lifetime loop's spacing for
  // a 40 mm mesh (2 mm) and triangle length (13 mm): a grader blade's worn edge. The projection
  // onto the front turned triangles over along the worn edge (a grid plane 0.36 mm beside it),
  // every decimation was refused and the marching cubes' 320,000 triangles were kept, folded:
  // the repair of overlapping facets refused them ("its outline does not bound its area") and
  // the lifetime run stopped at 10 mm of wear.
  const std::vector<std::array<double, 2>> section = {{0, 0}, {0.015, 0.04}, {0.015, 0.3}, {-0.015, 0.3}, {-0.015, 0.04}};
  const double length = 1.0, h = 0.002, edge = 0.04 / 3;
  const io::PolyData surface = prism(section, length, edge);
  std::vector<double> depth(surface.points.size() / 3);
  auto                rate = [](double x, double z) { return 0.012 * std::exp(-z / 0.05) * (1 + x) / 2; };
  for (std::size_t v = 0; v < depth.size(); ++v)
    depth[v] = rate(surface.points[3 * v], surface.points[3 * v + 2]);
  const auto e = eroded_surface(surface, depth, h, edge);

  // decimated (about 8,000 triangles of 13 mm over its area)
  EXPECT_LT(e.surface.triangles.size(), 20000u) << "not decimated";
  // nothing folded, nothing Gmsh's STL reader would drop (a height below 1e-8 of the part)
  SurfaceRepair repair;
  ASSERT_NO_THROW(repair = repair_overlapping_facets(e.surface, 1e-6 * length));
  EXPECT_EQ(repair.folds, 0u);
  std::size_t flat = 0;
  for (const auto &t : e.surface.triangles)
    {
      const double *p[3] = {&e.surface.points[3 * t[0]], &e.surface.points[3 * t[1]], &e.surface.points[3 * t[2]]};
      double        longest = 0;
      for (int q = 0; q < 3; ++q)
        longest = std::max(longest, std::hypot(p[q][0] - p[(q + 1) % 3][0], p[q][1] - p[(q + 1) % 3][1],
                                               p[q][2] - p[(q + 1) % 3][2]));
      const double u[3] = {p[1][0] - p[0][0], p[1][1] - p[0][1], p[1][2] - p[0][2]},
                   w[3] = {p[2][0] - p[0][0], p[2][1] - p[0][1], p[2][2] - p[0][2]};
      flat += std::hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]) / longest <
              1e-8 * length;
    }
  EXPECT_EQ(flat, 0u);

  // the worn edge where the set puts it: on the symmetry plane y = 0 the lowest point of the
  // surface's section against the zero of g(x, 0, z) = min(distance inside the design, the
  // balls' distance), found by bisection (the implicit function itself, not its triangles)
  const geometry::SurfaceDistance design(surface.points, surface.triangles);
  const WornFront                 balls(surface, depth, 2 * h);
  auto g = [&](double x, double z) {
    const double p[3] = {x, 0, z};
    double       foot[3];
    return std::min(-design.signed_distance(p), balls.distance(p, foot));
  };
  for (const double x : {0.25, 0.5, 0.75})
    {
      double below = 0, above = 0.1; // g < 0 (worn away) below the edge, > 0 above it
      ASSERT_LT(g(x, below), 0);
      ASSERT_GT(g(x, above), 0);
      while (above - below > 1e-7)
        (g(x, 0.5 * (below + above)) > 0 ? above : below) = 0.5 * (below + above);
      // the triangles' section by the plane through x: its lowest point
      double lowest = 1;
      for (const auto &t : e.surface.triangles)
        for (int q = 0; q < 3; ++q)
          {
            const double *a = &e.surface.points[3 * t[q]], *b = &e.surface.points[3 * t[(q + 1) % 3]];
            if ((a[0] - x) * (b[0] - x) <= 0 && a[0] != b[0])
              lowest = std::min(lowest, a[2] + (b[2] - a[2]) * (x - a[0]) / (b[0] - a[0]));
          }
      // (a sharp edge is cut by up to half a spacing: here 0.65-0.72 mm, where the projection's
      // turned triangles kept the marching cubes' corners)
      EXPECT_NEAR(lowest, above, 0.5 * h) << "the worn edge at x = " << x << " (worn " << above * 1e3 << " mm up)";
    }

  // Gmsh fills its triangles with tetrahedra, of the volume they enclose
  dealii::Triangulation<3> filled;
  const std::string        stl = (std::filesystem::temp_directory_path() / "abrade_long_chisel.stl").string();
  io::write_stl(stl, e.surface);
  ASSERT_NO_THROW(read_closed_triangles(stl, 0.04, filled, 120));
  EXPECT_NEAR(mesh_volume(filled), e.volume, 1e-6 * e.volume);
  std::filesystem::remove(stl);
}

// The STL reader's sliver rule (folds::is_sliver), which the set's decimation checks against:
// the height over the longest edge, computed here by hand.
TEST(Slivers, TheHeightOverTheLongestEdgeDecides)
{
  // a 2 m edge with its third corner 1 mm beside it, 3 m from the origin
  const double a[3] = {3, 0, 0}, b[3] = {5, 0, 0}, c[3] = {3.3, 1e-3, 0};
  EXPECT_TRUE(folds::is_sliver(a, b, c, 1.01e-3));
  EXPECT_FALSE(folds::is_sliver(a, b, c, 0.99e-3));
  EXPECT_FALSE(folds::is_sliver(c, a, b, 0.99e-3)); // (any order of the corners)
  // longest edge a -> f (5 m): twice the area 0.1 m x 1 mm, over 5 m: a height of 2e-5 m
  // (over the short edge a -> e it would be 1 mm)
  const double e[3] = {3.1, 0, 0}, f[3] = {8, 1e-3, 0};
  const double height = 1e-4 / std::hypot(5.0, 1e-3);
  EXPECT_TRUE(folds::is_sliver(a, e, f, 1.01 * height));
  EXPECT_FALSE(folds::is_sliver(a, e, f, 0.99 * height));
  // three corners at one point: a sliver at any height
  EXPECT_TRUE(folds::is_sliver(a, a, a, 0));
}

// WornFront passes over a triangle whose box puts it farther than the closest one found
// (f_T(x) >= |x - box| - d_max): the front must still be the minimum over all worn triangles,
// also within a fraction of a micrometre of a corner that fans of triangles share as their
// deepest (the edges' f_T there lost its digits to cancellation and fell below the bound by
// up to 5.5e-9 m: 62 % of such points differed, from a referee's test).
TEST(WornFront, TheFrontIsTheMinimumOverAllTrianglesNearASharedCorner)
{
  std::mt19937_64                        rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  long                                   differ = 0, total = 0;
  for (int trial = 0; trial < 2000; ++trial)
    {
      const int           n = 6;
      io::PolyData        fan;
      std::vector<double> depth = {0.03};
      const double        v[3]  = {3 + unit(rng), 0.5 * unit(rng), 0.2 * unit(rng)};
      fan.points.insert(fan.points.end(), v, v + 3);
      for (int k = 0; k < n; ++k)
        {
          for (int c = 0; c < 3; ++c)
            fan.points.push_back(v[c] - 0.2 * unit(rng));
          depth.push_back(0.03 * unit(rng));
        }
      for (long k = 0; k < n; ++k)
        fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % n});
      const WornFront front(fan, depth, 0.004);
      for (int q = 0; q < 50; ++q, ++total)
        {
          const double away = std::pow(10.0, -7 - 3 * unit(rng));
          const double x[3] = {v[0] + away * unit(rng), v[1] + away * unit(rng), v[2] + away * unit(rng)};
          double       on[3], foot[3];
          double       all = std::numeric_limits<double>::infinity();
          for (const auto &t : front.triangles())
            all = std::min(all, t.distance(x, foot));
          differ += front.distance(x, on) != all;
        }
    }
  EXPECT_EQ(differ, 0) << "of " << total << " points";
}
