// Cross-sections (io::plane_section, coupling/include/abrade/coupling/lifetime/sections.h) on shapes whose sections
// are known: a box cut through the nodes of its mesh (its outline the rectangle, closed), and a
// plate worn flat at the bottom (the window that shows the wear, from the distances by hand).
#include <abrade/coupling/lifetime/sections.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

using namespace abrade::coupling::lifetime;

namespace
{
  /// The box [0, 1] x [-a, a] x [0, h] with nodes at x = 0, 0.5 and 1 (its sides two quads
  /// long, each two triangles; the ends two triangles each).
  abrade::io::PolyData box(double a, double h)
  {
    abrade::io::PolyData              b;
    std::vector<std::array<long, 3>> &t    = b.triangles;
    const double                      y[4] = {-a, a, a, -a}, z[4] = {0, 0, h, h};
    for (double x : {0.0, 0.5, 1.0})
      for (int k = 0; k < 4; ++k)
        b.points.insert(b.points.end(), {x, y[k], z[k]});
    for (int s = 0; s < 2; ++s)   // the two slices along x
      for (int k = 0; k < 4; ++k) // the four sides
        {
          const int p0 = 4 * s + k, p1 = 4 * s + (k + 1) % 4, q0 = p0 + 4, q1 = p1 + 4;
          t.push_back({p0, p1, q1}), t.push_back({p0, q1, q0});
        }
    t.push_back({0, 2, 1}), t.push_back({0, 3, 2}), t.push_back({8, 9, 10}), t.push_back({8, 10, 11});
    return b;
  }

  double length(const std::vector<Segment> &s)
  {
    double l = 0;
    for (const auto &g : s)
      l += std::hypot(g.u1 - g.u0, g.v1 - g.v0);
    return l;
  }
} // namespace

// A plane through the mesh's nodes (x = 0.5) cuts the rectangle's whole outline, 2 (2a + h);
// a cut that takes only edges with ends strictly on both sides found nothing there.
TEST(Sections, PlaneThroughNodesCutsTheWholeOutline)
{
  const abrade::io::PolyData b = box(0.015, 0.3);
  for (double x : {0.5, 0.25, 0.9})
    {
      const auto s = abrade::io::plane_section(b, 0, x);
      EXPECT_NEAR(length(s), 2 * (0.03 + 0.3), 1e-12) << "x = " << x;
      for (const auto &g : s) // every piece on the rectangle's border
        for (const auto [y, z] : {std::pair{g.u0, g.v0}, std::pair{g.u1, g.v1}})
          EXPECT_TRUE(std::abs(std::abs(y) - 0.015) < 1e-12 || std::abs(z) < 1e-12 || std::abs(z - 0.3) < 1e-12);
    }
  EXPECT_TRUE(abrade::io::plane_section(b, 0, 1.5).empty());
}

// A plate 2 wide and 10 high worn flat by 0.5 at its bottom: the outlines differ by 0.5 at
// most, at the bottom's corners; the window is the bottom (y and z from 0 to 0.5) with a
// margin of max(0.5, a quarter of the region's size 2) = 0.5: y -1.5 ... 1.5, z -0.5 ... 1.0.
TEST(Sections, WindowZoomsToTheWornBottom)
{
  auto rectangle = [](double bottom) {
    return std::vector<Segment>{{-1, bottom, 1, bottom}, {1, bottom, 1, 10}, {1, 10, -1, 10}, {-1, 10, -1, bottom}};
  };
  std::map<long, std::vector<Segment>> blocks = {{0, rectangle(0)}, {1, rectangle(0.25)}, {2, rectangle(0.5)}};
  const SectionWindow                  w      = section_window(blocks);
  EXPECT_TRUE(w.zoomed);
  EXPECT_NEAR(w.largest_distance, 0.5, 1e-12);
  EXPECT_NEAR(w.y0, -1.5, 1e-12);
  EXPECT_NEAR(w.y1, 1.5, 1e-12);
  EXPECT_NEAR(w.z0, -0.5, 1e-12);
  EXPECT_NEAR(w.z1, 1.0, 1e-12);

  // unworn: the whole section with 5 % of its diagonal around it
  const SectionWindow whole = section_window({{0, rectangle(0)}, {1, rectangle(0)}});
  EXPECT_FALSE(whole.zoomed);
  EXPECT_NEAR(whole.z1 - whole.z0, 10 + 0.1 * std::hypot(2, 10), 1e-12);

  // the file's round trip, and a plot that names the design and the updates drawn
  const std::string file = (std::filesystem::temp_directory_path() / "abrade_test_sections.csv").string();
  write_section_blocks(file, blocks);
  const auto back = read_section_blocks(file);
  ASSERT_EQ(back.size(), 3u);
  EXPECT_DOUBLE_EQ(back.at(2)[0].v0, 0.5);
  std::ostringstream gp;
  EXPECT_TRUE(section_plot(gp, back, w, "s.png", "t"));
  EXPECT_NE(gp.str().find("title 'design'"), std::string::npos);
  EXPECT_NE(gp.str().find("title 'update 2'"), std::string::npos);
  std::remove(file.c_str());
}

// How the box faces near a point (io::normal_magnitudes_near, which chooses the plane of the
// section through a worn end face), by hand on the box [0, 1] x [-0.5, 0.5] x [0, 1]: nearest
// (1, 0, 0.5) lie the end face's two triangles (centres 0.24 away, area 0.5 each, normal x),
// then the four sides' triangles with two corners at x = 1 (centres at x = 5/6, 0.55 away) and
// two of those with one (x = 2/3, 0.62 away), area 0.25 each, normals y or z: the x magnitude
// is 1 / (1 + 6 x 0.25) = 0.4, y and z share 0.6.
TEST(Sections, NormalMagnitudesNearAnEndFace)
{
  const std::string file = std::filesystem::temp_directory_path().string() + "/abrade_test_sections_box.stl";
  abrade::io::write_stl(file, box(0.5, 1.0));
  const auto n = abrade::io::normal_magnitudes_near(file, {1.0, 0.0, 0.5});
  EXPECT_NEAR(n[0], 0.4, 1e-6);
  EXPECT_NEAR(n[1] + n[2], 0.6, 1e-6);
  std::remove(file.c_str());
}
