#pragma once
// The preview's set-up picture: the part where the case places it, among the case's walls,
// with the particles' fill region, the domain and the path the part follows over one cycle
// (the part job's part/scene_*.dat and scene_part.vtp, summary.json results.part.case),
// drawn by gnuplot from four directions: oblique, from the side (x-z), from above (x-y) and
// from the front (y-z).
#include "surface_views.h"

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace abrade::report
{
  struct CaseSetupPicture
  {
    std::string           part_file;   ///< the placed part (.vtp) with its faces' role
    std::string           walls_file;  ///< the other walls' outlines: segments [m], blank-separated
    std::string           path_file;   ///< the path: a block of points [m] per phase
    std::array<double, 6> domain{}, fill_region{}; ///< min, max [m]
    /// each phase's name at the end of its leg [m]
    std::vector<std::pair<std::string, std::array<double, 3>>> phase_ends;
  };

  /// Draws @p setup into @p directory/@p png with the part coloured by @p roles (RenderOptions'
  /// categories); false (and no picture) when the part cannot be read or gnuplot fails.
  bool render_case_setup(const std::string &directory, const std::string &png, const CaseSetupPicture &setup,
                         const std::vector<std::pair<std::string, std::string>> &roles);
} // namespace abrade::report
