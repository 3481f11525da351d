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
            parse(0);
            rate.value(dealii::Point<3>());
          }
        catch (const std::exception &)
          {
            throw std::invalid_argument("cannot evaluate '" + expression +
                                        "' as a function of x, y, z, t and zlow");
          }
      }

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        CycleWear w;
        w.tonnes_per_cycle = tonnes_per_cycle;
        const auto area = fem::vertex_areas(surface, fem::KnifeGeometry::wearable_boundary);
        // zlow: the lowest wearable point now (a band on the edge line that follows the tip up)
        double zlow = std::numeric_limits<double>::max();
        for (std::size_t v = 0; v < area.size(); ++v)
          if (area[v] > 0)
            zlow = std::min(zlow, surface.vertices[v][2]);
        parse(zlow < std::numeric_limits<double>::max() ? zlow : 0.0);
        rate.set_time(tonnes);
        std::vector<double> volume(surface.vertices.size(), 0.0);
        for (std::size_t v = 0; v < volume.size(); ++v)
          if (area[v] > 0)
            {
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
      void parse(double zlow)
      {
        rate.initialize("x,y,z,t", expression, {{"zlow", zlow}}, true);
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
