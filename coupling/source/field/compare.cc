// `abrade compare`: a field scan registered to a predicted (or design) surface, the deviations,
// depths at measured points and the profiles (field/compare.h).
#include <abrade/common/plane_section.h>
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/json.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/surface_distance.h>
#include <abrade/field/compare.h>
#include <abrade/field/worn_volume.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkKdTreePointLocator.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkCellData.h>
#include <vtkPolyData.h>
#include <vtkTriangle.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <array>
#include <sstream>
#include <set>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <fstream>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace abrade::field
{
  namespace
  {
    /// x,y,z of every point of @p g.
    std::vector<double> coordinates(const Geometry &g)
    {
      std::vector<double> x(3 * g.data->GetNumberOfPoints());
      for (vtkIdType i = 0; i < g.data->GetNumberOfPoints(); ++i)
        g.data->GetPoint(i, x.data() + 3 * i);
      return x;
    }

    /// The distance to the surface @p g (its triangles; other polygons and strips are
    /// triangulated first): the same signed distance, and so the same wear depth, as the
    /// lifetime loop's (surface_distance.h).
    geometry::SurfaceDistance surface_distance(const Geometry &g)
    {
      vtkPolyData *surface = g.data;
      vtkNew<vtkTriangleFilter> triangulate;
      if (surface->GetNumberOfStrips() > 0 || surface->GetPolys()->IsHomogeneous() != 3)
        {
          triangulate->SetInputData(surface);
          triangulate->PassVertsOff();
          triangulate->PassLinesOff();
          triangulate->Update();
          surface = triangulate->GetOutput();
        }
      std::vector<std::array<long, 3>> triangles;
      vtkCellArray                    *polys = surface->GetPolys();
      vtkIdType                        n;
      const vtkIdType                 *ids;
      for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
        if (n == 3)
          triangles.push_back({long(ids[0]), long(ids[1]), long(ids[2])});
      std::vector<double> points(3 * surface->GetNumberOfPoints());
      for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
        surface->GetPoint(i, points.data() + 3 * i);
      try
        {
          return geometry::SurfaceDistance(points, triangles);
        }
      catch (const std::invalid_argument &e)
        {
          throw InputError(g.path, e.what());
        }
    }

    /// Signed distance of every point (x,y,z flat) to @p surface (> 0 outside).
    std::vector<double> signed_distances(const std::vector<double> &points, const geometry::SurfaceDistance &surface)
    {
      std::vector<double> out(points.size() / 3);
      for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = surface.signed_distance(points.data() + 3 * i);
      return out;
    }

    /// Largest distance from the model's points within the scan's bounding box to the scan.
    double model_to_scan(const Geometry &model, const Geometry &scan)
    {
      double b[6];
      scan.data->GetBounds(b);
      const double margin = 0.02 * scan.size();
      vtkNew<vtkKdTreePointLocator>              cloud;
      std::optional<geometry::SurfaceDistance> surface;
      if (scan.point_cloud)
        cloud->SetDataSet(scan.data), cloud->BuildLocator();
      else
        surface.emplace(surface_distance(scan));
      double worst = 0;
      for (vtkIdType i = 0; i < model.data->GetNumberOfPoints(); ++i)
        {
          const double *p = model.data->GetPoint(i);
          bool          inside = true;
          for (int k = 0; k < 3; ++k)
            inside = inside && p[k] >= b[2 * k] - margin && p[k] <= b[2 * k + 1] + margin;
          if (!inside)
            continue;
          double d;
          if (scan.point_cloud)
            {
              double q[3];
              scan.data->GetPoint(cloud->FindClosestPoint(p), q);
              d = std::sqrt(vtkMath::Distance2BetweenPoints(p, q));
            }
          else
            d = std::abs(surface->signed_distance(p));
          worst = std::max(worst, d);
        }
      return worst;
    }

    /// The scan's triangles turned to face out of the knife, as the design's do: made consistent
    /// with their neighbours (VTK's normals filter), then all turned round if most of the scan's
    /// area faces into the design (a scanner's surface has no inside of its own).
    void orient_like_design(Geometry &scan, const geometry::SurfaceDistance &design)
    {
      // each connected piece of the scan (a knife, the fixture next to it) on its own
      const vtkSmartPointer<vtkPolyData> oriented = consistently_oriented(scan.data, false);
      // the connected pieces: triangles that share a point are in one piece (union-find)
      std::vector<vtkIdType> parent(std::size_t(oriented->GetNumberOfPoints()));
      std::iota(parent.begin(), parent.end(), vtkIdType(0));
      std::function<vtkIdType(vtkIdType)> root = [&](vtkIdType v) {
        while (parent[v] != v)
          v = parent[v] = parent[parent[v]];
        return v;
      };
      for (vtkIdType t = 0; t < oriented->GetNumberOfCells(); ++t)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          oriented->GetCellPoints(t, n, ids);
          for (vtkIdType k = 1; k < n; ++k)
            parent[root(ids[k])] = root(ids[0]);
        }
      std::map<vtkIdType, std::size_t> piece_of_root;
      std::vector<std::size_t>         piece(std::size_t(oriented->GetNumberOfCells()), 0);
      for (vtkIdType t = 0; t < oriented->GetNumberOfCells(); ++t)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          oriented->GetCellPoints(t, n, ids);
          piece[t] = piece_of_root.emplace(root(ids[0]), piece_of_root.size()).first->second;
        }
      const double  eps      = 1e-4 * scan.size();
      std::vector<double> outward(piece_of_root.size(), 0.0);
      for (vtkIdType t = 0; t < oriented->GetNumberOfCells(); ++t)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          oriented->GetCellPoints(t, n, ids);
          if (n != 3)
            continue;
          double a[3], b[3], c[3], normal[3];
          oriented->GetPoint(ids[0], a), oriented->GetPoint(ids[1], b), oriented->GetPoint(ids[2], c);
          vtkTriangle::ComputeNormal(a, b, c, normal);
          const double area = vtkTriangle::TriangleArea(a, b, c);
          double       up[3], down[3];
          for (int k = 0; k < 3; ++k)
            {
              const double centre = (a[k] + b[k] + c[k]) / 3;
              up[k] = centre + eps * normal[k], down[k] = centre - eps * normal[k];
            }
          outward[piece[t]] +=
            area * (design.signed_distance(up) > design.signed_distance(down) ? 1 : -1);
        }
      vtkNew<vtkCellArray> cells;
      for (vtkIdType t = 0; t < oriented->GetNumberOfCells(); ++t)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          oriented->GetCellPoints(t, n, ids);
          std::vector<vtkIdType> v(ids, ids + n);
          if (outward[piece[t]] < 0)
            std::reverse(v.begin(), v.end());
          cells->InsertNextCell(n, v.data());
        }
      auto result = vtkSmartPointer<vtkPolyData>::New();
      result->SetPoints(oriented->GetPoints());
      result->SetPolys(cells);
      scan.data = result;
    }

    void add_array(vtkPolyData *p, const char *name, const std::vector<double> &values)
    {
      vtkNew<vtkDoubleArray> a;
      a->SetName(name);
      for (double x : values)
        a->InsertNextValue(x);
      p->GetPointData()->AddArray(a);
    }

    /// Segments of a surface in a plane, or the points of a cloud within a thin slab of it:
    /// "curve u0 v0 u1 v1" lines (a point is a zero-length segment).
    void write_section(std::ofstream &out, const std::string &curve, const Geometry &g, int axis, double at)
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (g.point_cloud)
        {
          const double slab = 0.5 * g.size() / std::sqrt(double(g.data->GetNumberOfPoints()));
          for (vtkIdType i = 0; i < g.data->GetNumberOfPoints(); ++i)
            {
              const double *p = g.data->GetPoint(i);
              if (std::abs(p[axis] - at) <= slab)
                out << curve << ' ' << p[u] << ' ' << p[v] << ' ' << p[u] << ' ' << p[v] << '\n';
            }
          return;
        }
      for (const auto &c : io::plane_section(g.data, axis, at))
        out << curve << ' ' << c.u0 << ' ' << c.v0 << ' ' << c.u1 << ' ' << c.v1 << '\n';
    }

    /// The plots zoom to where the scan differs most: the (u, v) box of the scan points whose
    /// @p emphasis (measured depth, or |deviation|) exceeds half its largest, widened.
    void write_profiles(const CompareSettings &s, const Geometry &predicted, const Geometry &scan,
                        const Geometry *reference, const std::vector<double> &emphasis, io::OutputDirectory &out)
    {
      const char *axes = "xyz";
      const int   u_axis = (s.profile_axis + 1) % 3, v_axis = (s.profile_axis + 2) % 3;
      const double top = emphasis.empty() ? 0.0 : *std::max_element(emphasis.begin(), emphasis.end());
      double       lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      for (std::size_t i = 0; i < emphasis.size() && top > 0; ++i)
        if (emphasis[i] > 0.5 * top)
          {
            const double *p = scan.data->GetPoint(vtkIdType(i));
            lo[0] = std::min(lo[0], p[u_axis]), hi[0] = std::max(hi[0], p[u_axis]);
            lo[1] = std::min(lo[1], p[v_axis]), hi[1] = std::max(hi[1], p[v_axis]);
          }
      for (double at : s.profile_planes)
        {
          char name[64];
          std::snprintf(name, sizeof name, "profile_%c%.4g", axes[s.profile_axis], at);
          std::ofstream csv(out.file(std::string(name) + ".csv"));
          csv.precision(10);
          csv << "# curve u0 v0 u1 v1 [m]: sections of the plane " << axes[s.profile_axis] << " = " << at
              << " (u, v: the next two axes)\n";
          write_section(csv, "predicted", predicted, s.profile_axis, at);
          write_section(csv, "scan", scan, s.profile_axis, at);
          if (reference)
            write_section(csv, "design", *reference, s.profile_axis, at);
          csv.close();
          std::ofstream gp(out.file(std::string(name) + ".gp"));
          const char    u = axes[(s.profile_axis + 1) % 3], v = axes[(s.profile_axis + 2) % 3];
          if (lo[0] < hi[0] + 1e-300 && top > 0)
            for (int k = 0; k < 2; ++k)
              {
                const double pad = 0.5 * (hi[k] - lo[k]) + 0.01;
                gp << "set " << (k ? 'y' : 'x') << "range [" << 1000 * (lo[k] - pad) << ':' << 1000 * (hi[k] + pad) << "]\n";
              }
          gp << "set terminal pngcairo size 800,800\nset output '" << name << ".png'\nset size ratio -1\nset grid\n"
             << "set xlabel '" << u << " [mm]'\nset ylabel '" << v << " [mm]'\nset title 'section " << axes[s.profile_axis]
             << " = " << at << " m (zoomed to where the scan differs most)'\n"
             << "plot '" << name << ".csv' using (strcol(1) eq 'predicted' ? $2*1000 : 1/0):($3*1000):(($4-$2)*1000):(($5-$3)*1000) "
             << "with vectors nohead lw 2 lc rgb 'blue' title 'predicted' , '' using "
             << "(strcol(1) eq 'scan' ? $2*1000 : 1/0):($3*1000) with points pt 7 ps 0.3 lc rgb 'red' title 'scan'";
          if (reference)
            gp << ", '' using (strcol(1) eq 'design' ? $2*1000 : 1/0):($3*1000):(($4-$2)*1000):(($5-$3)*1000) "
                  "with vectors nohead dt 2 lw 1.5 lc rgb 'black' title 'design'";
          gp << '\n';
          gp.close();
          io::run_gnuplot(out.root(), std::string(name) + ".gp");
        }
    }
  } // namespace

  DeviationStatistics statistics(std::vector<double> d)
  {
    DeviationStatistics s;
    s.n = d.size();
    if (d.empty())
      return s;
    double sum = 0, sum2 = 0;
    for (double x : d)
      sum += x, sum2 += x * x, s.max_abs = std::max(s.max_abs, std::abs(x));
    s.mean = sum / d.size();
    s.rms  = std::sqrt(sum2 / d.size());
    for (double &x : d)
      x = std::abs(x);
    const std::size_t k = std::min(d.size() - 1, std::size_t(std::ceil(0.95 * d.size())) - 1);
    std::nth_element(d.begin(), d.begin() + k, d.end());
    s.p95 = d[k];
    return s;
  }

  namespace
  {
    /// `abrade compare`: a scan registered to the prediction (or the design), its deviations,
    /// with a design the measured depths and worn volumes, and the files that say so.
    class Comparison
    {
    public:
      explicit Comparison(const CompareSettings &s) : s(s) {}

      CompareResult run()
      {
        read_inputs();
        register_the_scan();
        deviation          = signed_distances(scan_points, surface_distance(predicted));
        r.to_predicted     = statistics(deviation);
        r.to_predicted.hausdorff = std::max(r.to_predicted.max_abs, model_to_scan(predicted, scan));
        if (r.has_reference)
          {
            measure_depths();
            r.to_reference.hausdorff = std::max(r.to_reference.max_abs, model_to_scan(reference, scan));
            measure_worn_volumes();
          }
        write_outputs();
        return r;
      }

    private:
      /// The prediction, the scan and the design read; the scan's units checked.
      void read_inputs();
      /// The scan registered on the design where there is one (the unworn parts are the same in
      /// both), else on the prediction; the fit's quality on its region and the rest apart; a
      /// scan that does not overlap the model refused.
      void register_the_scan();
      /// The measured depth below the design (the one definition of wear depth, the lifetime
      /// loop's too), the design point each scan point lies below (where calibrate looks the
      /// prediction up) and the prediction's depth there; a warning when a registration on the
      /// whole scan was pulled by evident wear.
      void measure_depths();
      /// The scanner's noise: from the depth differences of neighbouring scan points (1.4826 x
      /// their median / sqrt 2: smooth wear hardly differs between neighbours, noise does).
      double scanner_noise() const;
      /// The worn volumes, measured and predicted, and how they were found.
      void measure_worn_volumes();
      /// deviation.vtp, measured_depths.csv, the profiles and comparison.json.
      void write_outputs();
      /// measured_depths.csv: the design points the scan points lie below, their depths.
      void write_measured_depths(const io::OutputDirectory &out);
      void write_json(const io::OutputDirectory &out) const;

      const CompareSettings &s;
      CompareResult          r;
      Geometry               predicted, scan, reference;
      std::vector<double>    scan_points, deviation, measured, predicted_depth, feet;
    };

    void Comparison::read_inputs()
    {
      predicted = read_geometry(s.predicted, r.warnings);
      if (predicted.point_cloud)
        throw InputError(s.predicted, "the predicted geometry must be a surface (STL or VTU from a run)");
      scan = read_geometry(s.scan, r.warnings);
      r.has_reference = !s.reference.empty();
      if (r.has_reference)
        {
          reference = read_geometry(s.reference, r.warnings);
          if (reference.point_cloud)
            throw InputError(s.reference, "the design must be a surface");
        }
      r.scan_scale = check_units(scan, predicted, s.scan_units, r.warnings);
    }

    void Comparison::register_the_scan()
    {
      const Geometry &frame = r.has_reference ? reference : predicted;
      r.registration        = register_scan(scan, frame, s.registration);
      scan_points = coordinates(scan);
      // the fit's quality on the region it was made on, and the rest apart: worn points belong to
      // the rest, and an overlap is judged on the region alone
      double fit_rms = r.registration.rms;
      if (s.registration.region)
        {
          const std::vector<double> to_frame = signed_distances(scan_points, surface_distance(frame));
          double                    in = 0, out = 0;
          for (std::size_t i = 0; i < to_frame.size(); ++i)
            if (s.registration.region->contains(scan_points.data() + 3 * i))
              in += to_frame[i] * to_frame[i], ++r.registration.points_region;
            else
              out += to_frame[i] * to_frame[i], ++r.registration.points_rest;
          r.registration.rms_region = r.registration.points_region ? std::sqrt(in / r.registration.points_region) : 0;
          r.registration.rms_rest   = r.registration.points_rest ? std::sqrt(out / r.registration.points_rest) : 0;
          fit_rms                   = r.registration.rms_region;
        }
      if (fit_rms > 0.05 * frame.size())
        throw InputError(s.scan, "does not overlap the model: after registration its points lie " + std::to_string(fit_rms) +
                                   " m (RMS" + (s.registration.region ? ", in the registration region" : "") +
                                   ") from the model's surface, " + std::to_string(100 * fit_rms / frame.size()) +
                                   " % of its size");
    }

    void Comparison::measure_depths()
    {
      measured = geometry::wear_depth(surface_distance(reference), scan_points, &feet);
      std::vector<double> to_design;
      for (std::size_t i = 0; i < measured.size(); ++i)
        {
          to_design.push_back(-measured[i]);                     // signed distance to the design
          predicted_depth.push_back(measured[i] + deviation[i]); // the prediction's depth below this point
        }
      r.to_reference = statistics(to_design);
      // evident wear: the 95th percentile of |depth| beyond 0.2 mm and beyond four times the
      // scanner's noise
      const double noise = scanner_noise();
      if (s.registration.enabled && !s.registration.region && r.to_reference.p95 > std::max(2e-4, 4 * noise))
        r.warnings.push_back(
          "registered on the whole scan, its worn part included (95 % of |depth| up to " +
          std::to_string(1e3 * r.to_reference.p95) +
          " mm): the worn surface pulls the fit toward the design and the measured depths come out too small; give "
          "--register-on a box (model coordinates) around surfaces that do not wear (the back, the bolt holes)");
    }

    double Comparison::scanner_noise() const
    {
      vtkNew<vtkKdTreePointLocator> neighbours;
      neighbours->SetDataSet(scan.data);
      neighbours->BuildLocator();
      std::vector<double> differences;
      vtkNew<vtkIdList>   pair;
      for (vtkIdType i = 0; i < vtkIdType(measured.size()); i += std::max<vtkIdType>(1, vtkIdType(measured.size()) / 5000))
        {
          neighbours->FindClosestNPoints(2, scan_points.data() + 3 * i, pair);
          for (vtkIdType k = 0; k < pair->GetNumberOfIds(); ++k)
            if (pair->GetId(k) != i)
              differences.push_back(std::abs(measured[i] - measured[pair->GetId(k)]));
        }
      double noise = 0;
      if (!differences.empty())
        {
          std::nth_element(differences.begin(), differences.begin() + differences.size() / 2, differences.end());
          noise = 1.4826 * differences[differences.size() / 2] / std::sqrt(2.0);
        }
      return noise;
    }

    void Comparison::measure_worn_volumes()
    {
      if (scan.closed && predicted.closed && reference.closed)
        {
          r.measured_volume  = reference.volume() - scan.volume();
          r.predicted_volume = reference.volume() - predicted.volume();
          r.volume_method    = "enclosed volumes (design minus worn)";
        }
      else if (!scan.point_cloud)
        {
          // an open scan: the volume between the design and the scan (the prediction) within
          // the scan's footprint, over space (worn_volume.h)
          const geometry::SurfaceDistance design = surface_distance(reference);
          orient_like_design(scan, design);
          const geometry::SurfaceDistance scanned = surface_distance(scan);
          double sb[6], db[6];
          scan.data->GetBounds(sb);
          reference.data->GetBounds(db);
          // the box: the design's, within a tenth of the scan's size around the scan, and a few
          // cells beyond both (a scan that bulges out of the design counts negative: cut off at
          // the design's faces, noise would add up to a positive volume)
          std::array<double, 6> box;
          const double          pad  = 0.1 * scan.size();
          const double          cell = scan.size() / 400;
          for (int k = 0; k < 3; ++k)
            box[k]     = std::max(db[2 * k], sb[2 * k] - pad) - 10 * cell,
            box[k + 3] = std::min(db[2 * k + 1], sb[2 * k + 1] + pad) + 10 * cell;
          const WornVolume m    = worn_volume(design, scanned, scanned, box, cell);
          const WornVolume p    = worn_volume(design, surface_distance(predicted), scanned, box, cell);
          r.measured_volume     = m.volume;
          r.predicted_volume    = p.volume;
          char method[200];
          std::snprintf(method, sizeof method,
                        "the volume inside the design and outside the scan (the prediction) within the scan's "
                        "footprint, on a grid of %.3g mm (signed: noise adds nothing on average)",
                        1e3 * cell);
          r.volume_method = method;
        }
      else
        {
          r.volume_method = "none (a point cloud has no area)";
          r.warnings.push_back(s.scan + ": a point cloud: worn volumes are not computed");
        }
    }

    void Comparison::write_outputs()
    {
      io::OutputDirectory out(s.output);
      out.claim();
      add_array(scan.data, "deviation", deviation);
      if (r.has_reference)
        add_array(scan.data, "measured_depth", measured), add_array(scan.data, "predicted_depth", predicted_depth);
      if (scan.point_cloud)
        {
          vtkNew<vtkCellArray> verts; // so that ParaView draws the points
          for (vtkIdType i = 0; i < scan.data->GetNumberOfPoints(); ++i)
            verts->InsertNextCell(1, &i);
          scan.data->SetVerts(verts);
        }
      vtkNew<vtkXMLPolyDataWriter> w;
      w->SetFileName(out.file("deviation.vtp").c_str());
      w->SetInputData(scan.data);
      w->Write();
      if (r.has_reference)
        write_measured_depths(out);
      std::vector<double> emphasis = measured;
      if (emphasis.empty())
        for (double d : deviation)
          emphasis.push_back(std::abs(d));
      write_profiles(s, predicted, scan, r.has_reference ? &reference : nullptr, emphasis, out);
      write_json(out);
    }

    void Comparison::write_measured_depths(const io::OutputDirectory &out)
    {
      if (s.tonnes < 0)
        r.warnings.push_back("measured_depths.csv has no tonnage (pass --tonnes T to use it for calibration)");
      std::ostringstream m;
      m.precision(10);
      // the locations are the design points the scan points lie below: material points of the
      // fresh knife, as `abrade calibrate` reads them
      // (and worn_x, worn_y, worn_z: the scan point itself, registered)
      m << "x,y,z,tonnes,depth,worn_x,worn_y,worn_z\n";
      std::set<std::array<double, 3>> written; // a point scanned twice (merged scans) is one measurement
      for (vtkIdType i = 0; i < vtkIdType(measured.size()); ++i)
        {
          const double *p = feet.data() + 3 * i, *q = scan_points.data() + 3 * i;
          if (!written.insert({q[0], q[1], q[2]}).second)
            continue;
          m << p[0] << ',' << p[1] << ',' << p[2] << ',';
          if (s.tonnes >= 0)
            m << s.tonnes;
          m << ',' << measured[i] << ',' << q[0] << ',' << q[1] << ',' << q[2] << '\n';
        }
      io::write_file_atomically(out.file("measured_depths.csv"), m.str());
    }

    void Comparison::write_json(const io::OutputDirectory &out) const
    {
      io::Json json;
      json["predicted"] = s.predicted;
      json["scan"]      = s.scan;
      if (r.has_reference)
        json["design"] = s.reference;
      json["scan_scale_applied"] = r.scan_scale;
      auto &reg                   = json["registration"];
      std::vector<double> matrix(r.registration.matrix.begin(), r.registration.matrix.end());
      reg["matrix_row_major"] = matrix;
      reg["rms_distance"]     = r.registration.rms;
      reg["points_used"]      = long(r.registration.points_used);
      if (s.registration.region)
        {
          reg["rms_distance_in_region"]      = r.registration.rms_region;
          reg["points_in_region"]            = long(r.registration.points_region);
          reg["rms_distance_outside_region"] = r.registration.rms_rest;
          reg["points_outside_region"]       = long(r.registration.points_rest);
        }
      reg["on"] = !s.registration.enabled
                    ? std::string("none (--no-registration: the scan is in the model's frame)")
                    : std::string(r.has_reference ? "design" : "prediction") +
                        (s.registration.region ? " (within the region given)" : " (all of it)");
      auto put = [](io::Json &j, const DeviationStatistics &d) {
        j["points"] = long(d.n), j["rms"] = d.rms, j["mean"] = d.mean, j["max_abs"] = d.max_abs, j["p95_abs"] = d.p95,
        j["hausdorff"] = d.hausdorff;
      };
      put(json["scan_to_prediction"], r.to_predicted);
      if (r.has_reference)
        {
          put(json["scan_to_design"], r.to_reference);
          json["worn_volume"]["measured"]  = r.measured_volume;
          json["worn_volume"]["predicted"] = r.predicted_volume;
          json["worn_volume"]["method"]    = r.volume_method;
        }
      json["warnings"] = std::vector<double>{};
      for (const auto &w : r.warnings)
        json["warnings"].push_back(w);
      json.write(out.file("comparison.json"));
    }
  } // namespace

  CompareResult compare(const CompareSettings &s) { return Comparison(s).run(); }
} // namespace abrade::field
