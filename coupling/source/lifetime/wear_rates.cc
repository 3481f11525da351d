// One cycle's wear volumes per seed turned into wear depth rates per vertex (wear_rates.h).
#include <abrade/coupling/lifetime/wear_rates.h>
#include <abrade/fem/part_boundary.h>
#include <abrade/fem/surface_filter.h>

#include <algorithm>
#include <numeric>

namespace abrade::coupling::lifetime
{
  Rates depth_rates(const fem::SolidSurface &surface, const CycleWear &wear, double smoothing_radius)
  {
    const int  wearable = fem::wearable_boundary;
    const auto area     = fem::vertex_areas(surface, wearable);
    Rates      r;
    r.mean.assign(surface.vertices.size(), 0.0);
    for (const auto &volume : wear.seed_volume)
      {
        std::vector<double> depth = fem::filter_on_surface(surface, volume, smoothing_radius, wearable);
        for (std::size_t v = 0; v < depth.size(); ++v)
          {
            depth[v] = area[v] > 0 ? depth[v] / area[v] : 0.0;
            r.mean[v] += depth[v] / wear.seed_volume.size();
          }
        r.seed.push_back(std::move(depth));
        r.seed_volume.push_back(std::accumulate(volume.begin(), volume.end(), 0.0)); // the source's volume
        r.wear_volume += r.seed_volume.back() / wear.seed_volume.size();
      }
    r.largest = r.mean.empty() ? 0.0 : *std::max_element(r.mean.begin(), r.mean.end());
    return r;
  }
} // namespace abrade::coupling::lifetime
