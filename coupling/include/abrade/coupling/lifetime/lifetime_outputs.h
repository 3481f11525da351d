#pragma once
// The lifetime loop's files besides trajectory.csv and the knife series: cross-sections of the
// knife per update (knife/profile_F.csv, blocks per update) and the gnuplot figures
// (trajectory.png, knife/profile_F.png).
#include <abrade/fem/knife_geometry.h>
#include <abrade/fem/solid_surface.h>

#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  /// The knife's cross-sections at x = f L for each f of @p planes: segments (y, z) where
  /// surface triangles cross the plane, appended as update @p update's block (the first update
  /// starts the files).
  void write_profiles(const fem::SolidSurface &s, double length, const std::vector<double> &planes, long update,
                      const std::string &directory);

  /// Cuts the profile files back to the blocks of updates <= @p update (resume).
  void truncate_profiles(const std::vector<double> &planes, long update, const std::string &directory);

  /// trajectory.png (wear depth, recession and worn volume vs tonnes) and knife/profile_F.png.
  void plot_lifetime(const std::string &dir, const std::vector<double> &planes, const fem::KnifeGeometry &k);
} // namespace abrade::coupling::lifetime
