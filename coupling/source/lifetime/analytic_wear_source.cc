// The analytic wear source (Lifetime/Wear source = analytic): a known rate instead of the DEM,
// for verification of the loop (tests/lifetime/).
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/part_boundary.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/base/function_parser.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <limits>
#include <stdexcept>

namespace abrade::coupling::lifetime
{
  double standard_normal_of_seed(int seed)
  {
    std::mt19937_64 random(static_cast<std::uint64_t>(seed) * 0x9E3779B97F4A7C15ULL + 12345);
    const double    u1 = (double(random() >> 11) + 1) * 0x1.0p-53; // (0, 1]
    const double    u2 = double(random() >> 11) * 0x1.0p-53;       // [0, 1)
    return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * u2);
  }

  namespace
  {
    /// The heights the rate's variables zlow and zedge stand for on the part's current shape.
    /// zlow: the lowest wearable point now (a band on the edge that follows the tip up). zedge:
    /// the lowest wearable point within a longest triangle edge of the point along x (a band on
    /// the edge line that follows each part of the edge up as it recedes there): the lowest
    /// point of the surface's exact cuts with the planes x = const (each wearable triangle's
    /// segment in the plane) at stations 1/400 of the wearable length apart, the least of those
    /// within that distance; a point takes its nearest station's. The window reaches past the
    /// knife's rounded ends: from the cut alone the end cap is its own lowest point, its whole
    /// height wears, and the ends run away along x. Where nothing is cut (a part of no extent in
    /// x) zedge is zlow.
    class EdgeHeights
    {
    public:
      static constexpr std::size_t stations = 400;

      EdgeHeights(const fem::SolidSurface &surface, const std::vector<double> &area)
      {
        for (std::size_t v = 0; v < area.size(); ++v)
          if (area[v] > 0)
            {
              zlow = std::min(zlow, surface.vertices[v][2]);
              x0 = std::min(x0, surface.vertices[v][0]), x1 = std::max(x1, surface.vertices[v][0]);
            }
        spacing = x1 > x0 ? (x1 - x0) / double(stations - 1) : 1.0;
        std::vector<double> lowest(stations, none);
        double              longest = 0;
        for (std::size_t t = 0; t < surface.triangles.size(); ++t)
          {
            if (surface.boundary_id[t] != fem::wearable_boundary)
              continue;
            const auto &tri = surface.triangles[t];
            const auto &a = surface.vertices[tri[0]], &b = surface.vertices[tri[1]], &c = surface.vertices[tri[2]];
            longest = std::max({longest, a.distance(b), b.distance(c), c.distance(a)});
            const double lo = std::min({a[0], b[0], c[0]}), hi = std::max({a[0], b[0], c[0]});
            for (long k = std::max(0L, long(std::ceil((lo - x0) / spacing)));
                 x1 > x0 && k < long(stations) && x0 + double(k) * spacing <= hi; ++k)
              {
                const double x = x0 + double(k) * spacing;
                double       z = none;
                for (const auto &[p, q] : {std::pair(&a, &b), std::pair(&b, &c), std::pair(&c, &a)})
                  {
                    const double u = (*p)[0], w = (*q)[0];
                    if (u == x)
                      z = std::min(z, (*p)[2]);
                    if ((u - x) * (w - x) < 0)
                      z = std::min(z, (*p)[2] + ((*q)[2] - (*p)[2]) * (x - u) / (w - u));
                  }
                lowest[std::size_t(k)] = std::min(lowest[std::size_t(k)], z);
              }
          }
        // the least within a longest edge of each station
        window.assign(stations, none);
        const long reach = long(std::ceil(longest / spacing));
        for (long k = 0; k < long(stations); ++k)
          for (long j = std::max(0L, k - reach); j <= std::min(long(stations) - 1, k + reach); ++j)
            if (std::abs(double(j - k)) * spacing <= longest * (1 + 1e-12))
              window[std::size_t(k)] = std::min(window[std::size_t(k)], lowest[std::size_t(j)]);
      }

      /// The station nearest @p x.
      std::size_t station(double x) const
      {
        return std::size_t(std::clamp(std::round((x - x0) / spacing), 0.0, double(stations - 1)));
      }

      /// zedge at station @p k.
      double zedge(std::size_t k) const { return window[k] < none ? window[k] : zlow; }

      double zlow = std::numeric_limits<double>::max();

    private:
      static constexpr double none = std::numeric_limits<double>::max();
      double                  x0 = std::numeric_limits<double>::max(), x1 = -x0, spacing = 1;
      std::vector<double>     window;
    };

    class AnalyticWearSource : public WearSource
    {
    public:
      AnalyticWearSource(const std::string &expression, double tonnes_per_cycle, double scatter, bool as_volume)
        : expression(expression), tonnes_per_cycle(tonnes_per_cycle), scatter(scatter), as_volume(as_volume),
          uses_zedge(expression.find("zedge") != std::string::npos)
      {
        try
          {
            parse(0, 0);
            rate.value(dealii::Point<3>());
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument("cannot evaluate '" + expression +
                                        "' as a function of x, y, z, t, zlow and zedge");
          }
      }

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        CycleWear w;
        w.tonnes_per_cycle = tonnes_per_cycle;
        const auto        area = fem::vertex_areas(surface, fem::wearable_boundary);
        const EdgeHeights heights(surface, area);
        std::vector<double> volume(surface.vertices.size(), 0.0);
        // the points by station: one parse of the rate per station (zedge a constant of it), or
        // one for all where the rate does not use zedge
        std::vector<std::size_t> order;
        for (std::size_t v = 0; v < area.size(); ++v)
          if (area[v] > 0)
            order.push_back(v);
        if (uses_zedge)
          std::stable_sort(order.begin(), order.end(), [&](std::size_t p, std::size_t q) {
            return heights.station(surface.vertices[p][0]) < heights.station(surface.vertices[q][0]);
          });
        std::size_t parsed = EdgeHeights::stations;
        for (const std::size_t v : order)
          {
            if (const std::size_t k = uses_zedge ? heights.station(surface.vertices[v][0]) : 0; k != parsed)
              {
                parse(heights.zlow, heights.zedge(k));
                rate.set_time(tonnes);
                parsed = k;
              }
            const double r = rate.value(surface.vertices[v]);
            if (!(r >= 0) || !std::isfinite(r))
              {
                const auto &p = surface.vertices[v];
                throw std::domain_error("the rate is " + io::format_number(r) + " at (" + io::format_number(p[0]) +
                                        ", " + io::format_number(p[1]) + ", " + io::format_number(p[2]) + ") after " +
                                        io::format_number(tonnes) + " t: a wear rate is a finite number >= 0 [m/t]");
              }
            volume[v] = r * tonnes_per_cycle * area[v];
          }
        for (int seed : bed_seeds)
          {
            // lognormal, mean 1, relative standard deviation `scatter`: never negative
            const double sigma = std::sqrt(std::log1p(scatter * scatter));
            const double f     = std::exp(sigma * standard_normal_of_seed(seed) - 0.5 * sigma * sigma);
            w.seed_volume.push_back(volume);
            for (double &x : w.seed_volume.back())
              x *= f;
          }
        return w;
      }

      std::vector<std::string> phases() const override { return {}; }

      bool removes_volume() const override { return as_volume; }

    private:
      void parse(double zlow, double zedge)
      {
        rate.initialize("x,y,z,t", expression, {{"zlow", zlow}, {"zedge", zedge}}, true);
      }

      std::string               expression;
      dealii::FunctionParser<3> rate;
      double                    tonnes_per_cycle;
      double                    scatter; // relative, per bed
      bool                      as_volume;
      bool                      uses_zedge; // (else one parse for all points)
    };
  } // namespace

  std::unique_ptr<WearSource> make_analytic_wear_source(const std::string &expression, double tonnes_per_cycle,
                                                        double seed_scatter, bool as_volume)
  {
    return std::make_unique<AnalyticWearSource>(expression, tonnes_per_cycle, seed_scatter, as_volume);
  }
} // namespace abrade::coupling::lifetime
