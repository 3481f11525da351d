#pragma once
// Where on a wall the wear of a volume field (Output/Wear field, Archard's by default) went, for studies that compare wear patterns (docs/
// coarse-graining.md): walls/NAME_wear_profile.csv of the `dem` job, with columns
// kind, label, lower, upper, FIELD (the field's name: archard_volume), area, then FIELD_PHASE
// for every phase (archard_volume_penetration, ...: the same row's value from that phase's wear
// alone; the phases' columns sum to FIELD except in the filtered_peak rows) and rows
//  - kind "height": the volume on the triangles whose centroid is between lower and upper [m]
//    above the wall's lowest point (bands of Output/Wear profile band; a knife's edge first);
//  - kind "face": per direction of the triangles' outward normal in the reference pose (label
//    +x, -x, +y, -y, +z, -z: the axis the normal is closest to), their volume and area;
//  - kind "filtered_peak": the largest wear depth after the lifetime loop's surface filter
//    (fem/surface_filter.h, volume conserving) with length lower = upper [m]; label "radius"
//    for the largest particle radius (the loop's default), "fixed" for Output/Wear filter
//    length; the field's column holds the depth [m].
#include <abrade/dem/triangle_mesh.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  struct WearProfileSettings
  {
    double band         = 0.01;   ///< height band [m]
    double fixed_filter = 0.0275; ///< [m]; 0: no "fixed" row
    double radius       = 0;      ///< the largest particle radius [m]
  };

  /// The volumes of a field per triangle and per vertex (which have the same sum), over the
  /// whole run or one phase.
  struct WearVolumes
  {
    std::string         phase; ///< "" for the whole run
    std::vector<double> triangle, vertex;
  };

  /// Writes @p file from the wall's reference @p mesh and the volumes of field @p field over the
  /// whole run (@p volumes' first entry, phase "") and per phase (the others, in their order).
  void write_wear_profile(const std::string &file, const dem::TriangleMesh &mesh, const std::string &field,
                          const std::vector<WearVolumes> &volumes, const WearProfileSettings &settings);
} // namespace abrade::coupling
