// Coarse graining: larger particles standing for many, with the scaled properties and wear
// (coarse_graining.h).
#include <abrade/common/format_number.h>
#include <abrade/dem/coarse_graining.h>

#include <cmath>
#include <stdexcept>

namespace abrade::dem
{
  double coarse_grain(const double f, FillRegion &fill, Settings &settings)
  {
    if (!(f > 0) || !std::isfinite(f))
      throw std::invalid_argument("coarse-graining ratio must be positive and finite");
    auto &s  = fill.sizes;
    s.radius *= f, s.min *= f, s.max *= f, s.std *= f;
    settings.skin *= f; // 0 (automatic: a fraction of the smallest radius) stays 0
    const double count = double(fill.count) / (f * f * f);
    if (fill.count > 0)
      fill.count = std::max(1L, std::lround(count));
    return count;
  }

  FillRegion split_off_region(FillRegion &fill, const Vec3 &lo, const Vec3 &hi)
  {
    FillRegion part = fill;
    part.box_min    = lo.cwiseMax(fill.box_min), part.box_max = hi.cwiseMin(fill.box_max);
    if (fill.inside || !(part.box_min.array() < part.box_max.array()).all())
      throw std::invalid_argument("the fine region must overlap the fill box (and the fill have no region mesh)");
    const double share = (part.box_max - part.box_min).prod() / (fill.box_max - fill.box_min).prod();
    part.count         = std::lround(double(fill.count) * share);
    part.seed          = fill.seed + 1000003; // its own draws
    fill.count -= part.count;
    fill.exclude.emplace_back(part.box_min, part.box_max);
    return part;
  }

  std::vector<std::string> coarse_graining_warnings(const double f, const Settings &settings)
  {
    std::vector<std::string> out;
    if (f == 1)
      return out;
    if (settings.time_step > 0)
      out.push_back("Simulation/Time step is fixed (" + io::format_number(settings.time_step) +
                    " s) while the particles are coarse-grained by " + io::format_number(f) +
                    ": the stable step scales with the radius; 0 (a fraction of the Rayleigh time) follows it");
    if (settings.contact.cohesion != "none")
      out.push_back("Simulation/Cohesion model = " + settings.contact.cohesion + " with particles coarse-grained by " +
                    io::format_number(f) + ": the attraction grows as the contact area (f^2) and the weight as f^3, "
                    "so the bed is 1/f as cohesive as the real material unless Cohesion energy density is scaled by f");
    return out;
  }
} // namespace abrade::dem
