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
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

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

    /// VTK's PLY reader trusts the header's element counts (a file that holds fewer ends in a
    /// freed pointer): the counts are checked against what the file holds first.
    void check_ply(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      std::string   line;
      std::getline(in, line);
      if (line.rfind("ply", 0) != 0)
        throw InputError(path, "not a PLY file (it does not start with 'ply')");
      std::string format;
      long        declared = 0; // vertices and faces the header announces
      long        vertex_bytes = 0, vertices = 0;
      std::string element;
      const std::map<std::string, int> sizes = {{"char", 1},   {"uchar", 1},   {"int8", 1},    {"uint8", 1},
                                                {"short", 2},  {"ushort", 2},  {"int16", 2},   {"uint16", 2},
                                                {"int", 4},    {"uint", 4},    {"int32", 4},   {"uint32", 4},
                                                {"float", 4},  {"float32", 4}, {"double", 8},  {"float64", 8}};
      for (long n = 2; std::getline(in, line); ++n)
        {
          std::istringstream words(line);
          std::string        kind;
          words >> kind;
          if (kind == "end_header")
            break;
          if (kind == "format")
            words >> format;
          else if (kind == "element")
            {
              long count = -1;
              words >> element >> count;
              if (!words || count < 0 || count > (1L << 40))
                throw InputError(path + ":" + std::to_string(n), "element count is not a number of elements");
              if (element == "vertex")
                vertices = count;
              if (element == "vertex" || element == "face")
                declared += count;
            }
          else if (kind == "property" && element == "vertex")
            {
              std::string type;
              words >> type;
              const auto size = sizes.find(type);
              if (size == sizes.end())
                throw InputError(path + ":" + std::to_string(n), "vertex property of unknown type '" + type + "'");
              vertex_bytes += size->second;
            }
        }
      if (!in)
        throw InputError(path, "the PLY header has no end_header line");
      const auto body = std::filesystem::file_size(path) - static_cast<std::uintmax_t>(in.tellg());
      if (format == "ascii")
        {
          long lines = 0;
          for (std::string l; std::getline(in, l);)
            lines += l.find_first_not_of(" \t\r") != std::string::npos;
          if (lines < declared)
            throw InputError(path, "the header announces " + std::to_string(declared) +
                                     " vertices and faces, the file holds " + std::to_string(lines) + " lines of them");
        }
      else if (static_cast<double>(body) < static_cast<double>(vertices) * vertex_bytes)
        throw InputError(path, "the header announces " + std::to_string(vertices) + " vertices of " +
                                 std::to_string(vertex_bytes) + " bytes, the file holds " + std::to_string(body) +
                                 " bytes after its header");
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
      {
        check_obj(path);
        return read_with<vtkOBJReader>(path);
      }
    if (ext == ".ply")
      {
        check_ply(path);
        return read_with<vtkPLYReader>(path);
      }
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
