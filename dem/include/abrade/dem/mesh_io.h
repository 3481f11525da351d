#pragma once
// Reading wall meshes through VTK: STL (ASCII and binary), OBJ, PLY, legacy .vtk and .vtp.
// Vertices are welded so that neighbouring triangles share them; polygons are triangulated.
#include <abrade/dem/triangle_mesh.h>

#include <string>

namespace abrade::dem
{
  /// Reads a surface mesh; throws InputError naming the file if it cannot be read, holds no
  /// triangles, or has degenerate elements (reported by index). @p scale converts file units to
  /// metres (0.001 for a file in millimetres).
  TriangleMesh read_surface_mesh(const std::string &path, double scale = 1.0);

  /// Writes a mesh as binary STL.
  void write_stl(const std::string &path, const TriangleMesh &mesh);
} // namespace abrade::dem
