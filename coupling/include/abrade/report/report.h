#pragma once
// The run report: one self-contained HTML page per run (report.html in the run's directory), with
// every picture inlined, that opens in any browser without a network and prints well. It is
// written at the end of lifetime, sweep, concepts, compare and calibrate runs, and again by
// `abrade report RUN_DIR`. What it shows depends on the run (docs/user-guide.md, "The run
// report"):
//
//  - lifetime: the headline (predicted tonnes to end of life with its interval, the criterion
//    that ends it and where), the trajectory with its band, the worn knife coloured by wear
//    depth from two views at the design, mid-life and the end, the profile cross-sections, a
//    table per update, the run's warnings, and the parameters and provenance;
//  - concepts and sweep: the comparison table with its uncertainties, the plots, and the worn
//    shapes side by side;
//  - compare and calibrate: the numbers, the deviation and calibration plots, the fitted W with
//    its interval.
//
// The pictures of worn parts are drawn by gnuplot (pm3d, off-screen, a Debian package the
// project already uses) from the run's VTK files, with a colour bar in mm.
#include <string>
#include <vector>

namespace abrade::report
{
  /// Writes @p directory/report.html for the run in @p directory and returns its path. Throws
  /// InputError when the directory holds no run abrade knows. @p missing: the pictures the page
  /// should show but could not (gnuplot failed, a file was missing; the page says so where each
  /// would be), by file name.
  std::string write_report(const std::string &directory, std::vector<std::string> *missing = nullptr);

  /// Writes @p directory/part/open_in_paraview.py (knife/ in an earlier abrade's run): a
  /// pvpython script that opens the part's series (part.pvd) coloured by wear depth.
  void write_paraview_script(const std::string &directory);
} // namespace abrade::report
