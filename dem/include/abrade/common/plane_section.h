#pragma once
// The outline of a triangle surface in an axis plane (VTK's cutter): the cross-sections that
// `abrade compare` draws of a prediction, a scan and a design, and that the lifetime loop draws
// of the part per update (coupling/lifetime/sections.h).
#include <abrade/common/vtk_output.h>

#include <array>
#include <string>
#include <vector>

class vtkPolyData;

namespace abrade::io
{
  /// A piece of an outline in the plane's coordinates (u, v) [m]: the two axes after the
  /// plane's normal, in turn (x: y, z; y: z, x; z: x, y).
  struct SectionSegment
  {
    double u0, v0, u1, v1;
  };

  /// The segments where @p surface's polygons cross the plane x_axis = @p at (a plane through
  /// the surface's vertices included: the middle of a regular mesh, a deepest vertex).
  std::vector<SectionSegment> plane_section(vtkPolyData *surface, int axis, double at);
  /// The same of triangles given as arrays (fields ignored).
  std::vector<SectionSegment> plane_section(const PolyData &surface, int axis, double at);
  /// The same of a surface file (what io::read_polydata reads: .stl, .vtp, ...); an InputError
  /// when it cannot be read.
  std::vector<SectionSegment> plane_section_of_file(const std::string &file, int axis, double at);

  /// How the surface of @p file faces at @p point: the area-weighted mean of each component's
  /// magnitude of the unit normals of the eight triangles whose centres lie nearest (near 1 in
  /// x: a face square to x there, which a plane normal to x would lie in, not cut). An
  /// InputError when the file cannot be read; zeros when it holds no triangle.
  std::array<double, 3> normal_magnitudes_near(const std::string &file, const std::array<double, 3> &point);
} // namespace abrade::io
