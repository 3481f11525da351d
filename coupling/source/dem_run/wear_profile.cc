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
                          const std::vector<double> &triangle_volume, const std::vector<double> &vertex_volume,
                          const WearProfileSettings &p)
  {
    double z0 = 1e300, z1 = -1e300;
    for (const auto &v : mesh.vertices)
      z0 = std::min(z0, v[2]), z1 = std::max(z1, v[2]);
    const int           n_bands = std::max(1, int(std::ceil((z1 - z0) / p.band - 1e-9)));
    std::vector<double> band(n_bands, 0.0), face(6, 0.0), face_area(6, 0.0);
    for (std::size_t t = 0; t < mesh.n_triangles(); ++t)
      {
        const auto &tri = mesh.triangles[t];
        const dem::Vec3 a = mesh.vertices[tri[0]], b = mesh.vertices[tri[1]], c = mesh.vertices[tri[2]];
        const double    h = (a[2] + b[2] + c[2]) / 3 - z0;
        band[std::clamp(int(h / p.band), 0, n_bands - 1)] += triangle_volume[t];
        const dem::Vec3 n = (b - a).cross(c - a);
        int             axis;
        n.cwiseAbs().maxCoeff(&axis);
        const int k = 2 * axis + (n[axis] < 0);
        face[k] += triangle_volume[t], face_area[k] += 0.5 * n.norm();
      }
    io::CsvWriter csv(file, {"kind", "label", "lower", "upper", field, "area"});
    auto row = [&](const std::string &kind, const std::string &label, double lower, double upper, double value,
                   double area) {
      char b[160];
      std::snprintf(b, sizeof b, "%.9g,%.9g,%.17g,%.17g", lower, upper, value, area);
      csv.raw_row(kind + "," + label + "," + b);
    };
    for (int k = 0; k < n_bands; ++k)
      row("height", "", k * p.band, (k + 1) * p.band, band[k], 0);
    static const char *faces[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
    for (int k = 0; k < 6; ++k)
      row("face", faces[k], 0, 0, face[k], face_area[k]);
    if (p.radius > 0)
      row("filtered_peak", "radius", p.radius, p.radius, filtered_peak(mesh, vertex_volume, p.radius), 0);
    if (p.fixed_filter > 0)
      row("filtered_peak", "fixed", p.fixed_filter, p.fixed_filter, filtered_peak(mesh, vertex_volume, p.fixed_filter),
          0);
    csv.close();
  }
} // namespace abrade::coupling
