// PLY files (Turk's polygon file format: ASCII, binary little- and big-endian)
// read by abrade rather than by vtkPLYReader, which trusts the file: a header
// announcing more than the file holds, an unknown keyword, an index past the
// vertices or a last line without its newline freed pointers twice and crashed.
// The whole file is walked as its header declares it: known keywords and types
// only, x, y, z for the vertices and an index list for the faces, every number
// finite and every index a vertex; errors name the line (ASCII) or the element.
// Other properties (normals, colours) are read past; the geometry is what walls
// and scans need.
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/format_number.h>
#include <abrade/common/ply_file.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace abrade::io
{
  namespace
  {
    struct Property
    {
      std::string name, type, count_type; // count_type: a list
      bool        is_list() const { return !count_type.empty(); }
      bool        is_vertex_indices() const { return is_list() && (name == "vertex_indices" || name == "vertex_index"); }
    };

    struct Element
    {
      std::string           name;
      long                  count = 0;
      std::vector<Property> properties;
    };

    /// One PLY file, walked as its header declares it. Errors name the line being read (n).
    class PlyReader
    {
    public:
      explicit PlyReader(const std::string &path)
        : path(path), in(path, std::ios::binary)
      {}

      vtkSmartPointer<vtkPolyData> read()
      {
        read_header();
        check_the_geometry_is_declared();
        check_the_counts_fit_the_file();
        return read_the_elements();
      }

    private:
      const std::string    path;
      std::ifstream        in;
      std::string          line;
      long                 n = 1; ///< the line number
      std::string          format;
      std::vector<Element> elements;
      long                 vertices = -1;
      std::istringstream   words; ///< an ASCII element's values

      [[noreturn]] void fail(const std::string &what) const { throw InputError(path + ":" + std::to_string(n), what); }

      int type_size(const std::string &t) const
      {
        static const std::map<std::string, int> sizes = {
          {"char", 1}, {"uchar", 1}, {"int8", 1},  {"uint8", 1},  {"short", 2},   {"ushort", 2},  {"int16", 2},  {"uint16", 2},
          {"int", 4},  {"uint", 4},  {"int32", 4}, {"uint32", 4}, {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
        const auto it = sizes.find(t);
        if (it == sizes.end())
          fail("unknown PLY type '" + t + "'");
        return it->second;
      }

      /// "ply", then format, element and property lines up to end_header (comments skipped).
      void read_header()
      {
        std::getline(in, line);
        if (line != "ply" && line != "ply\r")
          throw InputError(path + ":1", "not a PLY file (it does not start with 'ply')");
        for (bool ended = false; !ended;)
          {
            if (!std::getline(in, line))
              fail("the header has no end_header line");
            ++n;
            if (!line.empty() && line.back() == '\r')
              line.pop_back();
            std::istringstream header(line);
            std::string        kind;
            header >> kind;
            if (kind == "end_header")
              ended = true;
            else if (kind == "format")
              {
                std::string version;
                header >> format >> version;
                if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
                  fail("unknown PLY format '" + format + "'");
              }
            else if (kind == "comment" || kind == "obj_info")
              continue;
            else if (kind == "element")
              {
                Element e;
                header >> e.name >> e.count;
                if (!header || e.count < 0 || e.count > (1L << 32))
                  fail("'element NAME COUNT' expected");
                elements.push_back(e);
              }
            else if (kind == "property")
              read_property(header);
            else
              fail("unknown PLY header line '" + line.substr(0, 40) + "'");
          }
        if (format.empty())
          fail("the header has no format line");
      }

      /// A property line's TYPE NAME or list COUNT_TYPE TYPE NAME, for the last element.
      void read_property(std::istringstream &header)
      {
        if (elements.empty())
          fail("a property before any element");
        Property p;
        header >> p.type;
        if (p.type == "list")
          {
            header >> p.count_type >> p.type;
            type_size(p.count_type);
            if (p.count_type.find("float") != std::string::npos || p.count_type == "double")
              fail("a list's count type must be an integer type, not " + p.count_type);
          }
        type_size(p.type);
        header >> p.name;
        if (!header)
          fail("'property TYPE NAME' expected");
        elements.back().properties.push_back(p);
      }

      /// The vertices have x, y, z and the faces an index list.
      void check_the_geometry_is_declared()
      {
        for (const auto &e : elements)
          if (e.name == "vertex")
            {
              vertices = e.count;
              for (const char *c : {"x", "y", "z"})
                if (std::none_of(e.properties.begin(), e.properties.end(),
                                 [&](const Property &p) { return p.name == c && !p.is_list(); }))
                  fail(std::string("the vertices have no property ") + c);
            }
          else if (e.name == "face" && std::none_of(e.properties.begin(), e.properties.end(),
                                                    [](const Property &p) { return p.is_vertex_indices(); }))
            fail("the faces have no index list (property list ... vertex_indices)");
        if (vertices < 0)
          fail("the header declares no vertex element");
      }

      /// Every element takes at least a byte of the file (more in ASCII): counts the file
      /// cannot hold are refused before anything is read, and an element without properties
      /// holds nothing.
      void check_the_counts_fit_the_file() const
      {
        const double size  = double(std::filesystem::file_size(path));
        double       least = 0;
        for (const auto &e : elements)
          {
            if (e.count > 0 && e.properties.empty())
              fail("element " + e.name + " has no properties");
            least += double(e.count);
          }
        if (least > size)
          fail("the header announces " + std::to_string(long(least)) + " elements, more than the file's " +
               std::to_string(long(size)) + " bytes can hold");
      }

      /// One value of type @p t: from the ASCII line's words, or from the binary stream.
      double value(const std::string &t)
      {
        if (format == "ascii")
          {
            std::string word;
            if (!(words >> word))
              fail("fewer values than the header declares");
            const auto x = finite_number(word);
            if (!x)
              fail("'" + word.substr(0, 20) + "' is not a finite number");
            return *x;
          }
        unsigned char bytes[8] = {};
        const int     size     = type_size(t);
        if (!in.read(reinterpret_cast<char *>(bytes), size))
          throw InputError(path, "the file ends inside its data (the header announces more than it holds)");
        if (format == "binary_big_endian")
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
      }

      /// In ASCII, the next line that is not blank, as the element @p item of @p e.
      void next_ascii_line(const Element &e, long item)
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

      /// Every element's values: the vertices' x, y, z and the faces' index lists kept, other
      /// properties (normals, colours) read past; each index a vertex.
      vtkSmartPointer<vtkPolyData> read_the_elements()
      {
        vtkNew<vtkPoints> points;
        points->SetDataTypeToDouble();
        vtkNew<vtkCellArray>   polys;
        std::vector<vtkIdType> face;
        for (const auto &e : elements)
          for (long item = 0; item < e.count; ++item)
            {
              if (format == "ascii")
                next_ascii_line(e, item);
              double xyz[3] = {0, 0, 0};
              for (const auto &p : e.properties)
                {
                  // (checked as read: a count past a long's range, 1.8e19 say, has no long value)
                  const double counted = p.is_list() ? value(p.count_type) : 1;
                  if (!(counted >= 0 && counted <= 1000))
                    fail("a list of " + format_number(counted) + " values");
                  const long count   = long(counted);
                  const bool indices = e.name == "face" && p.is_vertex_indices();
                  if (indices && count < 3)
                    fail("a face of " + std::to_string(count) + " vertices");
                  face.clear();
                  for (long k = 0; k < count; ++k)
                    {
                      const double x = value(p.type);
                      if (indices && (x < 0 || x >= double(vertices) || x != std::floor(x)))
                        fail("vertex index " + std::to_string(x) + " out of range (" + std::to_string(vertices) +
                             " vertices, counted from 0)");
                      if (indices)
                        face.push_back(vtkIdType(x));
                      else if (e.name == "vertex" && !p.is_list() && p.name.size() == 1 && p.name[0] >= 'x' &&
                               p.name[0] <= 'z')
                        xyz[p.name[0] - 'x'] = x;
                    }
                  if (indices)
                    polys->InsertNextCell(vtkIdType(face.size()), face.data());
                }
              if (e.name == "vertex")
                points->InsertNextPoint(xyz);
            }
        auto polydata = vtkSmartPointer<vtkPolyData>::New();
        polydata->SetPoints(points);
        polydata->SetPolys(polys);
        return polydata;
      }
    };
  } // namespace

  vtkSmartPointer<vtkPolyData> read_ply(const std::string &path)
  {
    return PlyReader(path).read();
  }
} // namespace abrade::io
