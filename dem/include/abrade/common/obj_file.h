#pragma once
// The geometry (vertices and faces) of a Wavefront OBJ file, every number and index checked
// (obj_file.cc). Needs VTK's include directories.
#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace abrade::io
{
  /// Reads the vertices (`v x y z [w]`) and faces (`f` with corners `v`, `v/vt`, `v//vn` or
  /// `v/vt/vn`, formats mixed as they come, negative indices counting back) of @p path; throws
  /// InputError naming the file and line for a coordinate that is missing or not a finite
  /// number, an index out of range (texture and normal indices too), or a face of fewer than
  /// three corners. Everything else (groups, materials, smoothing, lines) is read past.
  vtkSmartPointer<vtkPolyData> read_obj(const std::string &path);
} // namespace abrade::io
