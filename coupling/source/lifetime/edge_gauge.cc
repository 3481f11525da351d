// The gauges of a worn edge along its length (edge_gauge.h).
#include <abrade/coupling/lifetime/edge_gauge.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace abrade::coupling::lifetime
{
  namespace
  {
    /// The segments (y, z)-(y, z) where the triangles of @p s cross the plane x = @p x, and the
    /// lowest point, through the cut edges (a vertex on the plane counts for both its edges).
    struct Section
    {
      std::vector<std::array<double, 4>> segments;
      dealii::Point<3>                   lowest;
      double                             top   = -std::numeric_limits<double>::infinity();
      bool                               empty = true;
    };

    Section cut(const fem::SolidSurface &s, double x)
    {
      Section r;
      double  low = std::numeric_limits<double>::infinity();
      for (const auto &t : s.triangles)
        {
          std::vector<dealii::Point<3>> points;
          for (int e = 0; e < 3; ++e)
            {
              const auto  &a = s.vertices[t[e]], &b = s.vertices[t[(e + 1) % 3]];
              const double da = a[0] - x, db = b[0] - x;
              if (da == 0)
                points.push_back(a);
              else if (da * db < 0)
                points.push_back(a + da / (da - db) * (b - a));
            }
          if (points.size() < 2)
            continue;
          r.segments.push_back({points[0][1], points[0][2], points[1][1], points[1][2]});
          for (const auto &p : points)
            r.top = std::max(r.top, p[2]);
          for (const auto &p : points)
            if (p[2] < low)
              low = p[2], r.lowest = p, r.empty = false;
        }
      return r;
    }

    /// Where the section crosses z = h: its smallest and largest y (equal: it does not reach h).
    std::pair<double, double> crossing_at(const Section &sec, double h)
    {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for (const auto &g : sec.segments)
        {
          const double za = g[1] - h, zb = g[3] - h;
          if (za * zb > 0 || (za == 0 && zb == 0))
            continue;
          const double y = za == zb ? g[0] : g[0] + za / (za - zb) * (g[2] - g[0]);
          lo = std::min(lo, y), hi = std::max(hi, y);
        }
      return hi > lo ? std::make_pair(lo, hi) : std::make_pair(0.0, 0.0);
    }

    double width_at(const Section &sec, double h)
    {
      const auto [lo, hi] = crossing_at(sec, h);
      return hi - lo;
    }
  } // namespace

  EdgeSections edge_sections(const fem::SolidSurface &s, double x0, double x1, int stations, double h,
                             double inset_fraction)
  {
    EdgeSections r;
    const double inset = inset_fraction * (x1 - x0);
    for (int k = 0; k < stations; ++k)
      {
        const double x   = x0 + inset + (x1 - x0 - 2 * inset) * k / std::max(1, stations - 1);
        const Section sec = cut(s, x);
        r.x.push_back(x);
        r.height.push_back(sec.empty ? std::numeric_limits<double>::infinity() : sec.lowest[2]);
        r.top.push_back(sec.top);
        r.lowest.push_back(sec.lowest);
        const auto [lo, hi] = crossing_at(sec, h);
        r.thickness.push_back(hi - lo), r.y_low.push_back(lo), r.y_high.push_back(hi);
      }
    return r;
  }

  std::pair<EdgeSections, EdgeSections> worn_and_design_sections(const fem::SolidSurface &worn,
                                                                 const fem::SolidSurface &design, int stations, double h,
                                                                 double inset)
  {
    double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
    for (const auto &p : worn.vertices)
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    const double f = std::min(0.25, inset / (x1 - x0));
    return {edge_sections(worn, x0, x1, stations, h, f), edge_sections(design, x0, x1, stations, h, f)};
  }

  double full_thickness_height(const fem::SolidSurface &design, double x0, double x1, double z0, double z1)
  {
    const Section sec = cut(design, 0.5 * (x0 + x1));
    const int     n   = 400;
    double        widest = 0;
    std::vector<double> w(n + 1);
    for (int k = 0; k <= n; ++k)
      widest = std::max(widest, w[k] = width_at(sec, z0 + (z1 - z0) * k / n));
    for (int k = 0; k <= n; ++k)
      if (w[k] >= (1 - 1e-6) * widest)
        return (z1 - z0) * k / n;
    return 0;
  }

  EdgeGauge gauge(const EdgeSections &worn, const EdgeSections &design)
  {
    EdgeGauge g;
    for (std::size_t k = 0; k < worn.x.size() && k < design.x.size(); ++k)
      {
        // a section the wear has cut away entirely has receded past everything: as far as
        // the design's section reaches (its top: the largest z of its lowest point's plane)
        const double r = std::isfinite(worn.height[k]) ? worn.height[k] - design.height[k]
                                                       : design.top[k] - design.height[k];
        if (r > g.recession)
          g.recession = r, g.recession_station = k;
        if (k == 0 || worn.thickness[k] < g.thinnest)
          g.thinnest = worn.thickness[k], g.thinnest_station = k;
      }
    return g;
  }
} // namespace abrade::coupling::lifetime
