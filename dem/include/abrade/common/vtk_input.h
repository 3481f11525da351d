#pragma once
// Reading geometry files through VTK into vtkPolyData: one dispatch on the file extension for
// every reader of the project (wall meshes, knife solids' surfaces, field scans). Needs VTK's
// include directories (the libraries that call it link VTK).
#include <abrade/common/file_extension.h>
#include <abrade/common/vtk_output.h>

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace abrade::io
{
  /// Reads .stl, .obj, .ply, .vtk (legacy polydata), .vtp, or the outer surface of a .vtu.
  /// Throws InputError naming the file when it is missing or its extension is unknown; the
  /// result may hold no cells (a point cloud) or nothing (an empty or malformed file): callers
  /// check what they need. VTK's own error messages are silenced while reading.
  vtkSmartPointer<vtkPolyData> read_polydata(const std::string &path);

  /// The points and the triangles of @p p (its other cells left out), as plain arrays.
  PolyData triangles_of(vtkPolyData *p);

} // namespace abrade::io
