// Coarse graining: larger particles standing for many, with the scaled properties and wear
// (coarse_graining.h).
#include <abrade/common/format_number.h>
#include <abrade/dem/coarse_graining.h>

#include <algorithm>
#include <cmath>
#include <limits>
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

  std::vector<double> level_factors(const double fine, const double bulk, const double step)
  {
    if (step > 0 && step < 1.05)
      throw std::invalid_argument("a step between the levels' factors below 1.05 makes thousands of levels");
    const int n = step > 1 && bulk / fine > step ? int(std::ceil(std::log(bulk / fine) / std::log(step) - 1e-9)) : 1;
    std::vector<double> out;
    for (int k = 0; k < n; ++k)
      out.push_back(fine * std::pow(bulk / fine, double(k) / n));
    return out;
  }

  std::vector<Level> split_into_levels(FillRegion &fill, const FineRegion &region, const double bulk_factor)
  {
    const auto box_volume = [](const Vec3 &lo, const Vec3 &hi) { return (hi - lo).cwiseMax(0.0).prod(); };
    const Vec3 lo = region.lo.cwiseMax(fill.box_min), hi = region.hi.cwiseMin(fill.box_max);
    if (fill.inside || !(lo.array() < hi.array()).all())
      throw std::invalid_argument("the fine region must overlap the fill box (and the fill have no region mesh)");
    const double per_volume = double(fill.count) / box_volume(fill.box_min, fill.box_max); // real particles
    std::vector<Level> levels;
    Vec3               inner_lo = lo, inner_hi = hi; // the region the next level surrounds
    long               taken    = 0;
    for (const double f : level_factors(region.factor, bulk_factor, region.step))
      {
        Level level{fill, f, box_volume(lo, hi)};
        auto &part = level.fill; // whole in the fill box, the centres in the level's region
        if (levels.empty())
          part.centres_in = std::make_pair(lo, hi);
        else // a shell around the finer levels, touching them
          {
            const double t = region.layer_diameters * 2 * fill.sizes.largest() * f;
            const Vec3   shell_lo = (inner_lo.array() - t).matrix().cwiseMax(fill.box_min);
            const Vec3   shell_hi = (inner_hi.array() + t).matrix().cwiseMin(fill.box_max);
            // a shell cut by the fill box's face would be too thin to place its particles in:
            // the levels grow only where the box does not reach that face
            for (int d = 0; d < 3; ++d)
              if ((inner_lo[d] > fill.box_min[d] && shell_lo[d] != inner_lo[d] - t) ||
                  (inner_hi[d] < fill.box_max[d] && shell_hi[d] != inner_hi[d] + t))
                throw std::invalid_argument("the shell of particles coarse-grained by " + io::format_number(f, 4) + " (" +
                                            io::format_number(t, 3) + " m thick) reaches a face of the fill box across " +
                                            std::string(1, char('x' + d)) + ": extend the fine region to that face, or leave "
                                            "room for its shells and the bulk");
            part.centres_in = std::make_pair(shell_lo, shell_hi);
            part.exclude.emplace_back(inner_lo, inner_hi);
            level.volume = box_volume(shell_lo, shell_hi) - box_volume(inner_lo, inner_hi);
            inner_lo = shell_lo, inner_hi = shell_hi;
          }
        part.count = fill.count > 0 ? std::max(1L, std::lround(per_volume * level.volume)) : 0; // 0: the solid fraction
        part.seed  = level_seed(fill.seed, levels.size()); // its own draws
        taken += part.count;
        Settings unused; // (the skin is the caller's)
        coarse_grain(f, part, unused);
        levels.push_back(level);
      }
    // the rest: its centres out of the outermost box, touching it; a gap to a face of the fill
    // box narrower than its particles' diameter would stay empty (no centre fits in it)
    const double d_bulk = 2 * fill.sizes.largest() * bulk_factor;
    bool         room   = false;
    for (int d = 0; d < 3; ++d)
      for (const double gap : {inner_lo[d] - fill.box_min[d], fill.box_max[d] - inner_hi[d]})
        {
          if (gap > 0 && gap < d_bulk)
            throw std::invalid_argument("the fine region and its shells leave a gap of " + io::format_number(gap, 3) +
                                        " m to a face of the fill box across " + std::string(1, char('x' + d)) +
                                        ", narrower than a bulk particle (" + io::format_number(d_bulk, 3) +
                                        " m): extend the fine region to that face or leave a bulk particle's room");
          room = room || gap > 0;
        }
    if (!room || (fill.count > 0 && fill.count - taken < 1))
      throw std::invalid_argument("the fine region and its shells fill the fill box in every direction, leaving no "
                                  "room for the bulk's particles: make the fine region or its shells smaller");
    fill.count -= taken;
    fill.centres_in = std::make_pair(fill.box_min, fill.box_max);
    fill.exclude.emplace_back(inner_lo, inner_hi);
    return levels;
  }

  void reseed(FillRegion &fill, std::vector<Level> &levels, const std::uint64_t seed)
  {
    fill.seed = seed;
    for (std::size_t k = 0; k < levels.size(); ++k)
      levels[k].fill.seed = level_seed(seed, k);
  }

  std::size_t footprint_of(const std::vector<Level> &levels, const double x, const double y)
  {
    constexpr double inf = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < levels.size(); ++k)
      {
        const FillRegion &f = levels[k].fill;
        if (!f.centres_in)
          continue;
        const auto &[lo, hi] = *f.centres_in;
        const double x0 = lo[0] <= f.box_min[0] ? -inf : lo[0], x1 = hi[0] >= f.box_max[0] ? inf : hi[0];
        const double y0 = lo[1] <= f.box_min[1] ? -inf : lo[1], y1 = hi[1] >= f.box_max[1] ? inf : hi[1];
        if (x >= x0 && x <= x1 && y >= y0 && y <= y1)
          return k;
      }
    return levels.size();
  }

  std::vector<double> footprint_masses(const std::vector<Level> &levels, const ParticleStore &P)
  {
    std::vector<double> mass(levels.size() + 1, 0.0);
    for (std::size_t i = 0; i < P.size(); ++i)
      mass[footprint_of(levels, P.x[i], P.y[i])] += P.mass[i];
    return mass;
  }

  std::vector<long> refill_counts(const std::vector<long> &counts, const std::vector<double> &mean_mass,
                                  const std::vector<double> &wanted, const std::vector<double> &settled)
  {
    if (counts.empty() || mean_mass.size() != counts.size() || wanted.size() != counts.size() ||
        settled.size() != counts.size())
      throw std::invalid_argument("refill_counts: one count, mean mass and footprint mass per level, the bulk's last");
    std::vector<long> out = counts;
    const std::size_t bulk  = counts.size() - 1;
    double            added = 0; // mass, taken from the bulk
    for (std::size_t k = 0; k < bulk; ++k)
      if (const double lack = wanted[k] - settled[k]; lack > 0 && mean_mass[k] > 0)
        {
          const long n = std::lround(lack / mean_mass[k]);
          out[k] += n, added += n * mean_mass[k];
        }
    if (mean_mass[bulk] > 0)
      out[bulk] = std::max(1L, counts[bulk] - std::lround(added / mean_mass[bulk])); // (0: the solid fraction)
    return out;
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
