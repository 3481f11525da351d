// walls/NAME_wear_profile.csv: the wear by height above the lowest point, by face direction,
// and its filtered peak depth (see the header).
#include <abrade/common/csv_writer.h>
#include <abrade/coupling/dem_run/wear_profile.h>
#include <abrade/fem/surface_filter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace abrade::coupling
{
  namespace
  {
    /// The peak of the filtered depth: the volumes smoothed over @p length along the surface,
    /// divided by the vertex areas.
    double filtered_peak(const dem::TriangleMesh &mesh, const std::vector<double> &vertex_volume, double length)
    {
      fem::SolidSurface s;
      for (const auto &v : mesh.vertices)
        s.vertices.emplace_back(v[0], v[1], v[2]);
      for (const auto &t : mesh.triangles)
        s.triangles.push_back({unsigned(t[0]), unsigned(t[1]), unsigned(t[2])});
      s.boundary_id.assign(s.triangles.size(), 0);
      const auto volume = fem::filter_on_surface(s, vertex_volume, length);
      const auto area   = fem::vertex_areas(s);
      double     peak   = 0;
      for (std::size_t v = 0; v < volume.size(); ++v)
        if (area[v] > 0)
          peak = std::max(peak, volume[v] / area[v]);
      return peak;
    }
  } // namespace

  void write_wear_profile(const std::string &file, const dem::TriangleMesh &mesh, const std::string &field,
                          const std::vector<WearVolumes> &volumes, const WearProfileSettings &p)
  {
    double z0 = 1e300, z1 = -1e300;
    for (const auto &v : mesh.vertices)
      z0 = std::min(z0, v[2]), z1 = std::max(z1, v[2]);
    const int n_bands = std::max(1, int(std::ceil((z1 - z0) / p.band - 1e-9)));
    // each triangle's height band and face direction, and the faces' areas
    std::vector<int>    band_of(mesh.n_triangles()), face_of(mesh.n_triangles());
    std::vector<double> face_area(6, 0.0);
    for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
      {
        const auto &tri = mesh.triangles[t];
        const dem::Vec3 a = mesh.vertices[tri[0]], b = mesh.vertices[tri[1]], c = mesh.vertices[tri[2]];
        band_of[t] = std::clamp(int(((a[2] + b[2] + c[2]) / 3 - z0) / p.band), 0, n_bands - 1);
        const dem::Vec3 n = (b - a).cross(c - a);
        int             axis;
        n.cwiseAbs().maxCoeff(&axis);
        face_of[t] = 2 * axis + (n[axis] < 0);
        face_area[face_of[t]] += 0.5 * n.norm();
      }
    // one column per entry of volumes: the run's, then each phase's
    const std::size_t                n_columns = volumes.size();
    std::vector<std::vector<double>> band(n_bands, std::vector<double>(n_columns, 0.0)),
      face(6, std::vector<double>(n_columns, 0.0));
    for (std::size_t k = 0; k < n_columns; ++k)
      for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
        band[band_of[t]][k] += volumes[k].triangle[t], face[face_of[t]][k] += volumes[k].triangle[t];

    std::vector<std::string> columns{"kind", "label", "lower", "upper", field, "area"};
    for (std::size_t k = 1; k < n_columns; ++k)
      columns.push_back(field + "_" + volumes[k].phase);
    io::CsvWriter csv(file, columns);
    auto          row = [&](const std::string &kind, const std::string &label, double lower, double upper,
                   const std::vector<double> &values, double area) {
      char b[160];
      std::snprintf(b, sizeof b, "%.9g,%.9g,%.17g,%.17g", lower, upper, values[0], area);
      std::string line = kind + "," + label + "," + b;
      for (std::size_t k = 1; k < values.size(); ++k)
        std::snprintf(b, sizeof b, ",%.17g", values[k]), line += b;
      csv.raw_row(line);
    };
    for (int k = 0; k < n_bands; ++k)
      row("height", "", k * p.band, (k + 1) * p.band, band[k], 0);
    static const char *faces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (int k = 0; k < 6; ++k)
      row("face", faces[k], 0, 0, face[k], face_area[k]);
    auto peaks = [&](double length) {
      std::vector<double> v;
      for (const auto &vol : volumes)
        v.push_back(filtered_peak(mesh, vol.vertex, length));
      return v;
    };
    if (p.radius > 0)
      row("filtered_peak", "radius", p.radius, p.radius, peaks(p.radius), 0);
    if (p.fixed_filter > 0)
      row("filtered_peak", "fixed", p.fixed_filter, p.fixed_filter, peaks(p.fixed_filter), 0);
    csv.close();
  }
} // namespace abrade::coupling
