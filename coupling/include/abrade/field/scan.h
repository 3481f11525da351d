#pragma once
// Field geometry: worn knives as predicted by a run, scanned in the field, or as designed. A
// surface (triangles) or a point cloud, read through VTK (abrade::io::read_polydata) or, for
// point tables (.xyz, .csv, .txt), by a reader that names the bad line.
#include <vtkSmartPointer.h>

#include <array>
#include <string>
#include <vector>

class vtkPolyData;

namespace abrade::field
{
  struct Geometry
  {
    std::string                  path;
    vtkSmartPointer<vtkPolyData> data;        ///< triangles (surfaces) or points only (clouds)
    bool                         point_cloud = false;
    bool                         closed      = false; ///< every edge shared by exactly two triangles
    long                         non_manifold_edges = 0;
    long                         boundary_edges     = 0;

    /// Diagonal of the bounding box.
    double size() const;
    std::array<double, 3> centroid() const; ///< area-weighted for surfaces, of the points for clouds
    /// Enclosed volume (closed surfaces only; 0 otherwise).
    double volume() const;
  };

  /// The volume a triangle surface encloses, signed: > 0 when its triangles face outward
  /// (counter-clockwise seen from outside), < 0 when they face inward.
  double signed_volume(vtkPolyData *surface);
  /// @p surface with every triangle ordered like its neighbours (VTK's normals filter); with
  /// @p outward, a closed surface's triangles also face outward.
  vtkSmartPointer<vtkPolyData> consistently_oriented(vtkPolyData *surface, bool outward);

  /// Reads a surface (.stl, .ply, .obj, .vtp, .vtk, .vtu) or a point cloud (.ply without faces,
  /// .xyz, .csv, .txt: "x y z" or "x,y,z" per line, '#' comments, an optional header line).
  /// Polygons are triangulated and coincident points merged. Throws InputError naming the file
  /// (and the line, for tables) when it is missing, empty or malformed; @p warnings gets a line
  /// for a non-manifold or open surface. A closed surface whose triangles face inward (all or
  /// some) is turned to face outward, with a warning.
  Geometry read_geometry(const std::string &path, std::vector<std::string> &warnings);

  /// Scales the geometry's coordinates by @p factor (millimetres to metres: 0.001).
  void scale(Geometry &g, double factor);

  /// Units of a scan against the model it is compared with: "m" and "mm" fix the scale, "auto"
  /// detects a scan in millimetres (about 1000 times the model's size) and scales it by 0.001
  /// with a warning. Sizes that match neither are an InputError (wrong file or unit). Returns the
  /// factor applied.
  double check_units(Geometry &scan, const Geometry &model, const std::string &units, std::vector<std::string> &warnings);
} // namespace abrade::field
