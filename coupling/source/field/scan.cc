// Field geometry (worn knives predicted, scanned or designed) read as surfaces or point clouds
// (scan.h).
#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>
#include <abrade/field/scan.h>

#include <vtkCellArray.h>
#include <vtkCleanPolyData.h>
#include <vtkFeatureEdges.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTriangle.h>
#include <vtkCellData.h>
#include <vtkPolyDataNormals.h>
#include <vtkReverseSense.h>
#include <vtkTriangleFilter.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace abrade::field
{
  namespace
  {
    /// "x y z" / "x,y,z" / "x;y;z" per line; a first line that is not numeric is a header.
    vtkSmartPointer<vtkPolyData> read_point_table(const std::string &path)
    {
      std::ifstream in(path);
      if (!in)
        throw InputError(path, "cannot open the file");
      vtkNew<vtkPoints> points;
      std::string       line;
      long              number = 0, data_lines = 0;
      while (std::getline(in, line))
        {
          ++number;
          const auto hash = line.find('#');
          if (hash != std::string::npos)
            line.erase(hash);
          for (char &c : line)
            if (c == ',' || c == ';' || c == '\t')
              c = ' ';
          std::istringstream s(line);
          std::vector<double> v;
          std::string         word;
          bool                numeric = true;
          while (s >> word)
            {
              try
                {
                  std::size_t used = 0;
                  v.push_back(std::stod(word, &used));
                  numeric = numeric && used == word.size();
                }
              catch (const std::exception &)
                {
                  numeric = false;
                }
            }
          if (v.empty() && numeric)
            continue; // blank or comment
          if (!numeric || v.size() < 3)
            {
              if (data_lines == 0 && !numeric)
                continue; // header
              throw InputError(path + ":" + std::to_string(number), "expected three numbers x y z, found '" + line + "'");
            }
          if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
            throw InputError(path + ":" + std::to_string(number), "non-finite coordinate");
          points->InsertNextPoint(v[0], v[1], v[2]);
          ++data_lines;
        }
      vtkSmartPointer<vtkPolyData> p = vtkSmartPointer<vtkPolyData>::New();
      p->SetPoints(points);
      return p;
    }

    long count_edges(vtkPolyData *p, bool boundary)
    {
      vtkNew<vtkFeatureEdges> e;
      e->SetInputData(p);
      e->FeatureEdgesOff();
      e->ManifoldEdgesOff();
      e->BoundaryEdgesOff();
      e->NonManifoldEdgesOff();
      if (boundary)
        e->BoundaryEdgesOn();
      else
        e->NonManifoldEdgesOn();
      e->Update();
      return e->GetOutput()->GetNumberOfCells();
    }
  } // namespace

  double Geometry::size() const
  {
    double b[6];
    data->GetBounds(b);
    return std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) + (b[5] - b[4]) * (b[5] - b[4]));
  }

  std::array<double, 3> Geometry::centroid() const
  {
    std::array<double, 3> c{0, 0, 0};
    double                weight = 0;
    if (point_cloud)
      {
        for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
          {
            const double *p = data->GetPoint(i);
            for (int k = 0; k < 3; ++k)
              c[k] += p[k];
          }
        weight = double(data->GetNumberOfPoints());
      }
    else
      for (vtkIdType t = 0; t < data->GetNumberOfCells(); ++t)
        {
          double a[3], b[3], d[3];
          vtkIdType        n;
          const vtkIdType *ids;
          data->GetCellPoints(t, n, ids);
          data->GetPoint(ids[0], a), data->GetPoint(ids[1], b), data->GetPoint(ids[2], d);
          const double area = vtkTriangle::TriangleArea(a, b, d);
          for (int k = 0; k < 3; ++k)
            c[k] += area * (a[k] + b[k] + d[k]) / 3;
          weight += area;
        }
    for (double &x : c)
      x /= weight;
    return c;
  }

  vtkSmartPointer<vtkPolyData> consistently_oriented(vtkPolyData *surface, bool outward)
  {
    // VTK's normals filter reorders the triangles as it computes cell normals (with none asked
    // for it passes its input through unchanged)
    vtkNew<vtkPolyDataNormals> orient;
    orient->SetInputData(surface);
    orient->ConsistencyOn();
    orient->SetAutoOrientNormals(outward);
    orient->SplittingOff();
    orient->ComputePointNormalsOff();
    orient->ComputeCellNormalsOn();
    orient->Update();
    vtkSmartPointer<vtkPolyData> out = vtkSmartPointer<vtkPolyData>::New();
    out->ShallowCopy(orient->GetOutput());
    out->GetCellData()->RemoveArray("Normals");
    return out;
  }

  double signed_volume(vtkPolyData *surface)
  {
    double v = 0;
    for (vtkIdType t = 0; t < surface->GetNumberOfCells(); ++t)
      {
        vtkIdType        n;
        const vtkIdType *ids;
        surface->GetCellPoints(t, n, ids);
        if (n != 3)
          continue;
        double a[3], b[3], c[3];
        surface->GetPoint(ids[0], a), surface->GetPoint(ids[1], b), surface->GetPoint(ids[2], c);
        v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
      }
    return v;
  }

  double Geometry::volume() const
  {
    if (!closed)
      return 0;
    vtkNew<vtkMassProperties> m;
    m->SetInputData(data);
    m->Update();
    return m->GetVolume();
  }

  Geometry read_geometry(const std::string &path, std::vector<std::string> &warnings)
  {
    Geometry          g;
    g.path            = path;
    const std::string ext = io::lower_extension(path);
    vtkSmartPointer<vtkPolyData> raw =
      ext == ".xyz" || ext == ".csv" || ext == ".txt" ? read_point_table(path) : io::read_polydata(path);
    if (!raw || raw->GetNumberOfPoints() == 0)
      throw InputError(path, "holds no points (empty or malformed file)");
    for (vtkIdType i = 0; i < raw->GetNumberOfPoints(); ++i)
      {
        const double *p = raw->GetPoint(i);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
          throw InputError(path, "point " + std::to_string(i) + " has a non-finite coordinate");
      }
    g.point_cloud = raw->GetNumberOfPolys() == 0;
    if (g.point_cloud)
      {
        g.data = vtkSmartPointer<vtkPolyData>::New();
        g.data->SetPoints(raw->GetPoints());
        if (raw->GetNumberOfPoints() < 10)
          throw InputError(path, "a point cloud of " + std::to_string(raw->GetNumberOfPoints()) +
                                   " points is too small to register or compare");
        return g;
      }
    vtkNew<vtkTriangleFilter> tri;
    tri->SetInputData(raw);
    tri->PassLinesOff();
    tri->PassVertsOff();
    vtkNew<vtkCleanPolyData> clean; // merges the coincident points of STL triangles
    clean->SetInputConnection(tri->GetOutputPort());
    clean->SetTolerance(1e-9);
    clean->ConvertPolysToLinesOff();
    clean->Update();
    g.data = clean->GetOutput();
    if (g.data->GetNumberOfPolys() == 0)
      throw InputError(path, "all triangles are degenerate");
    g.non_manifold_edges = count_edges(g.data, false);
    g.boundary_edges     = count_edges(g.data, true);
    g.closed             = g.non_manifold_edges == 0 && g.boundary_edges == 0;
    if (g.closed)
      {
        // a closed surface must face outward: every signed distance (inside / outside) and the
        // enclosed volumes rely on it. Inward or mixed triangles (an export that flipped them)
        // are oriented outward by VTK's normals filter, with a warning.
        const double                 before   = signed_volume(g.data);
        vtkSmartPointer<vtkPolyData> oriented = consistently_oriented(g.data, true);
        if (signed_volume(oriented) < 0) // all of them inward: turned round
          {
            vtkNew<vtkReverseSense> reverse;
            reverse->SetInputData(oriented);
            reverse->ReverseCellsOn();
            reverse->ReverseNormalsOff();
            reverse->Update();
            oriented = reverse->GetOutput();
          }
        const double after = signed_volume(oriented);
        if (!(before > 0.999999 * after))
          {
            g.data = oriented;
            warnings.push_back(path + ": its triangles face inward" + (before > -0.999999 * after ? " in part" : "") +
                               " (enclosed volume " + std::to_string(before) + " m^3 instead of " +
                               std::to_string(after) + " m^3): turned to face outward");
          }
      }
    if (g.non_manifold_edges > 0)
      warnings.push_back(path + ": " + std::to_string(g.non_manifold_edges) +
                         " non-manifold edges (edges of more than two triangles): distances are still "
                         "computed, enclosed volumes are not");
    else if (g.boundary_edges > 0)
      warnings.push_back(path + ": an open surface (" + std::to_string(g.boundary_edges) +
                         " boundary edges): worn volumes are integrated over the scanned area only");
    return g;
  }

  void scale(Geometry &g, double factor)
  {
    vtkPoints *p = g.data->GetPoints();
    for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
      {
        double x[3];
        p->GetPoint(i, x);
        p->SetPoint(i, factor * x[0], factor * x[1], factor * x[2]);
      }
    p->Modified();
    g.data->Modified();
  }

  double check_units(Geometry &scan, const Geometry &model, const std::string &units, std::vector<std::string> &warnings)
  {
    double factor = 1;
    if (units == "mm")
      factor = 1e-3;
    else if (units != "m" && units != "auto")
      throw InputError("--scan-units", "'" + units + "' is not one of auto, m, mm");
    const double ratio = factor * scan.size() / model.size();
    if (units == "auto" && ratio > 200 && ratio < 5000)
      {
        factor = 1e-3;
        warnings.push_back(scan.path + ": the scan is " + std::to_string(int(std::round(ratio))) +
                           " times the size of the model: read as millimetres and scaled by 0.001 (pass "
                           "--scan-units m or mm to say which)");
      }
    else if (ratio < 0.2 || ratio > 5)
      throw InputError(scan.path, "its size (" + std::to_string(factor * scan.size()) + " m) does not match the model's (" +
                                    std::to_string(model.size()) + " m) by a factor " + std::to_string(ratio) +
                                    ": a wrong file or unit? (--scan-units m|mm)");
    if (factor != 1)
      scale(scan, factor);
    return factor;
  }
} // namespace abrade::field
