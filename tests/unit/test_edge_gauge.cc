// The gauges of a worn edge (coupling/include/abrade/coupling/lifetime/edge_gauge.h) on chisels
// whose sections are known: a pentagon (tip at z = tip(x), bevel top at 40 mm, faces at
// y = +-w(x), top at 250 mm) extruded along x from 0 to 1 m, its tip and faces linear in x.
// The edge height at a station is tip(x), the plate's width at the gauge height 2 w(x); the
// worst stations are the ends, a thousandth of the length inside (the corners are gauged).
#include <abrade/coupling/lifetime/edge_gauge.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace abrade;
using namespace abrade::coupling::lifetime;

namespace
{
  /// The chisel with tip height tip0 / tip1 and half-width w0 / w1 at x = 0 / 1.
  fem::SolidSurface chisel(double tip0, double tip1, double w0, double w1)
  {
    fem::SolidSurface s;
    auto              section = [](double tip, double w, double x) {
      return std::vector<dealii::Point<3>>{dealii::Point<3>(x, 0, tip), dealii::Point<3>(x, w, 0.04),
                                           dealii::Point<3>(x, w, 0.25), dealii::Point<3>(x, -w, 0.25),
                                           dealii::Point<3>(x, -w, 0.04)};
    };
    for (const auto &p : section(tip0, w0, 0))
      s.vertices.push_back(p);
    for (const auto &p : section(tip1, w1, 1))
      s.vertices.push_back(p);
    for (unsigned k = 0; k < 5; ++k) // the sides, two triangles each
      {
        const unsigned a = k, b = (k + 1) % 5;
        s.triangles.push_back({a, b, b + 5});
        s.triangles.push_back({a, b + 5, a + 5});
      }
    for (unsigned k = 1; k + 1 < 5; ++k) // the end caps, fans
      {
        s.triangles.push_back({0, k + 1, k});
        s.triangles.push_back({5, 5 + k, 5 + k + 1});
      }
    s.boundary_id.assign(s.triangles.size(), 0);
    return s;
  }
} // namespace

TEST(EdgeGauge, TheDesignsEdgeAndPlate)
{
  const auto         design = chisel(0, 0, 0.015, 0.015);
  // the first grid height (400 steps of 0.09 / 400) at or above the bevel's top
  const double h = full_thickness_height(design, 0, 1, 0, 0.09);
  EXPECT_GE(h, 0.04 - 1e-12);
  EXPECT_LT(h, 0.04 + 0.09 / 400);
  const EdgeSections d = edge_sections(design, 0, 1, 11, 0.02, 1e-3);
  ASSERT_EQ(d.x.size(), 11u);
  EXPECT_NEAR(d.x.front(), 0.001, 1e-12);
  EXPECT_NEAR(d.x.back(), 0.999, 1e-12);
  for (std::size_t k = 0; k < d.x.size(); ++k)
    {
      EXPECT_NEAR(d.height[k], 0, 1e-12);
      EXPECT_NEAR(d.thickness[k], 0.015, 1e-12); // half way up the bevel
    }
  const EdgeGauge g = gauge(d, d);
  EXPECT_EQ(g.recession, 0);
  EXPECT_NEAR(g.thinnest, 0.015, 1e-12);
}

TEST(EdgeGauge, TheWorstStationIsTheCornerWhereTheEdgeRoseMost)
{
  const double       h = 0.04;
  const EdgeSections d = edge_sections(chisel(0, 0, 0.015, 0.015), 0, 1, 41, h, 1e-3);
  // the edge risen 10 mm at x = 0, nothing at x = 1; the plate 10 mm thinner at x = 0
  const EdgeSections w = edge_sections(chisel(0.01, 0, 0.010, 0.015), 0, 1, 41, h, 1e-3);
  for (std::size_t k = 0; k < w.x.size(); ++k)
    {
      EXPECT_NEAR(w.height[k], 0.01 * (1 - w.x[k]), 1e-12);
      EXPECT_NEAR(w.thickness[k], 2 * (0.015 - 0.005 * (1 - w.x[k])), 1e-12);
    }
  const EdgeGauge g = gauge(w, d);
  EXPECT_EQ(g.recession_station, 0u);
  EXPECT_NEAR(g.recession, 0.01 * 0.999, 1e-12);
  EXPECT_EQ(g.thinnest_station, 0u);
  EXPECT_NEAR(g.thinnest, 2 * (0.015 - 0.005 * 0.999), 1e-12);
  // the other way round: the far corner
  // the stations follow the worn part's own length: a part worn back 0.1 m at x = 0 is gauged
  // from 0.1 m on (its design there too)
  fem::SolidSurface shorter = chisel(0.01, 0, 0.010, 0.015);
  for (auto &p : shorter.vertices)
    if (p[0] == 0)
      p[0] = 0.1;
  const auto [ws, ds] = worn_and_design_sections(shorter, chisel(0, 0, 0.015, 0.015), 41, h, 0.009);
  EXPECT_NEAR(ws.x.front(), 0.1 + 0.009, 1e-12);
  EXPECT_NEAR(ds.x.front(), ws.x.front(), 1e-15);
  EXPECT_NEAR(gauge(ws, ds).recession, 0.01 * (1 - 0.009 / 0.9), 1e-12);
  const EdgeGauge f = gauge(edge_sections(chisel(0, 0.004, 0.015, 0.012), 0, 1, 41, h, 1e-3), d);
  EXPECT_EQ(f.recession_station, 40u);
  EXPECT_NEAR(f.recession, 0.004 * 0.999, 1e-12);
  EXPECT_EQ(f.thinnest_station, 40u);
}

TEST(EdgeGauge, APlateWornAwayAtTheGaugeHeightHasNoThickness)
{
  // the tip risen above the gauge height at x = 0
  const EdgeSections w = edge_sections(chisel(0.03, 0.03, 0.015, 0.015), 0, 1, 5, 0.02, 1e-3);
  for (double t : w.thickness)
    EXPECT_EQ(t, 0);
}
