#pragma once
// Step 2 of the lifetime loop: one cycle's wear volumes per seed (wear_source.h) become wear
// depth rates per surface vertex, per seed and their mean: filtered on the wearable surface
// (fem/surface_filter.h, volume conserving) and divided by the vertex areas (a third of the
// vertex's wearable triangles').
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/solid_surface.h>

#include <vector>

namespace abrade::coupling::lifetime
{
  struct Rates
  {
    std::vector<std::vector<double>> seed;  ///< per seed: wear depth per cycle at each vertex [m]
    std::vector<double>              mean;  ///< the seeds' mean
    double                           largest = 0;        ///< of the mean
    double                           wear_volume = 0; ///< per cycle, the seeds' mean [m^3] (Output/Wear field)
    std::vector<double>              seed_volume;        ///< per cycle and seed [m^3]
  };

  /// The depth rates of @p wear on @p surface, filtered over @p smoothing_radius (0: none).
  Rates depth_rates(const fem::SolidSurface &surface, const CycleWear &wear, double smoothing_radius);
} // namespace abrade::coupling::lifetime
