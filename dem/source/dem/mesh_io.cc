// Wall meshes read and written (mesh_io.h).
#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>
#include <abrade/common/vtk_output.h>
#include <abrade/dem/mesh_io.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include <cmath>

namespace abrade::dem
{
  TriangleMesh read_surface_mesh(const std::string &path, double scale)
  {
    const vtkSmartPointer<vtkPolyData> poly = io::read_polydata(path);
    if (!poly || poly->GetNumberOfPolys() == 0)
      throw InputError(path, "no triangles could be read (empty or malformed file)");

    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputData(poly);
    tri->PassLinesOff();
    tri->PassVertsOff();
    tri->Update();
    vtkPolyData *t = tri->GetOutput();

    TriangleMesh mesh;
    mesh.vertices.resize(t->GetNumberOfPoints());
    for (vtkIdType i = 0; i < t->GetNumberOfPoints(); ++i)
      {
        double p[3];
        t->GetPoint(i, p);
        mesh.vertices[i] = scale * Vec3(p[0], p[1], p[2]);
      }
    vtkCellArray *polys = t->GetPolys();
    polys->InitTraversal();
    vtkIdType        n;
    const vtkIdType *ids;
    while (polys->GetNextCell(n, ids))
      if (n == 3)
        mesh.triangles.push_back({int(ids[0]), int(ids[1]), int(ids[2])});

    Vec3 lo, hi;
    mesh.bounding_box(lo, hi);
    const double size = (hi - lo).norm();
    if (!(size > 0) || !std::isfinite(size))
      throw InputError(path, "mesh has no extent or non-finite coordinates");
    // shared vertices for neighbouring triangles; triangles that collapse are dropped
    const std::size_t before = mesh.n_triangles();
    mesh.weld(1e-9 * size);
    if (mesh.n_triangles() == 0)
      throw InputError(path, "all " + std::to_string(before) + " triangles are degenerate");
    for (std::size_t k = 0; k < mesh.n_triangles(); ++k)
      if (!(mesh.area(k) > 1e-14 * size * size))
        throw InputError(path, "triangle " + std::to_string(k) + " has zero area");
    return mesh;
  }

  void write_stl(const std::string &path, const TriangleMesh &mesh)
  {
    io::PolyData d;
    for (const auto &v : mesh.vertices)
      d.points.insert(d.points.end(), {v[0], v[1], v[2]});
    for (const auto &t : mesh.triangles)
      d.triangles.push_back({t[0], t[1], t[2]});
    io::write_stl(path, d);
  }
} // namespace abrade::dem
