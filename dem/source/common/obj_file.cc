// Wavefront OBJ files read by abrade rather than by vtkOBJReader, which trusts the file: a
// texture or normal index past its list (`f 1/9/9 2/9/9 3/9/9`) crashed it, `v 0 0 nan` and
// `v 0 0 inf` came back as 0, `v 0 0` got z = 0, and faces of another corner format than the
// file's first (`f 1//1 2//1 3//1` then `f 3 4 5`) were dropped without a word. Here every
// coordinate is a finite number, every index (vertex, texture, normal) names an element defined
// before its line, and every corner format is read; errors name the line.
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/obj_file.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace abrade::io
{
  vtkSmartPointer<vtkPolyData> read_obj(const std::string &path)
  {
    std::ifstream in(path);
    if (!in)
      throw InputError(path, "cannot read the file");
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    vtkNew<vtkCellArray>   polys;
    long                   textures = 0, normals = 0;
    std::vector<vtkIdType> face;
    std::string            line;
    for (long n = 1; std::getline(in, line); ++n)
      {
        auto fail = [&](const std::string &what) { throw InputError(path + ":" + std::to_string(n), what); };
        if (!line.empty() && line.back() == '\r')
          line.pop_back();
        std::istringstream words(line.substr(0, line.find('#')));
        std::string        kind;
        words >> kind;
        if (kind == "v")
          {
            double xyz[3];
            for (int k = 0; k < 3; ++k)
              {
                std::string word;
                if (!(words >> word))
                  fail("a vertex needs three coordinates (x y z), this one has " + std::to_string(k));
                const auto x = finite_number(word);
                if (!x)
                  fail("vertex coordinate '" + word.substr(0, 20) + "' is not a finite number");
                xyz[k] = *x;
              }
            points->InsertNextPoint(xyz);
          }
        else if (kind == "vt")
          ++textures;
        else if (kind == "vn")
          ++normals;
        else if (kind == "f")
          {
            // a corner: v, v/vt, v//vn or v/vt/vn; an index counts from 1, or back from -1
            auto index = [&](const std::string &corner, const std::string &number, long defined,
                             const char *what, const char *whats) -> long {
              const auto read = whole_number(number);
              if (!read)
                fail("'" + corner.substr(0, 40) + "' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
              const long i = *read;
              if (i == 0 || i > defined || i < -defined)
                fail(std::string(what) + " index " + number + " out of range (" + std::to_string(defined) + " " +
                     whats + " defined before this line; indices count from 1, or back from -1)");
              return i > 0 ? i - 1 : defined + i;
            };
            face.clear();
            for (std::string corner; words >> corner;)
              {
                std::vector<std::string> parts;
                std::istringstream       split(corner);
                for (std::string p; std::getline(split, p, '/');)
                  parts.push_back(p);
                if (!corner.empty() && corner.back() == '/')
                  parts.push_back("");
                if (parts.empty() || parts.size() > 3)
                  fail("'" + corner.substr(0, 40) + "' is not a face corner (v, v/vt, v//vn or v/vt/vn)");
                face.push_back(vtkIdType(index(corner, parts[0], long(points->GetNumberOfPoints()), "vertex", "vertices")));
                if (parts.size() >= 2 && !parts[1].empty())
                  index(corner, parts[1], textures, "texture coordinate", "texture coordinates");
                if (parts.size() == 3)
                  index(corner, parts[2], normals, "normal", "normals");
              }
            if (face.size() < 3)
              fail("a face of " + std::to_string(face.size()) + " corner(s); a face needs at least three");
            polys->InsertNextCell(vtkIdType(face.size()), face.data());
          }
        // o, g, s, usemtl, mtllib, l, p and the free-form entries carry nothing a surface needs
      }
    auto polydata = vtkSmartPointer<vtkPolyData>::New();
    polydata->SetPoints(points);
    polydata->SetPolys(polys);
    return polydata;
  }
} // namespace abrade::io
