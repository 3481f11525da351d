#pragma once
// Whether a multi-level bed's fine region is wide enough around the worn walls' paths: the
// margin between a wall's path through the bed and a face of the fine box, against the depth the
// wall works at below the settled bed's surface (docs/coarse-graining.md, "Choosing the fine box").
#include <abrade/common/log.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/simulation.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// The margin recommended, in depths below the bed's surface: with 0.8 depths the multi-level
  /// beds' force over the first half of the knife's travel read 9 % below the uniform fine beds',
  /// with 1.2 depths 4 % below, with 1.6 depths 0.2 % above (docs/coarse-graining.md).
  inline constexpr double fine_region_margin_in_depths = 1.2;
  /// Below this many depths a run warns: the recommended 1.2 less the bed's surface's spread from
  /// bed to bed (the knife-bed's 0.345 m margin is 1.19-1.21 depths on the study's beds).
  inline constexpr double fine_region_margin_warning = 1.15;

  /// The box a wall sweeps over the phases of a cycle: the extremes, sampled
  /// @p samples_per_phase times a phase, of its part below the height @p below (its vertices
  /// there and where its triangles' edges cross the height: the part of the path in the bed;
  /// lower corner +inf where none is), or none where the path is
  /// not known beforehand (a rigid body's free motion, a wall a mechanism drives).
  std::optional<std::pair<dem::Vec3, dem::Vec3>> swept_box(const dem::Wall &wall, const std::vector<Phase> &phases,
                                                           double below = std::numeric_limits<double>::infinity(),
                                                           int    samples_per_phase = 200);

  /// The height of the bed's surface [m]: the median over the columns of the fill box's
  /// horizontal extent (@p fill, squares of two largest particle diameters) of the highest
  /// particle top in each (columns without particles left out; -max for an empty bed). Not the
  /// highest particle's top: a pellet resting on a heap or the container's edge stands 0.07 m
  /// above the knife-bed's surface. Collective.
  double bed_surface(const dem::Simulation &sim, const dem::FillRegion &fill);

  /// Logs, for each worn wall of @p c (Wear/Laws set) whose path is known (fixed or
  /// prescribed) and reaches below the settled bed's surface, its smallest horizontal margin to
  /// a face of the fine region beyond which the bulk's particles lie (a face on the fill box's
  /// has none) against the depth of its lowest point below the surface, with a warning under
  /// fine_region_margin_warning times; warnings too where the path reaches below the fine
  /// region's floor and where the fine region's top is below the fill box's (coarser particles
  /// poured above it settle over the path); a line for each worn wall whose path follows the
  /// loads (not checked). Nothing without a fine region or with gravity not along -z.
  /// Collective (the bed's surface is all ranks').
  void check_fine_region_margins(const DemCase &c, const dem::Simulation &sim, io::Log &log);
} // namespace abrade::coupling
