#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>

#include <vtkDataSetSurfaceFilter.h>
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
#include <filesystem>

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
        surface->Update();
        vtkSmartPointer<vtkPolyData> p = surface->GetOutput();
        return p;
      }
    throw InputError(path, "unknown geometry format '" + ext + "' (use .stl, .obj, .ply, .vtk, .vtp or .vtu)");
  }
} // namespace abrade::io
