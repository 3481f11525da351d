#pragma once
// The geometry (vertices and faces) of a PLY file, every count, value and index checked
// (ply_file.cc). Needs VTK's include directories.
#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace abrade::io
{
  /// Reads the vertices (x, y, z) and faces (vertex_indices) of @p path; throws InputError
  /// naming the file and the line (ASCII) or element for anything not as the header declares.
  vtkSmartPointer<vtkPolyData> read_ply(const std::string &path);
} // namespace abrade::io
