#pragma once
// Whether a multi-level bed's fine region is wide enough around the worn walls' paths: the
// margin between a wall's path and a face of the fine box, against the depth the wall works at
// below the settled bed's top (docs/coarse-graining.md, "Choosing the fine box").
#include <abrade/common/log.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/simulation.h>

#include <optional>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// The smallest margin wanted, in depths below the bed's top: with less, the multi-level beds'
  /// force over the first half of the knife's travel read 9 % (0.8 depths) and 4 % (1.2) below
  /// the uniform fine beds', 0.2 % above at 1.6 (docs/coarse-graining.md).
  inline constexpr double fine_region_margin_in_depths = 1.2;

  /// The box a wall sweeps over the phases of a cycle (its vertices' extremes, sampled
  /// @p samples_per_phase times a phase), or none where its path is not known beforehand (a
  /// rigid body's free motion, a wall a mechanism drives).
  std::optional<std::pair<dem::Vec3, dem::Vec3>> swept_box(const dem::Wall &wall, const std::vector<Phase> &phases,
                                                           int samples_per_phase = 200);

  /// The height of the bed's surface [m]: the median over the columns of the fill box's
  /// horizontal extent (@p fill, squares of two largest particle diameters) of the highest
  /// particle top in each (columns without particles left out). Not the highest particle's top:
  /// a pellet resting on the container's edge or on a heap stands 0.07 m above the knife-bed's
  /// surface. Collective.
  double bed_surface(const dem::Simulation &sim, const dem::FillRegion &fill);

  /// A worn wall's nearest approach to a face of the fine region that the bulk lies beyond.
  struct FineRegionMargin
  {
    std::string wall;
    int         axis   = 0;    ///< across which (0: x, 1: y)
    double      margin = 0;    ///< [m] from the wall's path to the fine region's face (< 0: beyond it)
    double      depth  = 0;    ///< [m] of the path's lowest point below the bed's surface
  };

  /// For each worn wall of @p c (Wear/Laws set) with a known path that reaches below @p surface
  /// (the settled bed's, bed_surface), its smallest horizontal margin to a face of the fine region beyond
  /// which the bulk's particles lie (a face on the fill box's has none). Empty without a fine
  /// region or with gravity not along -z.
  std::vector<FineRegionMargin> fine_region_margins(const DemCase &c, const dem::Simulation &sim, double surface);

  /// Logs each margin of fine_region_margins; a warning where it is under
  /// fine_region_margin_in_depths times the depth. Collective (the bed's surface is all ranks').
  void check_fine_region_margins(const DemCase &c, const dem::Simulation &sim, io::Log &log);
} // namespace abrade::coupling
