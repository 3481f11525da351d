#pragma once
// Inside abrade_common only (its public headers keep VTK out): io::PolyData in VTK's form.
#include <abrade/common/vtk_output.h>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <string>

namespace abrade::io
{
  /// The VTK form of @p data: points, triangles (or vertices for a point cloud), fields (@p path
  /// names the file in the messages of a field of the wrong size).
  vtkSmartPointer<vtkPolyData> to_vtk(const PolyData &data, const std::string &path);
} // namespace abrade::io
