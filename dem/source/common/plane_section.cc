#include <abrade/common/plane_section.h>

#include <abrade/common/vtk_input.h>

#include "vtk_polydata.h"

#include <vtkCutter.h>
#include <vtkNew.h>
#include <vtkPlane.h>

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
} // namespace abrade::io
