#pragma once
// The geometry (points and polygons) of a legacy VTK polydata file, every count and index
// checked (legacy_vtk.cc). Needs VTK's include directories.
#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace abrade::io
{
  /// Reads the points and polygons (triangle strips as triangles) of @p path, a legacy .vtk
  /// file with DATASET POLYDATA, ASCII or BINARY, versions up to 5; throws InputError naming
  /// the file and line (ASCII) for anything it does not hold as announced.
  vtkSmartPointer<vtkPolyData> read_legacy_vtk(const std::string &path);
} // namespace abrade::io
