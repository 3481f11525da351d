// `abrade calibrate`: the wear coefficient W fitted to measured wear depths, its interval, the
// footprint, and the runs ranked by pattern agreement (field/calibration.h).
#include <abrade/common/closest_point.h>
#include <abrade/common/csv_reader.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/format_number.h>
#include <abrade/common/surface_distance.h>
#include <abrade/common/json.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/vtk_input.h>
#include <abrade/field/calibration.h>
#include <abrade/field/golden_section.h>

#include <boost/math/distributions/students_t.hpp>

#include <vtkDataArray.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangle.h>
#include <vtkTriangleFilter.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>


#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <memory>
#include <regex>
#include <sstream>

namespace abrade::field
{
  namespace
  {
    /// A user's table: read_csv, its column names in lower case; an error when it is empty.
    io::CsvTable read_table(const std::string &path)
    {
      io::CsvTable t = io::read_csv(path);
      if (t.header.empty())
        throw InputError(path, "empty table (a header line and at least one row expected)");
      for (auto &name : t.header)
        name = io::lower_case(name);
      return t;
    }

    /// The number in column @p name of row @p r; InputError naming the file and line.
    double number(const io::CsvTable &t, std::size_t r, const std::string &name)
    {
      const std::string  where = t.file + ":" + std::to_string(t.line[r]);
      const int          c     = t.find(name);
      const std::string &cell  = c >= 0 && std::size_t(c) < t.rows[r].size() ? t.rows[r][c] : std::string();
      if (cell.empty())
        throw InputError(where, "no value in column '" + name + "'");
      if (const auto v = io::finite_number(cell))
        return *v;
      throw InputError(where, "'" + cell + "' in column '" + name + "' is not a number");
    }

    std::string columns_of(const io::CsvTable &t)
    {
      std::string s;
      for (const auto &name : t.header)
        s += (s.empty() ? "" : ", ") + name;
      return s;
    }

    /// The surface's triangles, for a SurfaceDistance.
    geometry::SurfaceDistance distance_to(vtkPolyData *surface)
    {
      std::vector<double>              points;
      std::vector<std::array<long, 3>> triangles;
      for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
        {
          const double *x = surface->GetPoint(i);
          points.insert(points.end(), {x[0], x[1], x[2]});
        }
      for (vtkIdType c = 0; c < surface->GetNumberOfCells(); ++c)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          surface->GetCellPoints(c, n, ids);
          if (n == 3)
            triangles.push_back({long(ids[0]), long(ids[1]), long(ids[2])});
        }
      return geometry::SurfaceDistance(points, triangles);
    }

    /// The wear depth at the design points @p points, on one output's surface: every point of
    /// the worn surface lies below its closest design point (its foot; geometry::wear_depth,
    /// the definition compare and the lifetime loop use), so the worn surface is laid onto the
    /// design at its feet and its depth interpolated linearly at the closest point there. A
    /// gauge at a design point, or a scan point's foot (compare's measured_depths.csv), is
    /// looked up where it is.
    std::vector<double> depth_at(vtkPolyData *surface, const geometry::SurfaceDistance &design,
                                 const std::vector<Measurement> &measurements)
    {
      vtkDataArray       *depth = surface->GetPointData()->GetArray("wear_depth");
      vtkNew<vtkPolyData> laid;
      laid->DeepCopy(surface);
      std::vector<double> worn;
      for (vtkIdType i = 0; i < surface->GetNumberOfPoints(); ++i)
        {
          const double *x = surface->GetPoint(i);
          worn.insert(worn.end(), {x[0], x[1], x[2]});
        }
      std::vector<double> feet;
      geometry::wear_depth(design, worn, &feet);
      vtkPoints *pts = laid->GetPoints();
      for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
        pts->SetPoint(i, feet[3 * i], feet[3 * i + 1], feet[3 * i + 2]);
      vtkNew<vtkStaticCellLocator> below_design, on_surface;
      below_design->SetDataSet(laid);
      below_design->BuildLocator();
      on_surface->SetDataSet(surface);
      on_surface->BuildLocator();
      // the depth interpolated at the closest point of @p mesh (the laid or the actual surface)
      auto lookup = [&](vtkStaticCellLocator *locator, vtkPolyData *mesh, const double *p) {
        double    q[3], d2;
        vtkIdType cell;
        int       sub;
        locator->FindClosestPoint(p, q, cell, sub, d2);
        vtkIdType        n;
        const vtkIdType *ids;
        mesh->GetCellPoints(cell, n, ids);
        double a[3], b[3], c[3];
        mesh->GetPoint(ids[0], a), mesh->GetPoint(ids[1], b), mesh->GetPoint(ids[2], c);
        const auto w = geometry::barycentric(q, a, b, c);
        return w[0] * depth->GetTuple1(ids[0]) + w[1] * depth->GetTuple1(ids[1]) + w[2] * depth->GetTuple1(ids[2]);
      };
      std::vector<double> out;
      for (const auto &m : measurements)
        out.push_back(m.has_worn_point ? lookup(on_surface, surface, m.worn_point.data())
                                       : lookup(below_design, laid, m.point.data()));
      return out;
    }
    /// Every measured point lies near the knife: within half its size of the design surface (a
    /// worn point lies less than the wear depth inside it; a scan may hold some of the holder). A
    /// point farther away is in other coordinates or units (a factor of 1000), and would be
    /// fitted to the nearest corner of the knife.
    void check_on_part(const geometry::SurfaceDistance &design, vtkPolyData *fresh,
                        const std::vector<Measurement> &measurements)
    {
      double b[6];
      fresh->GetBounds(b);
      const double size = std::sqrt((b[1] - b[0]) * (b[1] - b[0]) + (b[3] - b[2]) * (b[3] - b[2]) +
                                    (b[5] - b[4]) * (b[5] - b[4]));
      for (const auto &m : measurements)
        {
          const auto &p = m.has_worn_point ? m.worn_point : m.point;
          // the distance to the knife's box first (a point at 1e300 m is no query for a locator)
          double outside = 0;
          for (int k = 0; k < 3; ++k)
            outside += std::pow(std::max({b[2 * k] - p[k], p[k] - b[2 * k + 1], 0.0}), 2);
          const double d = std::sqrt(outside) > 0.5 * size ? std::sqrt(outside) : std::abs(design.signed_distance(p.data()));
          if (d > 0.5 * size)
            throw InputError(m.where, "the point (" + io::format_number(p[0]) + ", " + io::format_number(p[1]) + ", " +
                                        io::format_number(p[2]) + ") m lies " + io::format_number(d) +
                                        " m or more from the part's surface (the part is " + io::format_number(size) +
                                        " m across): coordinates in other units or another frame?");
        }
    }
  } // namespace

  std::vector<Measurement> read_measurements(const std::string &path, const std::string &locations)
  {
    const io::CsvTable t = read_table(path);
    auto has = [](const io::CsvTable &table, const std::string &c) { return table.find(c) >= 0; };
    std::map<std::string, std::array<double, 3>> named;
    if (!locations.empty())
      {
        const io::CsvTable l = read_table(locations);
        for (const char *c : {"name", "x", "y", "z"})
          if (!has(l, c))
            throw InputError(locations, std::string("missing column '") + c + "' (found: " + columns_of(l) + ")");
        std::map<std::string, long> defined_on;
        for (std::size_t r = 0; r < l.rows.size(); ++r)
          {
            const std::string &name = l.rows[r][l.find("name")];
            if (defined_on.count(name))
              throw InputError(locations + ":" + std::to_string(l.line[r]),
                               "location '" + name + "' is defined twice (first on line " +
                                 std::to_string(defined_on[name]) + ")");
            defined_on[name] = l.line[r];
            named[name]      = {number(l, r, "x"), number(l, r, "y"), number(l, r, "z")};
          }
      }
    const bool by_name = has(t, "location");
    std::vector<std::string> required = {"tonnes"};
    if (!by_name)
      required.insert(required.end(), {"x", "y", "z"});
    for (const auto &c : required)
      if (!has(t, c))
        throw InputError(path, "missing column '" + c + "' (found: " + columns_of(t) +
                                 "; needed: tonnes, depth or depth_mm, and x, y, z or location)");
    if (has(t, "depth") && has(t, "depth_mm"))
      throw InputError(path, "both 'depth' [m] and 'depth_mm' columns: keep one");
    const bool in_mm = !has(t, "depth") && has(t, "depth_mm");
    if (!has(t, "depth") && !in_mm)
      throw InputError(path, "missing column 'depth' [m] or 'depth_mm' (found: " + columns_of(t) + ")");
    if (by_name && named.empty())
      throw InputError(path, "column 'location' names points: give their coordinates with --locations FILE");
    std::vector<Measurement>                          out;
    std::map<std::array<double, 5>, std::string> seen; // point, tonnes, depth: where first
    for (std::size_t r = 0; r < t.rows.size(); ++r)
      {
        Measurement m;
        m.where  = path + ":" + std::to_string(t.line[r]);
        m.tonnes = number(t, r, "tonnes");
        m.depth  = in_mm ? 1e-3 * number(t, r, "depth_mm") : number(t, r, "depth");
        if (by_name)
          {
            const auto       &row  = t.rows[r];
            const std::size_t c    = std::size_t(t.find("location"));
            const std::string name = c < row.size() ? row[c] : "";
            if (!named.count(name))
              throw InputError(m.where, "unknown location '" + name + "' (not in " + locations + ")");
            m.point = named[name];
          }
        else
          m.point = {number(t, r, "x"), number(t, r, "y"), number(t, r, "z")};
        if (has(t, "worn_x") && has(t, "worn_y") && has(t, "worn_z"))
          m.has_worn_point = true, m.worn_point = {number(t, r, "worn_x"), number(t, r, "worn_y"), number(t, r, "worn_z")};
        if (m.tonnes < 0)
          throw InputError(m.where, "negative tonnes");
        const std::array<double, 5> key = {m.point[0], m.point[1], m.point[2], m.tonnes, m.depth};
        if (const auto [it, fresh] = seen.emplace(key, m.where); !fresh)
          throw InputError(m.where, "the same measurement as " + it->second + " (a row copied twice?)");
        out.push_back(m);
      }
    if (out.empty())
      throw InputError(path, "no measurements (the table has a header only)");
    if (std::none_of(out.begin(), out.end(), [](const Measurement &m) { return m.tonnes > 0; }))
      throw InputError(path, "every measurement is at 0 t: the fit needs wear measured after handled tonnes");
    return out;
  }

  RunSeries read_run(const std::string &directory, const std::vector<Measurement> &measurements)
  {
    RunSeries         run;
    run.directory     = directory;
    const std::string part = io::part_folder(directory); // (knife/knife.pvd in an earlier abrade's run)
    const std::string pvd  = directory + "/" + part + "/" + part + ".pvd";
    std::ifstream     in(pvd);
    if (!in)
      throw InputError(pvd, "not found: is " + directory + " the output folder of a lifetime run?");
    // the coefficient of the run's wear law (Output/Wear field; older runs wrote Archard's only)
    run.archard_coefficient = io::summary_number(directory + "/summary.json", "wear_coefficient")
                                .value_or(io::summary_number(directory + "/summary.json", "archard_coefficient").value_or(0));
    run.seeds                 = long(io::summary_number(directory + "/summary.json", "seeds").value_or(1));
    run.replicate_relative_sd = io::summary_number(directory + "/summary.json", "worn_volume_relative_spread").value_or(0);
    run.smoothing_radius      = io::summary_number(directory + "/summary.json", "smoothing_radius").value_or(0);
    run.particle_radius       = io::summary_number(directory + "/summary.json", "particle_radius").value_or(0);
    run.coarse_graining_factor = io::summary_number(directory + "/summary.json", "coarse_graining_factor").value_or(0);
    run.wear_field            = io::summary_string(directory + "/summary.json", "wear_field").value_or("");
    run.replay = io::summary_string(directory + "/summary.json", "wear_source").value_or("") == "replay";
    const std::regex data_set("<DataSet\\b([^>]*)>"), timestep("timestep=\"([^\"]*)\""), file_of("file=\"([^\"]*)\"");
    std::unique_ptr<geometry::SurfaceDistance> design;
    std::string      line;
    for (long n = 1; std::getline(in, line); ++n)
      {
        std::smatch tag, m, f;
        if (!std::regex_search(line, tag, data_set))
          continue;
        const std::string attributes = tag[1].str(), where = pvd + ":" + std::to_string(n);
        if (!std::regex_search(attributes, m, timestep) || !std::regex_search(attributes, f, file_of) || f[1].str().empty())
          throw InputError(where, "a DataSet without its timestep or file");
        const std::string time = m[1].str();
        const auto        number = io::finite_number(time);
        if (!number || *number < 0)
          throw InputError(where, "timestep \"" + time.substr(0, 40) + "\" is not a number of tonnes");
        const double t = *number;
        if (!run.tonnes.empty() && !(t > run.tonnes.back()))
          throw InputError(where, "timestep " + time + " t does not follow " + std::to_string(run.tonnes.back()) +
                                    " t: the outputs must come in increasing tonnes (edited?)");
        const std::string file    = directory + "/" + part + "/" + f[1].str();
        const auto        surface = io::read_polydata(file);
        vtkPolyData      *s       = surface;
        if (!s->GetPointData()->GetArray("wear_depth") || !s->GetPointData()->GetArray("wear_displacement") ||
            s->GetNumberOfCells() == 0)
          throw InputError(file, "no part surface with wear_depth and wear_displacement");
        if (!design) // the first output is the fresh knife: the design
          {
            design = std::make_unique<geometry::SurfaceDistance>(distance_to(s));
            check_on_part(*design, s, measurements);
          }
        run.tonnes.push_back(t);
        run.depth.push_back(depth_at(s, *design, measurements));
      }
    if (run.tonnes.size() < 2)
      throw InputError(pvd, "fewer than two outputs: the run has not made an update yet");
    return run;
  }

  double RunSeries::at(std::size_t p, double t, bool *extrapolated) const
  {
    std::size_t k = 1;
    while (k + 1 < tonnes.size() && tonnes[k] < t)
      ++k;
    if (extrapolated && t > tonnes.back() * (1 + 1e-6)) // (a fit at the last update is not beyond it)
      *extrapolated = true;
    const double f = (t - tonnes[k - 1]) / (tonnes[k] - tonnes[k - 1]);
    return depth[k - 1][p] + f * (depth[k][p] - depth[k - 1][p]);
  }

  RunSeries run_between(const std::vector<const RunSeries *> &given, double r, bool in_log_r)
  {
    std::vector<const RunSeries *> runs;
    for (const auto *run : given)
      if (run && run->smoothing_radius > 0)
        runs.push_back(run);
    if (runs.empty() || !(r > 0))
      throw std::invalid_argument("run_between: no runs with a footprint, or no footprint");
    std::sort(runs.begin(), runs.end(), [](auto a, auto b) { return a->smoothing_radius < b->smoothing_radius; });
    auto x = [&](double radius) { return in_log_r ? std::log(radius) : radius; };
    // the weights: within [r_j, r_j+1] the blend of the parabolas through (j-1, j, j+1) and
    // (j, j+1, j+2), from the first at r_j to the second at r_j+1 (the candidates' depths
    // exactly at their footprints, smooth between: a single parabola through the three nearest
    // jumps where the nearest three change); one parabola at the ends, a line for two runs
    const std::size_t   n = runs.size();
    std::vector<double> weight(n, 0.0);
    auto lagrange = [&](std::size_t first, std::size_t count, double share) {
      for (std::size_t k = first; k < first + count; ++k)
        {
          double l = 1;
          for (std::size_t j = first; j < first + count; ++j)
            if (j != k)
              l *= (x(r) - x(runs[j]->smoothing_radius)) / (x(runs[k]->smoothing_radius) - x(runs[j]->smoothing_radius));
          weight[k] += share * l;
        }
    };
    std::size_t j = 0; // the interval [r_j, r_j+1] holding r (the first or last beyond them)
    while (j + 2 < n && runs[j + 1]->smoothing_radius <= r)
      ++j;
    if (n == 1)
      weight[0] = 1;
    else if (n == 2)
      lagrange(0, 2, 1.0);
    else
      {
        const bool   left = j >= 1, right = j + 2 < n;
        const double lambda = std::clamp((x(r) - x(runs[j]->smoothing_radius)) /
                                           (x(runs[j + 1]->smoothing_radius) - x(runs[j]->smoothing_radius)), 0.0, 1.0);
        if (left && right)
          lagrange(j - 1, 3, 1 - lambda), lagrange(j, 3, lambda);
        else
          lagrange(left ? j - 1 : j, 3, 1.0);
      }
    // the runs' W0 (analytic runs have none: their scales are compared at 1); the nearest run
    // is the reference (its W0, beds and spread)
    bool with_w = true;
    for (const auto *run : runs)
      with_w = with_w && run->archard_coefficient > 0 && !run->tonnes.empty();
    auto              w0      = [&](const RunSeries &run) { return with_w ? run.archard_coefficient : 1.0; };
    const RunSeries  *nearest = *std::min_element(runs.begin(), runs.end(), [&](auto a, auto b) {
      return std::abs(std::log(a->smoothing_radius / r)) < std::abs(std::log(b->smoothing_radius / r));
    });
    RunSeries between        = *nearest;
    between.smoothing_radius = r;
    between.directory += " (interpolated to a footprint of " + std::to_string(r) + " m)";
    // the union of the outputs, in the reference's tonnes at its W0
    const double reference = w0(*nearest);
    between.tonnes.clear();
    for (std::size_t k = 0; k < n; ++k)
      if (weight[k] != 0)
        for (const double t : runs[k]->tonnes)
          between.tonnes.push_back(t * w0(*runs[k]) / reference);
    std::sort(between.tonnes.begin(), between.tonnes.end());
    between.tonnes.erase(std::unique(between.tonnes.begin(), between.tonnes.end(),
                                     [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); }),
                         between.tonnes.end());
    const std::size_t points = nearest->depth.empty() ? 0 : nearest->depth.front().size();
    between.depth.assign(between.tonnes.size(), std::vector<double>(points, 0.0));
    for (std::size_t o = 0; o < between.tonnes.size(); ++o)
      for (std::size_t k = 0; k < n; ++k)
        if (weight[k] != 0)
          for (std::size_t p = 0; p < points; ++p)
            between.depth[o][p] += weight[k] * runs[k]->at(p, between.tonnes[o] * reference / w0(*runs[k]));
    return between;
  }

  double student_t95(int dof)
  {
    static const double t[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
                               2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
                               2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
    if (dof < 1)
      return std::numeric_limits<double>::infinity();
    if (dof <= 30)
      return t[dof - 1];
    return 1.960 + 2.4 / dof; // within 0.2 % of the quantile above 30
  }

  namespace
  {
    /// The residual sum of squares of @p run's wear scaled by @p s.
    double sum_of_squares(const RunSeries &run, const std::vector<Measurement> &ms, double s)
    {
      double sum = 0;
      for (std::size_t i = 0; i < ms.size(); ++i)
        {
          const double e = run.at(i, s * ms[i].tonnes) - ms[i].depth;
          sum += e * e;
        }
      return sum;
    }
  } // namespace

  std::pair<double, double> least_squares_scale(const RunSeries &run, const std::vector<Measurement> &ms, double low,
                                                double high)
  {
    // a coarse scan first: the depths are linear in the tonnes between outputs, so the sum of
    // squares may have a local minimum at each output a measurement crosses (two 4.5 % apart
    // on the knife-bed's scans); then golden sections about the best
    constexpr int steps = 40;
    const double  step  = (std::log(high) - std::log(low)) / steps;
    int           best  = 0;
    double        least = std::numeric_limits<double>::infinity();
    for (int k = 0; k <= steps; ++k)
      if (const double e = sum_of_squares(run, ms, low * std::exp(k * step)); e < least)
        least = e, best = k;
    const double s = std::exp(golden_section_minimum([&](double x) { return sum_of_squares(run, ms, std::exp(x)); },
                                                     std::log(low) + std::max(0, best - 1) * step,
                                                     std::log(low) + std::min(steps, best + 1) * step, 1e-13, 100));
    return {s, sum_of_squares(run, ms, s)};
  }

  namespace
  {
    /// The scale of @p run's tonnes that fits @p ms best: a log-spaced scan over six decades,
    /// then golden sections around the best; refused at the scan's ends.
    double best_scale(const RunSeries &run, const std::vector<Measurement> &ms)
    {
      double best = 1, best_sse = sum_of_squares(run, ms, 1);
      for (int k = -300; k <= 300; ++k)
        {
          const double s = std::pow(10.0, k / 100.0), e = sum_of_squares(run, ms, s);
          if (e < best_sse)
            best = s, best_sse = e;
        }
      if (best <= 1.0001e-3 || best >= 0.9999e3 || !std::isfinite(best_sse))
        throw InputError(run.directory, "the best fit lies at the end of the range searched (the run's wear scaled by "
                                        "1e-3 .. 1e3): the run and the measurements differ by more than a factor of "
                                        "1000 (depths in mm given as m, tonnes in kg, or no wear measured?)");
      return least_squares_scale(run, ms, best * std::pow(10.0, -0.01), best * std::pow(10.0, 0.01)).first;
    }

    /// The fit's sensitivities at scale @p s, J_i = d depth / d s = T_i D'(s T_i), summed per
    /// spatial block of side @p block (sums of J_i e_i and of J_i^2) for the cluster-robust
    /// variance, and the depths the fit predicts.
    struct BlockScores
    {
      double                                                   jj = 0; ///< sum of J_i^2
      std::map<std::array<long, 3>, std::pair<double, double>> score;
      std::vector<double>                                      predicted;
    };
    BlockScores block_scores(const RunSeries &run, const std::vector<Measurement> &ms, double s, double block,
                             bool &extrapolated)
    {
      BlockScores b;
      b.predicted.resize(ms.size());
      for (std::size_t i = 0; i < ms.size(); ++i)
        {
          const double h = 1e-4 * s;
          const double j = (run.at(i, (s + h) * ms[i].tonnes) - run.at(i, (s - h) * ms[i].tonnes)) / (2 * h);
          b.jj += j * j;
          b.predicted[i] = run.at(i, s * ms[i].tonnes, &extrapolated);
          std::array<long, 3> key;
          for (int k = 0; k < 3; ++k)
            key[k] = long(std::floor(ms[i].point[k] / block));
          b.score[key].first += j * (b.predicted[i] - ms[i].depth);
          b.score[key].second += j * j;
        }
      return b;
    }

    /// The fit's standard error from the blocks that carry information on s (J = 0 where nothing
    /// wears: such blocks would only add degrees of freedom), in the jackknife form of the
    /// cluster-robust variance (CR3): var = (G-1)/G sum_g (S_g / (sum J^2 - Q_g))^2, S_g =
    /// sum_g J e, Q_g = sum_g J^2; into @p r with the blocks and the effective blocks.
    void cluster_robust_error(const BlockScores &b, CalibrationResult &r)
    {
      double G = 0, sum = 0;
      for (const auto &[key, sq] : b.score)
        if (sq.second > 1e-12 * b.jj)
          ++G;
      for (const auto &[key, sq] : b.score)
        if (sq.second > 1e-12 * b.jj && b.jj - sq.second > 0)
          sum += (sq.first / (b.jj - sq.second)) * (sq.first / (b.jj - sq.second));
      r.blocks = long(G);
      // the fit's degrees of freedom: the blocks its information is spread over (Kish's effective
      // number from each block's share of sum J^2: Satterthwaite's for the sum of the blocks'
      // squared scores, each in proportion to its share). A worn profile narrower than the
      // measurements puts most of it in a few blocks, and then the cluster-robust variance is
      // about as uncertain as a variance from those few (test_footprint_coverage: W given the
      // footprint covered 89-91 % with G - 1 = 13 degrees of freedom where 3.9 blocks carry the
      // information)
      double q2 = 0;
      for (const auto &[key, sq] : b.score)
        if (sq.second > 1e-12 * b.jj)
          q2 += sq.second * sq.second;
      r.effective_blocks = q2 > 0 ? std::min(G, b.jj * b.jj / q2) : 0.0;
      r.se_fit = G > 1 && b.jj > 0 ? std::sqrt((G - 1) / G * sum) : std::numeric_limits<double>::infinity();
    }

    /// The scale's 95 % interval in @p r: the fit's error and the replicates' (the run's beds)
    /// combined, at Welch-Satterthwaite's degrees of freedom.
    void scale_interval(const RunSeries &run, CalibrationResult &r)
    {
      const double inf      = std::numeric_limits<double>::infinity();
      const double dof_fit  = r.effective_blocks;
      r.se_replicates       = run.seeds > 1 ? r.scale * run.replicate_relative_sd / std::sqrt(double(run.seeds)) : 0.0;
      const double dof_rep  = double(run.seeds - 1);
      const double se       = std::sqrt(r.se_fit * r.se_fit + r.se_replicates * r.se_replicates);
      const double v_fit = r.se_fit * r.se_fit, v_rep = r.se_replicates * r.se_replicates;
      r.dof = dof_fit < 1 ? 0.0
                          : (v_fit + v_rep) * (v_fit + v_rep) / (v_fit * v_fit / dof_fit + (v_rep > 0 ? v_rep * v_rep / dof_rep : 0.0));
      const double t = r.dof >= 1 ? boost::math::quantile(boost::math::students_t_distribution<double>(r.dof), 0.975) : inf;
      r.scale_low    = std::max(0.0, r.scale - t * se);
      r.scale_high   = r.scale + t * se;
    }

    /// Pearson's correlation between the measured depths and @p predicted.
    double correlation(const std::vector<Measurement> &ms, const std::vector<double> &predicted)
    {
      double mean_m = 0, mean_p = 0;
      for (std::size_t i = 0; i < ms.size(); ++i)
        mean_m += ms[i].depth / ms.size(), mean_p += predicted[i] / ms.size();
      double smm = 0, spp = 0, smp = 0;
      for (std::size_t i = 0; i < ms.size(); ++i)
        {
          smm += (ms[i].depth - mean_m) * (ms[i].depth - mean_m);
          spp += (predicted[i] - mean_p) * (predicted[i] - mean_p);
          smp += (ms[i].depth - mean_m) * (predicted[i] - mean_p);
        }
      return smm > 0 && spp > 0 ? smp / std::sqrt(smm * spp) : 0.0;
    }
  } // namespace

  CalibrationResult calibrate(const RunSeries &run, const std::vector<Measurement> &ms, double block)
  {
    CalibrationResult r;
    r.directory          = run.directory;
    r.scale              = best_scale(run, ms);
    const BlockScores b  = block_scores(run, ms, r.scale, block, r.extrapolated);
    const double sum_sq  = sum_of_squares(run, ms, r.scale);
    r.rms_residual       = std::sqrt(sum_sq / ms.size());
    cluster_robust_error(b, r);
    if (sum_sq > 0 && ms.size() > 1 && std::isfinite(r.se_fit))
      r.design_effect = r.se_fit * r.se_fit * b.jj * double(ms.size() - 1) / sum_sq;
    r.smoothing_radius       = run.smoothing_radius;
    r.particle_radius        = run.particle_radius;
    r.coarse_graining_factor = run.coarse_graining_factor;
    r.wear_field             = run.wear_field;
    scale_interval(run, r);
    r.correlation = correlation(ms, b.predicted);
    if (run.archard_coefficient > 0)
      {
        r.archard_coefficient = r.scale * run.archard_coefficient;
        r.low                 = r.scale_low * run.archard_coefficient;
        r.high                = r.scale_high * run.archard_coefficient;
      }
    return r;
  }
} // namespace abrade::field
