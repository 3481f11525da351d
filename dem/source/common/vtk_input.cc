#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkPointData.h>
#include <vtkTriangleFilter.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObject.h>
#include <vtkPLYReader.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>

namespace abrade::io
{
  namespace
  {
    template <typename Reader>
    vtkSmartPointer<vtkPolyData> read_with(const std::string &path)
    {
      vtkNew<Reader> r;
      r->SetFileName(path.c_str());
      r->Update();
      vtkSmartPointer<vtkPolyData> p = r->GetOutput();
      return p;
    }

    /// Keeps VTK's error window quiet while it lives: the caller reports in its own words.
    struct QuietVtk
    {
      const int was = vtkObject::GetGlobalWarningDisplay();
      QuietVtk() { vtkObject::GlobalWarningDisplayOff(); }
      ~QuietVtk() { vtkObject::SetGlobalWarningDisplay(was); }
    };
  } // namespace

  std::string lower_extension(const std::string &path)
  {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), ::tolower);
    return e;
  }

  vtkSmartPointer<vtkPolyData> read_polydata(const std::string &path)
  {
    if (!std::filesystem::is_regular_file(path))
      throw InputError(path, "file not found");
    const std::string ext = lower_extension(path);
    QuietVtk          quiet;
    if (ext == ".stl")
      return read_with<vtkSTLReader>(path);
    if (ext == ".obj")
      return read_with<vtkOBJReader>(path);
    if (ext == ".ply")
      return read_with<vtkPLYReader>(path);
    if (ext == ".vtk")
      return read_with<vtkPolyDataReader>(path);
    if (ext == ".vtp")
      return read_with<vtkXMLPolyDataReader>(path);
    if (ext == ".vtu")
      {
        vtkNew<vtkXMLUnstructuredGridReader> r;
        r->SetFileName(path.c_str());
        vtkNew<vtkDataSetSurfaceFilter> surface;
        surface->SetInputConnection(r->GetOutputPort());
        // deal.II's DataOut writes every cell with its own copies of its vertices: merge them,
        // then the faces two cells share come twice and are dropped (the outer surface remains)
        vtkNew<vtkCleanPolyData> merge;
        merge->SetInputConnection(surface->GetOutputPort());
        merge->SetTolerance(0);
        merge->ConvertPolysToLinesOff();
        vtkNew<vtkTriangleFilter> triangles;
        triangles->SetInputConnection(merge->GetOutputPort());
        triangles->Update();
        vtkSmartPointer<vtkPolyData> all = triangles->GetOutput();
        std::map<std::array<vtkIdType, 3>, int> count;
        auto key = [&](vtkIdType c) {
          vtkIdType        n;
          const vtkIdType *ids;
          all->GetCellPoints(c, n, ids);
          std::array<vtkIdType, 3> k = {ids[0], ids[1], ids[2]};
          std::sort(k.begin(), k.end());
          return k;
        };
        for (vtkIdType c = 0; c < all->GetNumberOfCells(); ++c)
          ++count[key(c)];
        vtkNew<vtkCellArray> outer;
        for (vtkIdType c = 0; c < all->GetNumberOfCells(); ++c)
          if (count[key(c)] == 1)
            {
              vtkIdType        n;
              const vtkIdType *ids;
              all->GetCellPoints(c, n, ids);
              outer->InsertNextCell(n, ids);
            }
        auto p = vtkSmartPointer<vtkPolyData>::New();
        p->SetPoints(all->GetPoints());
        p->GetPointData()->ShallowCopy(all->GetPointData());
        p->SetPolys(outer);
        return p;
      }
    throw InputError(path, "unknown geometry format '" + ext + "' (use .stl, .obj, .ply, .vtk, .vtp or .vtu)");
  }
} // namespace abrade::io
