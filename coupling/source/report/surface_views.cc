// Pictures of surfaces without a display: VTK files coloured by a field, drawn by gnuplot from
// chosen views, laid face on, or zoomed on a region (surface_views.h).
#include "surface_views.h"

#include <abrade/common/external.h>

#include <Eigen/Eigenvalues>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkIdList.h>
#include <vtkMergePoints.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkTriangleFilter.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLGenericDataObjectReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <tuple>

namespace abrade::report
{
  std::string gnuplot_output_name(const std::string &path)
  {
    std::error_code ec;
    const auto      p = std::filesystem::absolute(path, ec);
    std::string     out;
    for (const char c : ec ? path : p.string()) // (a quote doubled inside gnuplot's single quotes)
      out += c == '\'' ? std::string("''") : std::string(1, c);
    return out;
  }

  std::string quote_free(std::string text)
  {
    std::replace(text.begin(), text.end(), '\'', ' ');
    return text;
  }

  namespace
  {
    /// The rotation that takes @p poly's points into their principal axes (largest spread along
    /// x, middle along z, smallest along y), about their mean.
    std::pair<Eigen::Matrix3d, Eigen::Vector3d> principal_frame(vtkPolyData *poly)
    {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      const vtkIdType n    = poly->GetNumberOfPoints();
      for (vtkIdType k = 0; k < n; ++k)
        mean += Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(k)) / double(n);
      Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
      for (vtkIdType k = 0; k < n; ++k)
        {
          const Eigen::Vector3d d = Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(k)) - mean;
          c += d * d.transpose();
        }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(c); // eigenvalues ascending
      Eigen::Matrix3d                                r;
      r.row(0) = e.eigenvectors().col(2).transpose(); // x: largest
      r.row(1) = e.eigenvectors().col(0).transpose(); // y: smallest
      r.row(2) = r.row(0).cross(r.row(1));            // z: the middle one, right-handed
      return {r, mean};
    }

    /// Writes the triangles of @p s's surface as pm3d quadrangles (each triangle a 2 x 2 patch
    /// with its third corner doubled) in mm, the field times @p scale as the colour (a point
    /// cloud as points: @p as_points); false when the file or the field is missing.
    using Frame = std::pair<Eigen::Matrix3d, Eigen::Vector3d>; ///< p -> R (p - c)

    /// The frame that lays a part face on: its largest spread along x, the middle along y, the
    /// smallest along z (right-handed), about its mean; and its extents there.
    std::pair<Frame, Eigen::Vector3d> face_on_frame(vtkPolyData *poly)
    {
      auto [r, mean] = principal_frame(poly); // rows: largest, smallest, middle
      Eigen::Matrix3d f;
      f.row(0) = r.row(0), f.row(1) = r.row(2), f.row(2) = r.row(0).cross(r.row(2));
      Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e300), hi = -lo;
      for (vtkIdType k = 0; k < poly->GetNumberOfPoints(); ++k)
        {
          const Eigen::Vector3d q = f * (Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(k)) - mean);
          lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
        }
      return {{f, mean}, hi - lo};
    }

    /// @p grid with its coincident points merged (the first one's point data kept). A solid's
    /// cells as deal.II writes them each have their own copies of their vertices: unmerged,
    /// every face of every cell is on the surface (8 times the boundary's triangles on a
    /// tetrahedral part, and the pictures' time and memory with them). (vtkAppendFilter's
    /// MergePoints passes a single unstructured grid through as it is.) A field that differs
    /// between a point's copies (deal.II writes cell fields as point data) keeps the first
    /// cell's value: only continuous fields (the wear depth) are drawn from solids.
    vtkSmartPointer<vtkUnstructuredGrid> with_shared_points(vtkUnstructuredGrid *grid)
    {
      auto points = vtkSmartPointer<vtkPoints>::New();
      auto merge  = vtkSmartPointer<vtkMergePoints>::New();
      merge->InitPointInsertion(points, grid->GetBounds());
      auto merged = vtkSmartPointer<vtkUnstructuredGrid>::New();
      merged->GetPointData()->CopyAllocate(grid->GetPointData(), grid->GetNumberOfPoints());
      std::vector<vtkIdType> id(grid->GetNumberOfPoints());
      for (vtkIdType k = 0; k < grid->GetNumberOfPoints(); ++k)
        if (merge->InsertUniquePoint(grid->GetPoint(k), id[k]))
          merged->GetPointData()->CopyData(grid->GetPointData(), k, id[k]);
      merged->SetPoints(points);
      merged->Allocate(grid->GetNumberOfCells());
      auto cell_points = vtkSmartPointer<vtkIdList>::New();
      for (vtkIdType c = 0; c < grid->GetNumberOfCells(); ++c)
        {
          grid->GetCellPoints(c, cell_points);
          for (vtkIdType k = 0; k < cell_points->GetNumberOfIds(); ++k)
            cell_points->SetId(k, id[cell_points->GetId(k)]);
          merged->InsertNextCell(grid->GetCellType(c), cell_points);
        }
      merged->GetCellData()->ShallowCopy(grid->GetCellData());
      return merged;
    }

    /// @p file's surface as triangles (nullptr when it cannot be read).
    vtkSmartPointer<vtkPolyData> triangles_of_file(const std::string &file)
    {
      std::error_code e;
      if (!std::filesystem::is_regular_file(file, e))
        return nullptr;
      auto reader = vtkSmartPointer<vtkXMLGenericDataObjectReader>::New();
      reader->SetFileName(file.c_str());
      reader->Update();
      auto surface = vtkSmartPointer<vtkDataSetSurfaceFilter>::New();
      if (auto *solid = vtkUnstructuredGrid::SafeDownCast(reader->GetOutput()))
        surface->SetInputData(with_shared_points(solid));
      else
        surface->SetInputConnection(reader->GetOutputPort());
      auto triangles = vtkSmartPointer<vtkTriangleFilter>::New();
      triangles->SetInputConnection(surface->GetOutputPort());
      triangles->Update();
      vtkSmartPointer<vtkPolyData> poly = triangles->GetOutput();
      return poly && poly->GetNumberOfPoints() > 0 ? poly : nullptr;
    }

    /// Calls @p f(c, ids, p) for every triangle c of @p poly: its point ids and its points.
    template <class F>
    void each_triangle(vtkPolyData *poly, F &&f)
    {
      for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          poly->GetCellPoints(c, n, ids);
          if (n != 3)
            continue;
          Eigen::Vector3d p[3]; // (GetPoint returns one buffer: each point copied before the next is read)
          for (int k = 0; k < 3; ++k)
            p[k] = Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(ids[k]));
          f(c, ids, p);
        }
    }

    /// @p fixed: the frame to draw in (else @p align's principal axes, or as it is).
    bool write_triangles(const SurfacePicture &s, const std::string &out, bool align, double scale,
                         std::vector<double> &values, bool &as_points, const Frame *fixed = nullptr,
                         const RenderOptions::Crop &crop = {})
    {
      const Eigen::Vector3d crop_centre(crop.centre[0], crop.centre[1], crop.centre[2]);
      auto outside = [&](const Eigen::Vector3d &p) { return crop.radius > 0 && (p - crop_centre).norm() > crop.radius; };
      const vtkSmartPointer<vtkPolyData> poly = triangles_of_file(s.file);
      if (!poly)
        return false;
      vtkDataArray *at_points = poly->GetPointData()->GetArray(s.field.c_str());
      vtkDataArray *at_cells  = poly->GetCellData()->GetArray(s.field.c_str());
      if (!at_points && !at_cells)
        return false;
      const auto [rotation, centre] = fixed ? *fixed
                                      : align ? principal_frame(poly)
                                              : std::pair{Eigen::Matrix3d(Eigen::Matrix3d::Identity()), Eigen::Vector3d(Eigen::Vector3d::Zero())};
      auto place = [&, rotation = rotation, centre = centre](double *p) {
        const Eigen::Vector3d q = rotation * (Eigen::Map<const Eigen::Vector3d>(p) - centre);
        p[0] = q[0], p[1] = q[1], p[2] = q[2];
      };
      std::ofstream data(out);
      as_points = poly->GetNumberOfPolys() == 0; // a point cloud (a scan's deviations): coloured points
      if (as_points && at_points)
        for (vtkIdType k = 0; k < poly->GetNumberOfPoints(); ++k)
          {
            double p[3];
            poly->GetPoint(k, p);
            if (outside(Eigen::Map<const Eigen::Vector3d>(p)))
              continue;
            place(p);
            const double v = scale * at_points->GetComponent(k, 0);
            if (!std::isfinite(v))
              continue;
            data << 1000 * p[0] << ' ' << 1000 * p[1] << ' ' << 1000 * p[2] << ' ' << v << '\n';
            values.push_back(v);
          }
      each_triangle(poly, [&](vtkIdType c, const vtkIdType *ids, const Eigen::Vector3d *corner) {
          if (outside((corner[0] + corner[1] + corner[2]) / 3))
            return;
          double x[3][4];
          for (int k = 0; k < 3; ++k)
            {
              double p[3] = {corner[k][0], corner[k][1], corner[k][2]};
              place(p);
              const double v = scale * (at_points ? at_points->GetComponent(ids[k], 0) : at_cells->GetComponent(c, 0));
              x[k][0] = 1000 * p[0], x[k][1] = 1000 * p[1], x[k][2] = 1000 * p[2], x[k][3] = std::isfinite(v) ? v : 0.0;
              values.push_back(x[k][3]);
            }
          auto line = [&](int k) { data << x[k][0] << ' ' << x[k][1] << ' ' << x[k][2] << ' ' << x[k][3] << '\n'; };
          line(0), line(1), data << '\n', line(2), line(2), data << "\n\n";
        });
      return bool(data);
    }

    /// gnuplot's view angles (rot_x, rot_z in degrees) that look from the direction @p d (unit,
    /// towards the viewer: gnuplot's viewer lies towards (sin x sin z, -sin x cos z, cos x)).
    std::pair<double, double> view_angles(const Eigen::Vector3d &d)
    {
      const double x = std::acos(std::clamp(d[2], -1.0, 1.0)) * 180 / M_PI;
      double       z = std::atan2(d[0], -d[1]) * 180 / M_PI;
      return {x, z < 0 ? z + 360 : z};
    }

    /// The two views of a zoomed region of @p file (RenderOptions::Crop): from the side its
    /// wear faces -- against the surface's motion there (wear_displacement) where the file has
    /// it, else the triangles' normals, each turned away from the part's middle, weighted by
    /// area and @p field -- 35 degrees to either side of it, across the region's thinnest
    /// spread. Empty when the region holds no triangle.
    std::vector<std::pair<double, double>> zoom_views(const std::string &file, const std::string &field,
                                                      const RenderOptions::Crop &crop)
    {
      const auto poly = triangles_of_file(file);
      if (!poly)
        return {};
      vtkDataArray *at_points = poly->GetPointData()->GetArray(field.c_str());
      vtkDataArray *at_cells  = poly->GetCellData()->GetArray(field.c_str());
      Eigen::Vector3d middle  = Eigen::Vector3d::Zero();
      for (vtkIdType k = 0; k < poly->GetNumberOfPoints(); ++k)
        middle += Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(k)) / double(poly->GetNumberOfPoints());
      const Eigen::Vector3d centre(crop.centre[0], crop.centre[1], crop.centre[2]);
      Eigen::Vector3d       facing = Eigen::Vector3d::Zero(), mean = Eigen::Vector3d::Zero();
      std::vector<Eigen::Vector3d> inside;
      each_triangle(poly, [&](vtkIdType c, const vtkIdType *ids, const Eigen::Vector3d *p) {
          double value = 0;
          for (int k = 0; k < 3; ++k)
            value += (at_points ? at_points->GetComponent(ids[k], 0) : at_cells ? at_cells->GetComponent(c, 0) : 0.0) / 3;
          const Eigen::Vector3d m = (p[0] + p[1] + p[2]) / 3;
          if ((m - centre).norm() > crop.radius)
            return;
          Eigen::Vector3d a = 0.5 * (p[1] - p[0]).cross(p[2] - p[0]); // area x normal
          if (a.dot(m - middle) < 0)
            a = -a;
          facing += a * (std::abs(value) + 1e-12);
          inside.push_back(m);
          mean += m;
        });
      if (inside.empty())
        return {};
      mean /= double(inside.size());
      // where the surface moved (a lifetime run's wear_displacement, inward): seen from where
      // the material was, whatever the triangles' orientation and the part's shape (a bucket's
      // worn floor faces its cavity, whose middle the normals above would turn away from)
      if (vtkDataArray *moved = poly->GetPointData()->GetArray("wear_displacement");
          moved && moved->GetNumberOfComponents() == 3)
        {
          Eigen::Vector3d away = Eigen::Vector3d::Zero();
          for (vtkIdType k = 0; k < poly->GetNumberOfPoints(); ++k)
            {
              const Eigen::Vector3d p = Eigen::Map<const Eigen::Vector3d>(poly->GetPoint(k));
              if ((p - centre).norm() <= crop.radius)
                away -= Eigen::Vector3d(moved->GetComponent(k, 0), moved->GetComponent(k, 1), moved->GetComponent(k, 2));
            }
          if (away.norm() > 0)
            facing = away;
        }
      Eigen::Vector3d d = facing.norm() > 0 ? facing.normalized() : (centre - middle).normalized();
      if (!d.allFinite())
        d = Eigen::Vector3d(0, -1, 0);
      // the tilt: across the region's thinnest spread that is not along d
      Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
      for (const auto &m : inside)
        spread += (m - mean) * (m - mean).transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> e(spread); // ascending
      Eigen::Vector3d                                across = Eigen::Vector3d::UnitZ();
      for (int k = 0; k < 3; ++k)
        if (std::abs(e.eigenvectors().col(k).dot(d)) < 0.7)
          {
            across = e.eigenvectors().col(k);
            break;
          }
      across = (across - across.dot(d) * d).normalized();
      const double t = 35 * M_PI / 180;
      return {view_angles(std::cos(t) * d + std::sin(t) * across), view_angles(std::cos(t) * d - std::sin(t) * across)};
    }
  } // namespace

  SurfaceSize surface_size(const std::string &file)
  {
    SurfaceSize size;
    const auto  poly = triangles_of_file(file);
    if (!poly)
      return size;
    double b[6];
    poly->GetBounds(b);
    size.largest_extent = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
    double    sum = 0;
    vtkIdType n   = 0;
    each_triangle(poly, [&](vtkIdType, const vtkIdType *, const Eigen::Vector3d *p) {
      for (int e = 0; e < 3; ++e, ++n)
        sum += (p[e] - p[(e + 1) % 3]).norm();
    });
    size.mean_edge = n > 0 ? sum / double(n) : 0.0;
    return size;
  }

  bool write_pm3d_surface(const SurfacePicture &picture, const std::string &out, double scale, std::vector<double> &values)
  {
    bool as_points = false;
    return write_triangles(picture, out, false, scale, values, as_points) && !as_points;
  }

  namespace
  {
    /// How render_surfaces lays out its pictures, and the values they colour.
    struct Layout
    {
      bool                face_on = false;        ///< a long part laid flat, its two sides one above the other
      Eigen::Vector3d     extent  = Eigen::Vector3d::Zero(); ///< the first surface's, in its principal frame
      Frame               front, back;            ///< (face on) the frames of the two sides
      std::vector<double> values;                 ///< every drawn value, for the colour range
      std::vector<char>   as_points;              ///< per surface: drawn as points (not a closed surface)
      double              lo = 0, hi = 0;         ///< the colour range
    };

    /// The surfaces' data files (stem_K.dat, and stem_K_back.dat face on) in @p directory, the
    /// layout decided and the colour range found; false where a surface cannot be drawn.
    bool write_surface_data(const std::string &directory, const std::string &stem,
                            const std::vector<SurfacePicture> &surfaces, const RenderOptions &options, Layout &l)
    {
      l.as_points.assign(surfaces.size(), 0);
      // a long part (its largest extent face_on_elongation times its middle one, or more) is laid
      // face on, its two sides one above the other at full width, so that it fills its panels;
      // every surface in the first one's frame
      if (options.face_on_elongation > 0 && !surfaces.empty() && options.crop.radius <= 0)
        if (const auto poly = triangles_of_file(surfaces.front().file))
          std::tie(l.front, l.extent) = face_on_frame(poly);
      l.face_on = l.extent[1] > 0 && l.extent[0] >= options.face_on_elongation * l.extent[1];
      l.back    = l.front;
      l.back.first.row(1) *= -1, l.back.first.row(2) *= -1; // (turned half round x: the other side up)
      for (std::size_t k = 0; k < surfaces.size(); ++k)
        {
          bool              points = false;
          const std::string name   = directory + "/" + stem + "_" + std::to_string(k);
          if (!write_triangles(surfaces[k], name + ".dat", options.align, options.categories.empty() ? 1000.0 : 1.0,
                               l.values, points, l.face_on ? &l.front : nullptr, options.crop))
            return false;
          std::vector<double> again; // (the same values)
          if (l.face_on && !write_triangles(surfaces[k], name + "_back.dat", false, 1000.0, again, points, &l.back))
            return false;
          l.as_points[k] = points;
        }
      if (l.values.empty() || surfaces.empty())
        return false;
      std::sort(l.values.begin(), l.values.end());
      l.lo = l.values.front();
      l.hi = l.values[std::min(l.values.size() - 1, std::size_t(options.top_percentile * (l.values.size() - 1)))];
      if (options.signed_range)
        l.hi = std::max(std::abs(l.lo), std::abs(l.hi)), l.lo = -l.hi;
      else
        l.lo = std::min(l.lo, 0.0);
      if (!(l.hi > l.lo))
        l.hi = l.lo + 1e-3;
      return true;
    }

    /// The gnuplot script's terminal, multiplot and palette. Returns the factor from metres to
    /// the colour bar's unit (1000: a few micrometres of wear shown in um).
    double write_script_head(std::ostream &gp, const std::string &directory, const std::string &png, int columns,
                             int panel, const RenderOptions &options, const Layout &l)
    {
      // wear of one cycle is a few micrometres: then the colour bar is in um
      const bool   categorical = !options.categories.empty();
      const double unit = l.hi < 0.01 && !options.signed_range && !categorical ? 1000.0 : 1.0;
      std::string  label = options.label;
      if (unit != 1.0 && label.size() > 4 && label.compare(label.size() - 4, 4, "[mm]") == 0)
        label = label.substr(0, label.size() - 4) + "[um]";
      if (l.face_on)
        gp << "set terminal pngcairo size 1400," << 2 * columns * panel << " font 'DejaVu Sans,10'\n"
           << "set output '" << gnuplot_output_name(directory + "/" + png) << "'\nset termoption noenhanced\n"
           << "set multiplot\n"
           << "set view map\nset size ratio -1\nunset tics\nunset border\nunset key\n"
           << "set colorbox\n"
           << "set pm3d depthorder corners2color mean\n";
      else
        gp << "set terminal pngcairo size " << std::max(700, 400 * columns) << ",860 font 'DejaVu Sans,10'\n"
           << "set output '" << gnuplot_output_name(directory + "/" + png) << "'\nset termoption noenhanced\n"
           << "set multiplot layout 2," << columns << " rowsfirst\n"
           << "set view equal xyz\nunset tics\nunset border\nunset key\nset xyplane 0\n"
           << "set pm3d depthorder corners2color mean lighting primary 0.5 specular 0.1\n";
      if (categorical) // one colour per category, named on the colour bar
        {
          const std::size_t n = options.categories.size();
          gp << "set cbrange [-0.5:" << double(n) - 0.5 << "]\nset cblabel '" << label << "'\nset palette maxcolors " << n
             << "\nset palette defined (";
          for (std::size_t k = 0; k < n; ++k)
            gp << (k ? ", " : "") << k << " '" << options.categories[k].second << "'";
          gp << ")\nset cbtics (";
          for (std::size_t k = 0; k < n; ++k)
            gp << (k ? ", " : "") << "'" << quote_free(options.categories[k].first) << "' " << k;
          gp << ")\n";
        }
      else
        gp << "set cbrange [" << unit * l.lo << ":" << unit * l.hi << "]\nset cblabel '" << label << "'\nset cbtics\n"
           << (options.signed_range ? "set palette defined (0 '#2166ac', 0.5 '#f7f7f7', 1 '#b2182b')\n"
                                    : "set palette defined (0 '#440154', 0.25 '#3b528b', 0.5 '#21918c', 0.75 '#5ec962', 1 '#fde725')\n");
      return unit;
    }

    /// Face on: each surface's two sides laid flat, one above the other, each in its box of
    /// @p panel pixels.
    void write_face_on_panels(std::ostream &gp, const std::string &stem, const std::vector<SurfacePicture> &surfaces,
                              int panel, double unit)
    {
      const int columns = int(surfaces.size());
      for (std::size_t k = 0; k < surfaces.size(); ++k)
        for (int v = 0; v < 2; ++v)
          {
            const double height = 2.0 * double(columns * panel), row = double(2 * k + v);
            const double top = 1 - (row * panel + 26) / height, bottom = 1 - (row + 1) * panel / height;
            gp << "set lmargin at screen 0.01\nset rmargin at screen 0.9\n"
               << "set tmargin at screen " << top << "\nset bmargin at screen " << bottom << "\n"
               << "set colorbox user origin screen 0.915, " << bottom << " size screen 0.012, " << top - bottom
               << "\nset title '" << quote_free(surfaces[k].title)
               << (v == 0 ? " (one side)" : " (the other side)") << "' offset 0,-0.8\nsplot '" << stem << "_" << k
               << (v == 0 ? ".dat" : "_back.dat") << "' using 1:2:3:(column(4)*" << unit << ") with pm3d\n";
          }
    }

    /// Every surface from two sides (@p views: gnuplot's rot_x, rot_z in degrees, titled with
    /// @p sides), a row per view, the labels that face the viewer.
    void write_perspective_views(std::ostream &gp, const std::string &stem, const std::vector<SurfacePicture> &surfaces,
                                 const std::vector<std::pair<double, double>> &views,
                                 const std::vector<std::string> &sides, const RenderOptions &options, const Layout &l,
                                 double unit)
    {
      for (int v = 0; v < 2; ++v)
        for (std::size_t k = 0; k < surfaces.size(); ++k)
          {
            // one colour bar per row, beside the last picture
            // the labels whose normals face this view's viewer (gnuplot's view: turned rot_z
            // about z, then rot_x about x; the viewer towards (sin x sin z, -sin x cos z, cos x))
            const double rot_x = views[v].first * M_PI / 180, rot_z = views[v].second * M_PI / 180;
            const double viewer[3] = {std::sin(rot_x) * std::sin(rot_z), -std::sin(rot_x) * std::cos(rot_z), std::cos(rot_x)};
            gp << "unset label\n";
            if (!options.align)
              for (const auto &lb : options.labels)
                if (lb.normal[0] * viewer[0] + lb.normal[1] * viewer[1] + lb.normal[2] * viewer[2] > 0.05 ||
                    lb.normal[0] * lb.normal[0] + lb.normal[1] * lb.normal[1] + lb.normal[2] * lb.normal[2] < 0.25)
                  gp << "set label '" << quote_free(lb.text) << "' at " << 1000 * lb.at[0] << "," << 1000 * lb.at[1] << ","
                     << 1000 * lb.at[2]
                     << (lb.marker ? " front left offset 1.5,0 font ',10' textcolor rgb 'red' point pt 6 ps 3 lw 2 lc rgb 'red'\n"
                                   : " front center font ',8' textcolor rgb 'black'\n");
            gp << (k + 1 == surfaces.size() ? "set colorbox\n" : "unset colorbox\n")
               << "set view " << views[v].first << ", " << views[v].second << ", " << (options.crop.radius > 0 ? 1.45 : 1.1)
               << "\n"
               << "set title '" << quote_free(surfaces[k].title) << sides[v] << "' offset 0,1\n"
               << "splot '" << stem << "_" << k << ".dat' using 1:2:3:(column(4)*" << unit << ") "
               << (l.as_points[k] ? "with points pointtype 7 pointsize 0.35 palette\n" : "with pm3d\n");
          }
    }
  } // namespace

  bool render_surfaces(const std::string &directory, const std::string &png, const std::vector<SurfacePicture> &surfaces,
                       const RenderOptions &options, bool *laid_face_on)
  {
    std::filesystem::create_directories(directory);
    const std::string stem = std::filesystem::path(png).stem().string();
    Layout            l;
    const bool        written = write_surface_data(directory, stem, surfaces, options, l);
    if (laid_face_on)
      *laid_face_on = l.face_on;
    if (!written)
      return false;

    std::ofstream gp(directory + "/" + stem + ".gp");
    // one column per surface, the front view above the back view (face on: a row each, the
    // panels as wide as the picture and as high as the part's shape asks: the part 1246 px
    // wide, 0.01 ... 0.9 of the width, its colour bar beside it; each panel with 26 px for its
    // title)
    const int    columns = int(surfaces.size());
    const int    part_px = std::clamp(int(1246 * l.extent[1] / (l.extent[0] > 0 ? l.extent[0] : 1)), 60, 660);
    const int    panel   = l.face_on ? part_px + 26 : 0; // [px]
    const double unit    = write_script_head(gp, directory, png, columns, panel, options, l);
    if (l.face_on)
      write_face_on_panels(gp, stem, surfaces, panel, unit);
    else
      {
        // two sides of the part: from the front and above, and from the back (a zoom: from the
        // side its wear faces, to either side of it)
        std::vector<std::pair<double, double>> views = {{70, 25}, {70, 205}};
        std::vector<std::string>               sides = {" (front)", " (back)"};
        if (options.crop.radius > 0)
          {
            views = zoom_views(surfaces.front().file, surfaces.front().field, options.crop);
            sides = {" (one side of the worn face)", " (its other side)"};
            if (views.empty())
              return false;
          }
        write_perspective_views(gp, stem, surfaces, views, sides, options, l, unit);
      }
    gp << "unset multiplot\n";
    gp.close();
    return io::run_gnuplot(directory, stem + ".gp", true) && std::filesystem::exists(directory + "/" + png);
  }
} // namespace abrade::report
