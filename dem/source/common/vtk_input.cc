// Every surface reader of the project (STL, OBJ, PLY, legacy VTK, VTP, VTU), checked before
// VTK sees a file (vtk_input.h).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/input_file.h>
#include <abrade/common/obj_file.h>
#include <abrade/common/legacy_vtk.h>
#include <abrade/common/ply_file.h>
#include <abrade/common/vtk_input.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkCleanPolyData.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkPointData.h>
#include <vtkTriangleFilter.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <algorithm>
#include <array>
#include <cctype>
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

    /// What VTK's XML and STL readers hand back is checked before anything follows an index
    /// or uses a coordinate: they read a connectivity past the points (`0 1 99999` for three
    /// points crashed a wall's export; 7 or 1000 read memory past the points), offsets that do
    /// not rise, and NaN or infinite coordinates (an STL wall with a NaN was "of zero area") as
    /// they are. @p cells are one of the data set's cell arrays, @p kind names them.
    void check_cells(const std::string &path, vtkCellArray *cells, vtkIdType n_points, const char *kind,
                     vtkIdType least)
    {
      if (!cells || cells->GetNumberOfCells() == 0)
        return;
      vtkDataArray *offsets = cells->GetOffsetsArray(), *connectivity = cells->GetConnectivityArray();
      const vtkIdType n = cells->GetNumberOfCells(), size = connectivity->GetNumberOfTuples();
      double          previous = 0;
      for (vtkIdType c = 0; c <= n; ++c)
        {
          const double o = offsets->GetTuple1(c);
          if (!(o >= previous && o <= double(size)) || (c == 0 && o != 0) || (c == n && o != double(size)))
            throw InputError(path, std::string("the ") + kind + "' offsets are broken at " + kind + " " +
                                     std::to_string(c) + " (offset " + format_number(o, 17) + " of a connectivity of " +
                                     std::to_string(size) + " indices)");
          // VTK cannot build its cell map of a polygon of two points (and then reads a null one)
          if (c > 0 && o - previous < double(least))
            throw InputError(path, "cell " + std::to_string(c - 1) + " of the " + kind + " has " +
                                     format_number(o - previous, 17) + " point(s), fewer than " +
                                     std::to_string(least));
          previous = o;
        }
      for (vtkIdType k = 0; k < size; ++k)
        {
          const double i = connectivity->GetTuple1(k);
          if (!(i >= 0 && i < double(n_points)))
            throw InputError(path, std::string("point index ") + format_number(i, 17) + " in the " + kind +
                                     "' connectivity (entry " + std::to_string(k) + ") is out of range (" +
                                     std::to_string(n_points) + " points, counted from 0)");
        }
    }

    void check_points(const std::string &path, vtkPoints *points)
    {
      if (!points)
        return;
      for (vtkIdType p = 0; p < points->GetNumberOfPoints(); ++p)
        {
          double x[3];
          points->GetPoint(p, x);
          if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
            {
              std::ostringstream where;
              where << "point " << p << " (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
              throw InputError(path, where.str() + " has a coordinate that is not a finite number");
            }
        }
    }

    /// VTK reads an STL whose first bytes are not all text as binary and allocates for the
    /// triangle count its header announces: a garbled ASCII file (a byte changed in a line)
    /// asked for gigabytes and the process died. Such a file must be a binary STL whose count
    /// fits its size (84 bytes of header and count, 50 a triangle).
    void check_stl(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      char          head[256];
      in.read(head, sizeof head);
      const std::streamsize n_read = in.gcount();
      const bool            text   = std::all_of(head, head + n_read, [](char c) {
        const auto u = static_cast<unsigned char>(c);
        return (u >= 32 && u < 127) || u == '\t' || u == '\n' || u == '\r';
      });
      if (text)
        return;
      const auto size = std::filesystem::file_size(path);
      if (size < 84)
        throw InputError(path, "not an STL file: not text, and shorter (" + std::to_string(size) +
                                 " bytes) than a binary STL's 84-byte header");
      std::uint32_t count = 0;
      std::memcpy(&count, head + 80, 4); // (little-endian, as the format is)
      if (84 + 50 * std::uint64_t(count) > size)
        throw InputError(path, "a binary STL whose header announces " + std::to_string(count) + " triangles (" +
                                 std::to_string(84 + 50 * std::uint64_t(count)) + " bytes) in a file of " +
                                 std::to_string(size) + " bytes: cut short, or an ASCII STL with bytes that are "
                                                        "not text");
    }

    /// VTK's XML readers believe the counts a file declares: NumberOfComponents="35555555"
    /// on three points kept one busy for minutes, and a NumberOfPoints of billions allocates
    /// what it says. Every count must fit the file (a compressed file: a thousand times its
    /// size) and an array has at most 64 components.
    void check_xml_counts(const std::string &path)
    {
      std::ifstream      in(path, std::ios::binary);
      std::ostringstream text;
      text << in.rdbuf();
      std::string head = text.str();
      if (const auto appended = head.find("<AppendedData"); appended != std::string::npos)
        head.resize(appended); // (the raw data after it is no XML)
      const double size  = double(std::filesystem::file_size(path));
      const double limit = (head.find("compressor=") != std::string::npos ? 1000 : 1) * size;
      // every NumberOf...="value" attribute (found by hand: std::regex on a scan of tens of MB is slow)
      for (std::size_t at = head.find("NumberOf"); at != std::string::npos; at = head.find("NumberOf", at + 8))
        {
          std::size_t name_end = at + 8;
          while (name_end < head.size() && std::isalpha(static_cast<unsigned char>(head[name_end])))
            ++name_end;
          const std::string what = head.substr(at, name_end - at);
          std::size_t       q    = head.find_first_not_of(" \t\r\n", name_end);
          if (q == std::string::npos || head[q] != '=')
            continue;
          q = head.find_first_not_of(" \t\r\n", q + 1);
          if (q == std::string::npos || (head[q] != '"' && head[q] != '\''))
            continue;
          const std::size_t close = head.find(head[q], q + 1);
          const std::string value = head.substr(q + 1, close == std::string::npos ? 30 : close - q - 1);
          char        *stop       = nullptr;
          const double n          = std::strtod(value.c_str(), &stop);
          const bool   components = what == "NumberOfComponents";
          if (stop == value.c_str() || !(n >= 0) || n > (components ? 64 : limit))
            throw InputError(path, what + "=\"" + value.substr(0, 30) + "\" is more than the file can hold" +
                                     (components ? " (at most 64 components)" : " (" + format_number(size) + " bytes)"));
        }
    }

    vtkSmartPointer<vtkPolyData> checked(const std::string &path, vtkSmartPointer<vtkPolyData> p)
    {
      const vtkIdType n = p->GetNumberOfPoints();
      check_points(path, p->GetPoints());
      check_cells(path, p->GetVerts(), n, "vertices", 1);
      check_cells(path, p->GetLines(), n, "lines", 2);
      check_cells(path, p->GetPolys(), n, "polygons", 3);
      check_cells(path, p->GetStrips(), n, "strips", 3);
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

  vtkSmartPointer<vtkPolyData> read_polydata(const std::string &path)
  {
    require_input_file(path);
    const std::string ext = lower_extension(path);
    QuietVtk          quiet;
    if (ext == ".stl")
      {
        check_stl(path);
        return checked(path, read_with<vtkSTLReader>(path));
      }
    if (ext == ".obj")
      return read_obj(path);
    if (ext == ".ply")
      return read_ply(path);
    if (ext == ".vtk")
      return read_legacy_vtk(path);
    if (ext == ".vtp")
      {
        check_xml_counts(path);
        return checked(path, read_with<vtkXMLPolyDataReader>(path));
      }
    if (ext == ".vtu")
      {
        check_xml_counts(path);
        vtkNew<vtkXMLUnstructuredGridReader> r;
        r->SetFileName(path.c_str());
        r->Update();
        vtkUnstructuredGrid *grid = r->GetOutput();
        check_points(path, grid->GetPoints());
        check_cells(path, grid->GetCells(), grid->GetNumberOfPoints(), "cells", 1);
        vtkNew<vtkDataSetSurfaceFilter> surface;
        surface->SetInputData(grid);
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

  PolyData triangles_of(vtkPolyData *p)
  {
    PolyData out;
    out.points.resize(3 * p->GetNumberOfPoints());
    for (vtkIdType k = 0; k < p->GetNumberOfPoints(); ++k)
      p->GetPoint(k, &out.points[3 * k]);
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < p->GetNumberOfCells(); ++c)
      {
        p->GetCellPoints(c, ids);
        if (ids->GetNumberOfIds() == 3)
          out.triangles.push_back({long(ids->GetId(0)), long(ids->GetId(1)), long(ids->GetId(2))});
      }
    return out;
  }
} // namespace abrade::io
