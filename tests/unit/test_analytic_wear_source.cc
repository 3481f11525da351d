// The analytic wear source's variables of the knife's current shape (Lifetime/Analytic/Wear rate,
// coupling/source/lifetime/analytic_wear_source.cc), against a surface whose answer is known: a
// chisel of length 0.15 m, 30 mm thick, 40 mm bevel, sheared so that its edge line is a V along
// x (z = s |x - 75 mm|, s = 0.2: 15 mm up at both ends). Every cut x = const is the same section
// shifted up by s |x - 75 mm|, so the lowest wearable point within a distance w of a point along
// x (zedge, w the longest edge of the wearable triangles) is exactly s max(0, |x - 75 mm| - w):
// on one half of the knife the window's lower end finds it, on the other its upper end (a
// one-sided window fails on one half); the lowest wearable point of the knife is the V's apex,
// z = 0 (zlow). The edge line has vertices every 20 mm and the bevel's upper rims every 7 mm
// (both with one at the apex), so most cuts hold no edge vertex (a zedge taken from the vertices
// of slices a triangle edge thick was off by up to 6 mm, and this test fails on it). The rate 'zedge + 1' (or 'zlow + 1'), as a depth per tonne, gives each vertex the
// volume (zedge + 1) x tonnes x its area, from which zedge is read back.
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/part_boundary.h>
#include <abrade/fem/surface_filter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace abrade;
using abrade::coupling::lifetime::make_analytic_wear_source;

namespace
{
  constexpr double length = 0.15, half_thickness = 0.015, bevel = 0.04, slope = 0.2;

  constexpr double apex = 0.5 * length;

  /// 0, step, 2 step, ... and the apex and the end
  std::vector<double> stations(double step)
  {
    std::vector<double> x;
    for (double s = 0; s < length - 1e-9; s += step)
      {
        if (x.size() > 0 && x.back() < apex - 1e-9 && s > apex + 1e-9)
          x.push_back(apex);
        if (std::abs(s - apex) > 1e-9)
          x.push_back(s);
      }
    x.push_back(length);
    return x;
  }

  /// The two bevel faces (wearable) between the edge line and their upper rims, and the strip
  /// between the rims (clamped), each face zipped between two polylines by x.
  fem::SolidSurface sheared_chisel()
  {
    fem::SolidSurface s;
    auto line = [&](const std::vector<double> &xs, double y, double z) {
      std::vector<unsigned> ids;
      for (double x : xs)
        {
          ids.push_back(unsigned(s.vertices.size()));
          s.vertices.emplace_back(x, y, z + slope * std::abs(x - apex));
        }
      return ids;
    };
    const auto edge = line(stations(0.02), 0, 0);
    const auto plus = line(stations(0.007), half_thickness, bevel);
    const auto minus = line(stations(0.007), -half_thickness, bevel);
    auto zip = [&](const std::vector<unsigned> &a, const std::vector<unsigned> &b, dealii::types::boundary_id id) {
      std::size_t i = 0, j = 0;
      while (i + 1 < a.size() || j + 1 < b.size())
        {
          const bool along_a = j + 1 == b.size() || (i + 1 < a.size() && s.vertices[a[i + 1]][0] <= s.vertices[b[j + 1]][0]);
          if (along_a)
            s.triangles.push_back({a[i], b[j], a[i + 1]}), ++i;
          else
            s.triangles.push_back({a[i], b[j], b[j + 1]}), ++j;
          s.boundary_id.push_back(id);
        }
    };
    zip(edge, plus, fem::wearable_boundary);
    zip(edge, minus, fem::wearable_boundary);
    zip(plus, minus, fem::clamped_boundary);
    return s;
  }

  /// The rate @p expression at every wearable vertex, read back from the volumes of one cycle.
  std::vector<std::pair<double, double>> rate_at_vertices(const fem::SolidSurface &s, const std::string &expression)
  {
    const double tonnes = 2;
    auto         source = make_analytic_wear_source(expression, tonnes, 0.0, false);
    const auto   wear   = source->cycle(s, 0.0, {1});
    const auto   area   = fem::vertex_areas(s, fem::wearable_boundary);
    std::vector<std::pair<double, double>> out; // x, rate
    for (std::size_t v = 0; v < area.size(); ++v)
      if (area[v] > 0)
        out.emplace_back(s.vertices[v][0], wear.seed_volume.at(0)[v] / (tonnes * area[v]));
    return out;
  }
} // namespace

TEST(AnalyticWearSource, ZedgeIsTheLowestPointWithinALongestEdgeAlongX)
{
  const auto s = sheared_chisel();
  const auto r = rate_at_vertices(s, "zedge + 1");
  ASSERT_GT(r.size(), 40u);
  double w = 0; // the longest edge of a wearable triangle
  for (std::size_t t = 0; t < s.triangles.size(); ++t)
    if (s.boundary_id[t] == fem::wearable_boundary)
      for (int e = 0; e < 3; ++e)
        w = std::max(w, s.vertices[s.triangles[t][e]].distance(s.vertices[s.triangles[t][(e + 1) % 3]]));
  ASSERT_GT(w, 0.04);
  double worst = 0;
  for (const auto &[x, rate] : r)
    worst = std::max(worst, std::abs(rate - 1 - slope * std::max(0.0, std::abs(x - apex) - w)));
  // the cuts are exact at stations 1/400 of the length apart; a point takes its nearest one's
  // (half a spacing), the window ends at a station (one more)
  EXPECT_LT(worst, 1.5 * slope * length / 399 + 1e-12) << "zedge off the sheared edge line by " << worst << " m";
}

TEST(AnalyticWearSource, ZlowIsTheLowestWearablePoint)
{
  const auto s = sheared_chisel();
  for (const auto &[x, rate] : rate_at_vertices(s, "zlow + 1"))
    EXPECT_NEAR(rate, 1.0, 1e-12) << "at x = " << x;
}
