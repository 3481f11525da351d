#include <abrade/common/error.h>
#include <abrade/common/legacy_vtk.h>
#include <abrade/common/ply_file.h>
#include <abrade/common/vtk_input.h>

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkPointData.h>
#include <vtkTriangleFilter.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

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

    /// VTK's OBJ reader follows face indices unchecked (an index past the vertices, or 0, reads
    /// out of bounds): every index is checked here first, naming the line.
    void check_obj(const std::string &path)
    {
      std::ifstream in(path);
      std::string   line;
      long          vertices = 0;
      for (long n = 1; std::getline(in, line); ++n)
        {
          std::istringstream words(line);
          std::string        kind;
          words >> kind;
          if (kind == "v")
            ++vertices;
          else if (kind == "f" || kind == "l")
            for (std::string corner; words >> corner;)
              {
                const std::string number = corner.substr(0, corner.find('/'));
                std::size_t       used   = 0;
                long              index  = 0;
                try
                  {
                    index = std::stol(number, &used);
                  }
                catch (const std::exception &)
                  {
                    used = 0;
                  }
                if (used != number.size() || number.empty())
                  throw InputError(path + ":" + std::to_string(n), "'" + corner + "' is not a vertex index");
                if (index == 0 || index > vertices || index < -vertices)
                  throw InputError(path + ":" + std::to_string(n),
                                   "vertex index " + number + " out of range (" + std::to_string(vertices) +
                                     " vertices defined before this line; indices count from 1, or back from -1)");
              }
        }
    }

    /// Keeps VTK's error window quiet while it lives: the caller reports in its own words.
    struct QuietVtk
    {
      const int was = vtkObject::GetGlobalWarningDisplay();
      QuietVtk() { vtkObject::GlobalWarningDisplayOff(); }
      ~QuietVtk() { vtkObject::SetGlobalWarningDisplay(was); }
    };
  } // namespace

  vtkSmartPointer<vtkPolyData> read_polydata(const std::string &path)
  {
    if (!std::filesystem::is_regular_file(path))
      throw InputError(path, "file not found");
    const std::string ext = lower_extension(path);
    QuietVtk          quiet;
    if (ext == ".stl")
      return read_with<vtkSTLReader>(path);
    if (ext == ".obj")
      {
        check_obj(path);
        return read_with<vtkOBJReader>(path);
      }
    if (ext == ".ply")
      return read_ply(path);
    if (ext == ".vtk")
      return read_legacy_vtk(path);
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
