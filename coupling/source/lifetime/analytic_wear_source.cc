// The analytic wear source (Lifetime/Wear source = analytic): a known rate instead of the DEM,
// for verification of the loop (tests/lifetime/).
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/knife_geometry.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/base/function_parser.h>

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
    class AnalyticWearSource : public WearSource
    {
    public:
      AnalyticWearSource(const std::string &expression, double tonnes_per_cycle, double scatter, bool as_volume)
        : expression(expression), tonnes_per_cycle(tonnes_per_cycle), scatter(scatter), as_volume(as_volume)
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
        const auto area = fem::vertex_areas(surface, fem::KnifeGeometry::wearable_boundary);
        // zlow: the lowest wearable point now (a band on the edge that follows the tip up);
        // zedge: the lowest wearable point of the knife's slice through the point (slices of
        // the edge length across x, as thick as the wearable points lie apart along the edge:
        // a band on the edge line that follows each part of the edge up as it recedes there)
        double              zlow = std::numeric_limits<double>::max();
        std::vector<double> zedge(surface.vertices.size(), 0.0);
        std::vector<double> slice_low;
        double              x0 = std::numeric_limits<double>::max(), x1 = -x0, width = 0;
        for (std::size_t v = 0; v < area.size(); ++v)
          if (area[v] > 0)
            {
              zlow = std::min(zlow, surface.vertices[v][2]);
              x0 = std::min(x0, surface.vertices[v][0]), x1 = std::max(x1, surface.vertices[v][0]);
            }
        double edges = 0;
        for (const auto &t : surface.triangles)
          for (int e = 0; e < 3; ++e)
            edges += surface.vertices[t[e]].distance(surface.vertices[t[(e + 1) % 3]]);
        if (x1 > x0 && edges > 0) // slices of the triangles' mean edge length
          {
            const double mean_edge = edges / (3.0 * double(surface.triangles.size()));
            slice_low.assign(std::max(1.0, std::round((x1 - x0) / mean_edge)), std::numeric_limits<double>::max());
            width = (x1 - x0) / double(slice_low.size());
          }
        auto slice = [&](double x) {
          return std::min(slice_low.size() - 1, std::size_t(std::max(0.0, (x - x0) / width)));
        };
        for (std::size_t v = 0; !slice_low.empty() && v < area.size(); ++v)
          if (area[v] > 0)
            slice_low[slice(surface.vertices[v][0])] = std::min(slice_low[slice(surface.vertices[v][0])],
                                                                surface.vertices[v][2]);
        for (std::size_t v = 0; v < area.size(); ++v)
          zedge[v] = slice_low.empty() ? zlow : slice_low[slice(surface.vertices[v][0])];
        std::vector<double> volume(surface.vertices.size(), 0.0);
        double              parsed_edge = std::numeric_limits<double>::quiet_NaN();
        for (std::size_t v = 0; v < volume.size(); ++v)
          if (area[v] > 0)
            {
              if (!(zedge[v] == parsed_edge)) // (one parse per slice)
                {
                  parse(zlow, zedge[v]);
                  rate.set_time(tonnes);
                  parsed_edge = zedge[v];
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
    };
  } // namespace

  std::unique_ptr<WearSource> make_analytic_wear_source(const std::string &expression, double tonnes_per_cycle,
                                                        double seed_scatter, bool as_volume)
  {
    return std::make_unique<AnalyticWearSource>(expression, tonnes_per_cycle, seed_scatter, as_volume);
  }
} // namespace abrade::coupling::lifetime
