#pragma once
// The lifetime loop's files besides trajectory.csv and the part series: cross-sections of the
// part per update (part/profile_F.csv, blocks per update) and the gnuplot figures
// (trajectory.png, part/profile_F.png).
#include <abrade/coupling/lifetime/sections.h>
#include <abrade/fem/solid_surface.h>

#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// Where the part's cross-sections are taken and what the figures show, from the design
  /// surface's bounding box (the part's frame: x along the edge, z up from the edge): the
  /// planes x = x0 + f (x1 - x0); y over twice the part's thickness and z from its lowest
  /// point up to three thicknesses (the worn end, where the gauges look for the whole plate).
  struct ProfileFrame
  {
    double x0 = 0, x1 = 1, y0 = -1, y1 = 1, z0 = 0, z1 = 1;
  };
  ProfileFrame profile_frame(const fem::SolidSurface &design);
  /// The plane x of the fraction @p f of the length (0 and 1 a thousandth inside the ends).
  double plane_x(const ProfileFrame &frame, double f);

  /// The worn surface after update @p update in the part's folder @p part (io::part_folder):
  /// "part_00003.stl" (update 0: the design).
  std::string part_surface_name(const std::string &part, long update);

  /// The part's cross-sections at the fractions @p planes of its length: segments (y, z) where
  /// surface triangles cross the plane (sections.h), appended as update @p update's block; the
  /// first update starts the files with the outline of @p design as update 0.
  void write_profiles(const fem::SolidSurface &s, const fem::SolidSurface &design, const ProfileFrame &frame,
                      const std::vector<double> &planes, long update, const std::string &directory);

  /// Cuts the profile files back to the blocks of updates <= @p update (resume), each replaced
  /// at once (written aside, renamed). A line that is not a profile segment is an InputError
  /// naming the file and line, unless it is the last (an append cut by a crash: dropped).
  /// Returns the profile files that are missing.
  std::vector<std::string> truncate_profiles(const std::vector<double> &planes, long update, const std::string &directory);

  /// What trajectory.png marks besides the data: the end-of-life limits on the depth and the
  /// recession and the gauged edge recession [m] (0: none), and an extrapolated life, drawn dashed from the last update's
  /// point (tonnes, value of the criterion's quantity [m]) to (life, limit).
  struct TrajectoryMarks
  {
    double depth_limit = 0, recession_limit = 0, edge_limit = 0;
    double plate_limit = 0;           ///< Minimum plate thickness (0: none; then not drawn)
    std::size_t recession_points = 1; ///< the followed points (point_recession, _2, ...): each drawn
    bool   extrapolated = false;
    double last_tonnes = 0, last_value = 0, life = 0, limit = 0;
  };

  /// The cross-section through the place that ended the life (part/section_worst.csv and
  /// .png): the place @p where in the part's frame [m], the updates' surfaces it is cut from
  /// (part/part_00000.stl ... part_N.stl, N = @p updates) and what is drawn there.
  struct WorstSection
  {
    std::vector<double> where;
    long                updates = 0;
    SectionMark         mark;
  };

  /// trajectory.png (wear depth, recession and worn volume vs tonnes, the limits and an
  /// extrapolation), part/profile_F.png and, given @p worst, part/section_worst.png: each
  /// cross-section with the design's outline, zoomed to the wear (sections.h).
  void plot_lifetime(const std::string &dir, const std::vector<double> &planes, const ProfileFrame &frame,
                     const TrajectoryMarks &marks = {}, const WorstSection *worst = nullptr);
} // namespace abrade::coupling::lifetime
