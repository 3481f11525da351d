#include <abrade/common/error.h>
#include <abrade/common/vtk_output.h>
#include <abrade/dem/mesh_io.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <filesystem>

namespace abrade::dem
{
  namespace
  {
    std::string extension(const std::string &path)
    {
      std::string e = std::filesystem::path(path).extension().string();
      std::transform(e.begin(), e.end(), e.begin(), ::tolower);
      return e;
    }

    template <typename Reader>
    vtkSmartPointer<vtkPolyData> read_with(const std::string &path)
    {
      vtkNew<Reader> r;
      r->SetFileName(path.c_str());
      r->Update();
      vtkSmartPointer<vtkPolyData> p = r->GetOutput();
      return p;
    }
  } // namespace

  TriangleMesh read_surface_mesh(const std::string &path, double scale)
  {
    if (!std::filesystem::exists(path))
      throw InputError(path, "mesh file not found");
    const std::string            ext = extension(path);
    vtkSmartPointer<vtkPolyData> poly;
    if (ext == ".stl")
      poly = read_with<vtkSTLReader>(path);
    else if (ext == ".obj")
      poly = read_with<vtkOBJReader>(path);
    else if (ext == ".ply")
      poly = read_with<vtkPLYReader>(path);
    else if (ext == ".vtk")
      poly = read_with<vtkPolyDataReader>(path);
    else if (ext == ".vtp")
      poly = read_with<vtkXMLPolyDataReader>(path);
    else
      throw InputError(path, "unknown mesh format '" + ext + "' (use .stl, .obj, .ply, .vtk or .vtp)");
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
