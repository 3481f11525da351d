// The geometry of a legacy VTK file (.vtk, DATASET POLYDATA), read here rather than by
// vtkPolyDataReader: VTK's reader follows the cell counts and point indices of a file without
// checking them, and a damaged file (a count of 2147483647, an index past the points, a file cut
// short) makes it read out of bounds and crash. Here every count is checked against what the
// file holds and every index against the points, and an error names the line (ASCII) or the
// section (BINARY). Walls and scans need the geometry only: point and cell data are not read.
//
// The format (VTK User's Guide, "VTK File Formats"): four header lines (version, title,
// ASCII|BINARY, DATASET POLYDATA), then sections
//   POINTS n type             3n values
//   VERTICES|LINES|POLYGONS|TRIANGLE_STRIPS n size
//     up to version 4: n cells as "k i1 ... ik", size = n + sum k values in all;
//     version 5: "OFFSETS type" (n values) and "CONNECTIVITY type" (size values) follow
//   FIELD, METADATA            (skipped)
//   POINT_DATA, CELL_DATA      (the end of the geometry)
// BINARY data is big-endian and follows its section line directly.
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/legacy_vtk.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

namespace abrade::io
{
  namespace
  {
    class LegacyVtkFile
    {
    public:
      explicit LegacyVtkFile(const std::string &path) : path(path)
      {
        std::ifstream in(path, std::ios::binary);
        if (!in)
          throw InputError(path, "cannot open the file");
        text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
      }

      /// The next line that is not blank (without its end and trailing blanks), or "" at the end
      /// of the file; with @p raw the next line as it is, blank or not.
      std::string line(bool raw = false)
      {
        while (at < text.size())
          {
            const std::size_t end = std::min(text.find('\n', at), text.size());
            std::string       l   = text.substr(at, end - at);
            token                 = at;
            at                    = end + 1;
            while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t'))
              l.pop_back();
            if (raw || l.find_first_not_of(" \t") != std::string::npos)
              return l;
          }
        return "";
      }

      bool at_end() const { return at >= text.size(); }

      /// @p count values of VTK type @p type (ASCII words or big-endian bytes).
      std::vector<double> values(long count, const std::string &type)
      {
        const auto size = sizes.find(type);
        if (size == sizes.end())
          fail("unknown data type '" + type + "'");
        const double rest = double(text.size() - std::min(at, text.size()));
        if (count < 0 || (binary ? double(count) * size->second > rest : double(count) > rest / 2 + 1))
          fail("announces " + std::to_string(count) + " values, more than the rest of the file holds");
        std::vector<double> v(count);
        if (binary)
          {
            for (long k = 0; k < count; ++k)
              {
                unsigned char b[8];
                std::memcpy(b, text.data() + at, size->second);
                at += size->second;
                std::reverse(b, b + size->second); // big-endian
                v[k] = decode(b, type, size->second);
                if (!std::isfinite(v[k]))
                  fail("a value that is not a finite number (value " + std::to_string(k) + " of the section)");
              }
            if (at < text.size() && text[at] == '\n')
              ++at;
          }
        else
          for (long k = 0; k < count; ++k)
            {
              const std::size_t a = text.find_first_not_of(" \t\r\n", at);
              if (a == std::string::npos)
                fail("the file ends after " + std::to_string(k) + " of " + std::to_string(count) + " values");
              token = a;
              at = std::min(text.find_first_of(" \t\r\n", a), text.size());
              const std::string word = text.substr(a, at - a);
              const auto        x    = finite_number(word);
              if (!x)
                fail("'" + word.substr(0, 20) + "' is not a finite number");
              v[k] = *x;
              if (type != "float" && type != "double" && v[k] != std::floor(v[k]))
                fail("'" + word.substr(0, 20) + "' is not an integer");
            }
        return v;
      }

      std::size_t position() const { return at; }
      void        seek(std::size_t p) { at = p; }

      [[noreturn]] void fail(const std::string &what) const
      {
        const long line = 1 + long(std::count(text.begin(), text.begin() + long(std::min(token, text.size())), '\n'));
        throw InputError(path + (binary ? "" : ":" + std::to_string(line)), what);
      }

      const std::string path;
      bool              binary = false;

    private:
      static double decode(const unsigned char *b, const std::string &type, int size)
      {
        if (type == "float")
          {
            float f;
            std::memcpy(&f, b, 4);
            return f;
          }
        if (type == "double")
          {
            double d;
            std::memcpy(&d, b, 8);
            return d;
          }
        long long v = 0;
        for (int k = size - 1; k >= 0; --k)
          v = (v << 8) | b[k];
        const bool is_signed = type.find("unsigned") == std::string::npos && type.find("uint") == std::string::npos;
        if (is_signed && size < 8 && ((v >> (8 * size - 1)) & 1))
          v -= 1LL << (8 * size);
        return double(v);
      }

      const std::map<std::string, int> sizes = {
        {"bit", 1}, {"char", 1}, {"unsigned_char", 1}, {"short", 2}, {"unsigned_short", 2}, {"int", 4},
        {"unsigned_int", 4}, {"long", 8}, {"unsigned_long", 8}, {"float", 4}, {"double", 8},
        {"vtktypeint32", 4}, {"vtktypeuint32", 4}, {"vtktypeint64", 8}, {"vtktypeuint64", 8}};
      std::string text;
      std::size_t at    = 0;
      std::size_t token = 0; ///< where the line or value read last starts (for the line number)
    };

    long count_from(LegacyVtkFile &f, const std::string &word, const std::string &what)
    {
      char      *end = nullptr;
      const long n   = std::strtol(word.c_str(), &end, 10);
      if (word.empty() || *end != '\0' || n < 0 || n > (1L << 40))
        f.fail("'" + word.substr(0, 20) + "' is not a count of " + what);
      return n;
    }

    /// The four header lines: the version, the title, ASCII or BINARY, DATASET POLYDATA.
    void read_header(LegacyVtkFile &f)
    {
      if (f.line().rfind("# vtk DataFile Version", 0) != 0)
        f.fail("not a legacy VTK file (it does not start with '# vtk DataFile Version')");
      f.line(true); // the title (it may be empty)
      std::string format = f.line();
      std::transform(format.begin(), format.end(), format.begin(), ::toupper);
      if (format != "ASCII" && format != "BINARY")
        f.fail("'ASCII' or 'BINARY' expected, found '" + format.substr(0, 40) + "'");
      const std::string dataset = f.line();
      if (dataset != "DATASET POLYDATA")
        f.fail("'" + dataset.substr(0, 40) + "': only DATASET POLYDATA is read (save other kinds as .vtp or .stl)");
      f.binary = format == "BINARY";
    }

    /// "POINTS n type": the number of points and their coordinates into @p points.
    long read_points(LegacyVtkFile &f, const std::string &count, const std::string &type, vtkPoints *points)
    {
      const long n   = count_from(f, count, "points");
      const auto xyz = f.values(3 * n, type);
      points->SetDataTypeToDouble();
      points->SetNumberOfPoints(n);
      for (long i = 0; i < n; ++i)
        points->SetPoint(i, xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      return n;
    }

    /// A cell section's cells: where each starts in the point indices (offsets, one more than
    /// the cells) and the indices.
    struct Cells
    {
      std::vector<long>      offsets = {0};
      std::vector<vtkIdType> ids;
    };

    /// Version 5: "OFFSETS type" (@p n offsets), then "CONNECTIVITY type" (@p size indices).
    Cells offsets_and_connectivity(LegacyVtkFile &f, const std::string &key, long n, long size,
                                   const std::string &offsets_type)
    {
      Cells      cells;
      const auto o = f.values(n, offsets_type);
      cells.offsets.assign(o.begin(), o.end());
      // (a CONNECTIVITY line without a type takes the offsets')
      std::string next_key = "OFFSETS", type = offsets_type;
      std::istringstream(f.line()) >> next_key >> type;
      if (next_key != "CONNECTIVITY")
        f.fail(key + ": CONNECTIVITY expected after OFFSETS");
      const auto c = f.values(size, type);
      cells.ids.assign(c.begin(), c.end());
      if (n < 1 || cells.offsets.front() != 0 || cells.offsets.back() != size ||
          !std::is_sorted(cells.offsets.begin(), cells.offsets.end()))
        f.fail(key + ": the offsets do not run from 0 to " + std::to_string(size) + " in order");
      return cells;
    }

    /// Up to version 4: @p n cells as "k i1 ... ik", @p size values in all.
    Cells counted_cells(LegacyVtkFile &f, const std::string &key, long n, long size)
    {
      Cells      cells;
      const auto v = f.values(size, "int");
      long       p = 0;
      for (long c = 0; c < n; ++c)
        {
          // (compared as read: a count past a long's range has no long value)
          const double counted = p < size ? v[p] : -1;
          const long   k       = counted >= 1 && counted <= double(size - p - 1) ? long(counted) : -1;
          if (k < 1 || p + 1 + k > size)
            f.fail(key + ": cell " + std::to_string(c) + " of " + std::to_string(n) +
                   " does not fit into the section's " + std::to_string(size) + " values");
          cells.ids.insert(cells.ids.end(), v.begin() + p + 1, v.begin() + p + 1 + k);
          cells.offsets.push_back(long(cells.ids.size()));
          p += 1 + k;
        }
      if (p != size)
        f.fail(key + ": " + std::to_string(n) + " cells take " + std::to_string(p) + " values, the section announces " +
               std::to_string(size));
      return cells;
    }

    /// "VERTICES|LINES|POLYGONS|TRIANGLE_STRIPS n size" (either layout), checked against the
    /// @p n_points points; the polygons and the strips' triangles into @p polys.
    void read_cells(LegacyVtkFile &f, const std::string &key, const std::string &count, const std::string &values,
                    long n_points, vtkCellArray *polys)
    {
      if (n_points < 0)
        f.fail(key + " before POINTS");
      const long         n = count_from(f, count, "cells"), size = count_from(f, values, "values");
      const auto         mark = f.position();
      std::string        next_key, type;
      std::istringstream(f.line()) >> next_key >> type;
      Cells cells;
      if (next_key == "OFFSETS")
        cells = offsets_and_connectivity(f, key, n, size, type);
      else
        {
          f.seek(mark);
          cells = counted_cells(f, key, n, size);
        }
      for (const vtkIdType id : cells.ids)
        if (id < 0 || id >= n_points)
          f.fail(key + ": point index " + std::to_string(id) + " out of range (" + std::to_string(n_points) +
                 " points, counted from 0)");
      for (std::size_t c = 0; c + 1 < cells.offsets.size(); ++c)
        {
          const vtkIdType *cell = cells.ids.data() + cells.offsets[c];
          const long       k    = cells.offsets[c + 1] - cells.offsets[c];
          if (key == "POLYGONS" && k >= 3)
            polys->InsertNextCell(k, cell);
          else if (key == "POLYGONS")
            f.fail("POLYGONS: polygon " + std::to_string(c) + " has " + std::to_string(k) + " points");
          else if (key == "TRIANGLE_STRIPS") // triangles (i, i+1, i+2), every other one turned
            for (long t = 0; t + 2 < k; ++t)
              {
                const vtkIdType tri[3] = {cell[t], cell[t + (t % 2 ? 2 : 1)], cell[t + (t % 2 ? 1 : 2)]};
                polys->InsertNextCell(3, tri);
              }
        }
    }

    /// "FIELD name n": n arrays "name components tuples type" and their values, skipped.
    void skip_field(LegacyVtkFile &f, const std::string &n_arrays)
    {
      const long arrays = count_from(f, n_arrays, "arrays");
      for (long k = 0; k < arrays; ++k)
        {
          std::istringstream array(f.line());
          std::string        name, components, tuples, type;
          array >> name >> components >> tuples >> type;
          if (name == "NULL_ARRAY")
            continue;
          f.values(count_from(f, components, "components") * count_from(f, tuples, "tuples"), type);
        }
    }
  } // namespace

  vtkSmartPointer<vtkPolyData> read_legacy_vtk(const std::string &path)
  {
    LegacyVtkFile f(path);
    read_header(f);
    auto                 polydata = vtkSmartPointer<vtkPolyData>::New();
    vtkNew<vtkPoints>    points;
    vtkNew<vtkCellArray> polys;
    long                 n_points = -1;
    for (std::string l = f.line(); !l.empty(); l = f.line())
      {
        std::istringstream words(l);
        std::string        key, a, b;
        words >> key >> a >> b;
        if (key == "POINT_DATA" || key == "CELL_DATA") // (the end of the geometry)
          break;
        if (key == "POINTS")
          {
            if (n_points >= 0) // (the cells read so far index the first points)
              f.fail("POINTS given twice");
            n_points = read_points(f, a, b, points);
          }
        else if (key == "VERTICES" || key == "LINES" || key == "POLYGONS" || key == "TRIANGLE_STRIPS")
          read_cells(f, key, a, b, n_points, polys);
        else if (key == "METADATA") // information keys, up to a blank line
          while (!f.at_end() && !f.line(true).empty())
            ;
        else if (key == "FIELD")
          skip_field(f, b);
        else
          f.fail("unknown section '" + l.substr(0, 40) + "'");
      }
    polydata->SetPoints(points);
    polydata->SetPolys(polys);
    return polydata;
  }
} // namespace abrade::io
