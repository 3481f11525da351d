#pragma once
// VTK XML output for ParaView without exposing VTK headers: a point set or a triangle surface
// with named per-point and per-cell fields written as .vtp, and a .pvd file that strings the
// written files into a time series.
#include <array>
#include <string>
#include <vector>

namespace abrade::io
{
  /// A named field: n_components = 1 (scalar) or 3 (vector), values interleaved.
  struct Field
  {
    std::string         name;
    int                 n_components = 1;
    std::vector<double> values;
  };

  struct PolyData
  {
    std::vector<double>                 points; ///< x0 y0 z0 x1 y1 z1 ...
    std::vector<std::array<long, 3>>    triangles; ///< empty: written as vertices (a point cloud)
    std::vector<Field>                  point_fields;
    std::vector<Field>                  cell_fields;
  };

  /// Writes @p data as a binary, compressed VTK XML PolyData file (.vtp).
  void write_vtp(const std::string &path, const PolyData &data);

  /// Writes the triangles of @p data (fields are ignored) as a binary STL file.
  void write_stl(const std::string &path, const PolyData &data);

  /// A ParaView collection file (.pvd): each added file is written with its time, and the .pvd is
  /// rewritten after every addition so that an interrupted run leaves a valid series behind.
  class PvdSeries
  {
  public:
    PvdSeries() = default;
    explicit PvdSeries(const std::string &pvd_path) : path(pvd_path) {}
    void set_path(const std::string &pvd_path) { path = pvd_path; }
    /// @p file is relative to the directory of the .pvd file.
    void add(double time, const std::string &file);

  private:
    std::string                                 path;
    std::vector<std::pair<double, std::string>> entries;
  };
} // namespace abrade::io
