#include <abrade/common/error.h>
#include <abrade/common/legacy_vtk.h>
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

    /// VTK's PLY reader trusts the file (a header announcing more than the file holds, an
    /// unknown keyword, an index past the vertices: freed pointers and segfaults). The whole
    /// file is walked here first, as the header declares it: known keywords and types only,
    /// x, y, z for the vertices and an index list for the faces, every number finite and every
    /// index a vertex; errors name the line (ASCII) or the element.
    void check_ply(const std::string &path)
    {
      std::ifstream in(path, std::ios::binary);
      std::string   line;
      std::getline(in, line);
      if (line != "ply" && line != "ply\r")
        throw InputError(path + ":1", "not a PLY file (it does not start with 'ply')");
      const std::map<std::string, int> sizes = {{"char", 1},  {"uchar", 1},  {"int8", 1},    {"uint8", 1},
                                                {"short", 2}, {"ushort", 2}, {"int16", 2},   {"uint16", 2},
                                                {"int", 4},   {"uint", 4},   {"int32", 4},   {"uint32", 4},
                                                {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
      struct Property
      {
        std::string name, type, count_type; // count_type: a list
      };
      struct Element
      {
        std::string           name;
        long                  count = 0;
        std::vector<Property> properties;
      };
      std::vector<Element> elements;
      std::string          format;
      long                 n = 1;
      auto fail = [&](const std::string &what) { throw InputError(path + ":" + std::to_string(n), what); };
      auto type_size = [&](const std::string &t) {
        const auto it = sizes.find(t);
        if (it == sizes.end())
          fail("unknown PLY type '" + t + "'");
        return it->second;
      };
      for (bool ended = false; !ended;)
        {
          if (!std::getline(in, line))
            fail("the header has no end_header line");
          ++n;
          if (!line.empty() && line.back() == '\r')
            line.pop_back();
          std::istringstream words(line);
          std::string        kind;
          words >> kind;
          if (kind == "end_header")
            ended = true;
          else if (kind == "format")
            {
              std::string version;
              words >> format >> version;
              if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
                fail("unknown PLY format '" + format + "'");
            }
          else if (kind == "comment" || kind == "obj_info")
            continue;
          else if (kind == "element")
            {
              Element e;
              words >> e.name >> e.count;
              if (!words || e.count < 0 || e.count > (1L << 32))
                fail("'element NAME COUNT' expected");
              elements.push_back(e);
            }
          else if (kind == "property")
            {
              if (elements.empty())
                fail("a property before any element");
              Property p;
              words >> p.type;
              if (p.type == "list")
                {
                  words >> p.count_type >> p.type;
                  type_size(p.count_type);
                }
              type_size(p.type);
              words >> p.name;
              if (!words)
                fail("'property TYPE NAME' expected");
              elements.back().properties.push_back(p);
            }
          else
            fail("unknown PLY header line '" + line.substr(0, 40) + "'");
        }
      if (format.empty())
        fail("the header has no format line");
      long vertices = -1;
      for (const auto &e : elements)
        if (e.name == "vertex")
          {
            vertices = e.count;
            for (const char *c : {"x", "y", "z"})
              if (std::none_of(e.properties.begin(), e.properties.end(), [&](const Property &p) {
                    return p.name == c && p.count_type.empty();
                  }))
                fail(std::string("the vertices have no property ") + c);
          }
        else if (e.name == "face" && std::none_of(e.properties.begin(), e.properties.end(), [](const Property &p) {
                   return !p.count_type.empty() && (p.name == "vertex_indices" || p.name == "vertex_index");
                 }))
          fail("the faces have no index list (property list ... vertex_indices)");
      if (vertices < 0)
        fail("the header declares no vertex element");

      const bool ascii = format == "ascii";
      const bool swap  = format == "binary_big_endian";
      // one value of type t: from the ASCII line's words, or from the binary stream
      std::istringstream words;
      auto               value = [&](const std::string &t) {
        if (ascii)
          {
            std::string word;
            if (!(words >> word))
              fail("fewer values than the header declares");
            std::size_t used = 0;
            double      x    = 0;
            try
              {
                x = std::stod(word, &used);
              }
            catch (const std::exception &)
              {
                used = 0;
              }
            if (used != word.size() || !std::isfinite(x))
              fail("'" + word.substr(0, 20) + "' is not a finite number");
            return x;
          }
        unsigned char bytes[8] = {};
        const int     size     = type_size(t);
        if (!in.read(reinterpret_cast<char *>(bytes), size))
          throw InputError(path, "the file ends inside its data (the header announces more than it holds)");
        if (swap)
          std::reverse(bytes, bytes + size);
        double x = 0;
        if (t == "float" || t == "float32")
          {
            float f;
            std::memcpy(&f, bytes, 4);
            x = f;
          }
        else if (t == "double" || t == "float64")
          std::memcpy(&x, bytes, 8);
        else
          {
            const bool is_signed = t[0] != 'u';
            long long  v         = 0;
            for (int k = size - 1; k >= 0; --k)
              v = (v << 8) | bytes[k];
            if (is_signed && size < 8 && (v >> (8 * size - 1)) & 1)
              v -= 1LL << (8 * size);
            x = double(v);
          }
        if (!std::isfinite(x))
          throw InputError(path, "a value that is not a finite number");
        return x;
      };
      for (const auto &e : elements)
        for (long item = 0; item < e.count; ++item)
          {
            if (ascii)
              {
                do
                  {
                    if (!std::getline(in, line))
                      throw InputError(path, "the header announces " + std::to_string(e.count) + " " + e.name +
                                               " elements, the file ends at " + e.name + " " + std::to_string(item));
                    ++n;
                  }
                while (line.find_first_not_of(" \t\r") == std::string::npos);
                words.clear();
                words.str(line);
              }
            for (const auto &p : e.properties)
              {
                const long count = p.count_type.empty() ? 1 : long(value(p.count_type));
                if (count < 0 || count > 1000)
                  fail("a list of " + std::to_string(count) + " values");
                if (e.name == "face" && !p.count_type.empty() && count < 3)
                  fail("a face of " + std::to_string(count) + " vertices");
                for (long k = 0; k < count; ++k)
                  {
                    const double x = value(p.type);
                    if (e.name == "face" && !p.count_type.empty() && (x < 0 || x >= double(vertices) || x != std::floor(x)))
                      fail("vertex index " + std::to_string(x) + " out of range (" + std::to_string(vertices) +
                           " vertices, counted from 0)");
                  }
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
