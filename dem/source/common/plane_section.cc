// Surfaces cut by axis planes with VTK's cutter, and how a surface faces at a point
// (plane_section.h).
#include <abrade/common/plane_section.h>

#include <abrade/common/vtk_input.h>

#include "vtk_polydata.h"

#include <vtkCutter.h>
#include <vtkNew.h>
#include <vtkPlane.h>

#include <algorithm>
#include <cmath>

namespace abrade::io
{
  std::vector<SectionSegment> plane_section(vtkPolyData *surface, int axis, double at)
  {
    std::vector<SectionSegment> out;
    if (!surface || surface->GetNumberOfPolys() == 0)
      return out;
    vtkNew<vtkPlane> plane;
    double           origin[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
    origin[axis] = at, normal[axis] = 1;
    plane->SetOrigin(origin);
    plane->SetNormal(normal);
    vtkNew<vtkCutter> cut;
    cut->SetCutFunction(plane);
    cut->SetInputData(surface);
    cut->Update();
    vtkPolyData *lines = cut->GetOutput();
    const int    u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
      {
        vtkIdType        n;
        const vtkIdType *ids;
        lines->GetCellPoints(c, n, ids);
        for (vtkIdType k = 0; k + 1 < n; ++k)
          {
            double a[3], b[3]; // (GetPoint(id) returns one buffer: copied)
            lines->GetPoint(ids[k], a);
            lines->GetPoint(ids[k + 1], b);
            out.push_back({a[u], a[v], b[u], b[v]});
          }
      }
    return out;
  }

  std::vector<SectionSegment> plane_section(const PolyData &surface, int axis, double at)
  {
    if (surface.triangles.empty())
      return {};
    return plane_section(to_vtk(surface, "a section's surface").Get(), axis, at);
  }

  std::vector<SectionSegment> plane_section_of_file(const std::string &file, int axis, double at)
  {
    return plane_section(read_polydata(file).Get(), axis, at);
  }

  std::array<double, 3> normal_magnitudes_near(const std::string &file, const std::array<double, 3> &point)
  {
    const PolyData surface = triangles_of(read_polydata(file).Get());
    struct Near
    {
      double                distance, area;
      std::array<double, 3> normal;
    };
    std::vector<Near> triangles;
    const auto       &x = surface.points;
    for (const auto &t : surface.triangles)
      {
        double e1[3], e2[3], d2 = 0;
        for (int i = 0; i < 3; ++i)
          {
            e1[i]          = x[3 * t[1] + i] - x[3 * t[0] + i], e2[i] = x[3 * t[2] + i] - x[3 * t[0] + i];
            const double m = (x[3 * t[0] + i] + x[3 * t[1] + i] + x[3 * t[2] + i]) / 3;
            d2 += (m - point[i]) * (m - point[i]);
          }
        const std::array<double, 3> a = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                         e1[0] * e2[1] - e1[1] * e2[0]};
        const double                l = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (l > 0)
          triangles.push_back({d2, 0.5 * l, {a[0] / l, a[1] / l, a[2] / l}});
      }
    const std::size_t k = std::min<std::size_t>(8, triangles.size());
    std::partial_sort(triangles.begin(), triangles.begin() + long(k), triangles.end(),
                      [](const Near &a, const Near &b) { return a.distance < b.distance; });
    std::array<double, 3> sum{};
    double                area = 0;
    for (std::size_t t = 0; t < k; ++t)
      {
        for (int i = 0; i < 3; ++i)
          sum[i] += triangles[t].area * std::abs(triangles[t].normal[i]);
        area += triangles[t].area;
      }
    if (area > 0)
      for (double &c : sum)
        c /= area;
    return sum;
  }
} // namespace abrade::io
