// Field scans and measurements (abrade compare / calibrate): synthetic scans of known geometry
// under a known rigid transform and noise are registered back and give the known deviations;
// the design against itself gives zero deviation; bad scans and tables are clear errors.
#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>
#include <abrade/dem/triangle_mesh.h>
#include <abrade/field/calibration.h>
#include <abrade/field/compare.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPLYWriter.h>
#include <vtkPolyDataWriter.h>
#include <vtkSTLWriter.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>

using namespace abrade;
using namespace abrade::field;

namespace
{
  const double L = 0.4, H = 0.5, T = 0.03, bevel = 0.06;

  std::string tmp(const std::string &name)
  {
    const auto dir = std::filesystem::temp_directory_path() / "abrade_field_test";
    std::filesystem::create_directories(dir);
    return (dir / name).string();
  }

  /// A knife with its bevel on the +y side only (no rotational symmetry), the edge at y = -T/2,
  /// z = 0; with @p cut > 0 the edge is worn flat to height cut. Extruded along x, refined.
  dem::TriangleMesh knife(double cut = 0)
  {
    std::vector<std::pair<double, double>> profile; // (y, z), counter-clockwise seen from +x
    if (cut > 0)
      profile = {{-T / 2, cut}, {-T / 2 + T * cut / bevel, cut}};
    else
      profile = {{-T / 2, 0}};
    profile.insert(profile.end(), {{T / 2, bevel}, {T / 2, H}, {-T / 2, H}});
    dem::TriangleMesh m;
    const int         n = int(profile.size());
    for (double x : {0.0, L})
      for (const auto &[y, z] : profile)
        m.vertices.emplace_back(x, y, z);
    for (int k = 0; k < n; ++k) // sides
      {
        const int a = k, b = (k + 1) % n;
        m.triangles.push_back({a, b, n + b});
        m.triangles.push_back({a, n + b, n + a});
      }
    for (int k = 1; k + 1 < n; ++k) // end caps (convex profile: fans)
      {
        m.triangles.push_back({0, k + 1, k});
        m.triangles.push_back({n, n + k, n + k + 1});
      }
    m.refine(0.02);
    return m;
  }

  /// Writes @p m as STL after x -> scale (R x + t) plus Gaussian noise along random directions.
  void write(const dem::TriangleMesh &m, const std::string &path, const Eigen::Isometry3d &move = Eigen::Isometry3d::Identity(),
             double scale = 1, double noise = 0)
  {
    std::mt19937                     rng(7);
    std::normal_distribution<double> g(0, noise > 0 ? noise : 1);
    vtkNew<vtkPoints>                pts;
    for (const auto &v : m.vertices)
      {
        Eigen::Vector3d p = move * v;
        if (noise > 0)
          p += Eigen::Vector3d(g(rng), g(rng), g(rng));
        p *= scale;
        pts->InsertNextPoint(p.data());
      }
    vtkNew<vtkCellArray> cells;
    for (const auto &t : m.triangles)
      {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, ids);
      }
    vtkNew<vtkPolyData> poly;
    poly->SetPoints(pts);
    poly->SetPolys(cells);
    vtkNew<vtkSTLWriter> w;
    w->SetFileName(path.c_str());
    w->SetInputData(poly);
    w->SetFileTypeToBinary();
    w->Write();
  }

  Eigen::Isometry3d some_move()
  {
    Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
    t.rotate(Eigen::AngleAxisd(0.6, Eigen::Vector3d(1, 2, 3).normalized()));
    t.pretranslate(Eigen::Vector3d(0.3, -0.1, 0.05));
    return t;
  }

  /// Angle [rad] and shift [m] between a registration and the inverse of the applied move.
  std::pair<double, double> error_of(const Registration &r, const Eigen::Isometry3d &move)
  {
    Eigen::Matrix4d m;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        m(i, j) = r.matrix[4 * i + j];
    const Eigen::Matrix4d e = m * move.matrix(); // identity if exact
    const double          angle = Eigen::AngleAxisd(Eigen::Matrix3d(e.block<3, 3>(0, 0))).angle();
    return {angle, e.block<3, 1>(0, 3).norm()};
  }
} // namespace

TEST(FieldCompare, DesignAgainstItselfIsZero)
{
  write(knife(), tmp("design.stl"));
  CompareSettings s;
  s.predicted = s.scan = s.reference = tmp("design.stl");
  s.output                            = tmp("self");
  const auto r = compare(s);
  EXPECT_LT(r.to_predicted.max_abs, 1e-7);
  EXPECT_LT(r.to_predicted.hausdorff, 1e-7);
  EXPECT_LT(r.registration.rms, 1e-7);
  EXPECT_NEAR(r.measured_volume, 0, 1e-10);
}

TEST(FieldCompare, MovedNoisyScanInMillimetresIsRegisteredBack)
{
  write(knife(), tmp("design.stl"));
  const auto   move  = some_move();
  const double sigma = 1e-4; // 0.1 mm per coordinate
  write(knife(), tmp("scan_mm.stl"), move, 1000, sigma);
  CompareSettings s;
  s.predicted = tmp("design.stl"), s.scan = tmp("scan_mm.stl"), s.output = tmp("moved");
  s.profile_planes = {0.2};
  const auto r     = compare(s);
  EXPECT_DOUBLE_EQ(r.scan_scale, 1e-3);
  ASSERT_FALSE(r.warnings.empty());
  EXPECT_NE(r.warnings.back().find("millimetres"), std::string::npos);
  const auto [angle, shift] = error_of(r.registration, move);
  EXPECT_LT(angle, 1e-3 * M_PI / 180 * 50); // 0.05 degrees
  EXPECT_LT(shift, 5e-5);                   // 0.05 mm
  // the noise along the normal: sigma (one of three components), mean zero
  EXPECT_NEAR(r.to_predicted.rms, sigma, 0.1 * sigma);
  EXPECT_NEAR(r.to_predicted.mean, 0, 0.1 * sigma);
  EXPECT_NEAR(r.to_predicted.p95, 1.96 * sigma, 0.2 * sigma);
  EXPECT_TRUE(std::filesystem::exists(tmp("moved/deviation.vtp")));
  EXPECT_TRUE(std::filesystem::exists(tmp("moved/comparison.json")));
  EXPECT_GT(std::filesystem::file_size(tmp("moved/profile_x0.2.csv")), 100u);
}

TEST(FieldCompare, WornScanRegisteredOnTheUnwornPartGivesTheWear)
{
  const double cut = 0.01; // the edge worn flat 10 mm up
  write(knife(), tmp("design.stl"));
  write(knife(cut), tmp("worn.stl"));
  const auto move = some_move();
  write(knife(cut), tmp("worn_scan.stl"), move);
  CompareSettings s;
  s.predicted = tmp("worn.stl"), s.scan = tmp("worn_scan.stl"), s.reference = tmp("design.stl");
  s.output              = tmp("worn");
  s.tonnes              = 1000;
  s.registration.region = Box{{-1, -1, 0.1}, {1, 1, 1}}; // the top 80 %, which does not wear
  const auto r          = compare(s);
  const auto [angle, shift] = error_of(r.registration, move);
  EXPECT_LT(angle, 1e-5);
  EXPECT_LT(shift, 1e-5); // 0.01 mm: ICP converges slowly along the prism
  EXPECT_LT(r.to_predicted.max_abs, 1e-5); // the scan is the prediction
  const double removed = L * 0.5 * cut * (T * cut / bevel);
  EXPECT_NEAR(r.measured_volume, removed, 1e-3 * removed);
  EXPECT_NEAR(r.predicted_volume, removed, 1e-3 * removed);
  // deepest point of the cut: where it is as far from the -y face as from the bevel
  const double deepest = cut * T / (std::hypot(T, bevel) + bevel);
  EXPECT_NEAR(r.to_reference.max_abs, deepest, 0.02 * deepest);
  // the measured depths go out as a calibration table
  const auto table = read_measurements(tmp("worn/measured_depths.csv"));
  EXPECT_EQ(table.size(), r.to_reference.n);
}

namespace
{
  /// The part of @p m below @p z_max: an open surface, as a scanner sees the lower part of a knife.
  dem::TriangleMesh lower_part(const dem::TriangleMesh &m, double z_max)
  {
    dem::TriangleMesh open = m;
    open.triangles.clear();
    for (const auto &t : m.triangles)
      if (m.vertices[t[0]][2] < z_max && m.vertices[t[1]][2] < z_max && m.vertices[t[2]][2] < z_max)
        open.triangles.push_back(t);
    return open;
  }
} // namespace

// An open scan of a knife whose edge is cut 10 mm flat: the worn volume is the volume between the
// design and the scan within the scan's footprint, 1.0e-5 m^3 (within 5 %; the depth below the
// design integrated over the scanned area gave 2.1e-6, 4.8x low: the cut face lies only a few
// millimetres below the bevels).
TEST(FieldCompare, OpenScanOfACutTipGivesItsVolume)
{
  const double cut = 0.01;
  write(knife(), tmp("design.stl"));
  write(knife(cut), tmp("worn.stl"));
  write(lower_part(knife(cut), 0.25), tmp("open_scan.stl"));
  CompareSettings s;
  s.predicted = tmp("worn.stl"), s.scan = tmp("open_scan.stl"), s.reference = tmp("design.stl");
  s.output               = tmp("open_cut");
  s.registration.enabled = false;
  const auto   r       = compare(s);
  const double removed = L * 0.5 * cut * (T * cut / bevel);
  EXPECT_NEAR(removed, 1.0e-5, 1e-12);
  std::cout << "cut tip, open scan: measured " << r.measured_volume << ", predicted " << r.predicted_volume
            << " m^3, true " << removed << "\n";
  EXPECT_NEAR(r.measured_volume / removed, 1, 0.05);
  EXPECT_NEAR(r.predicted_volume / removed, 1, 0.05);
  EXPECT_NE(r.volume_method.find("footprint"), std::string::npos) << r.volume_method;
}

// An open, noisy scan of an unworn knife (0.2 mm Gaussian noise per coordinate) has no worn
// volume: the volume is signed, so the scan lying now above, now below the design adds nothing on
// average. Clipping each depth at zero, as before, made sigma / sqrt(2 pi) x area of it.
TEST(FieldCompare, NoisyOpenScanOfAnUnwornKnifeHasNoVolume)
{
  const double sigma = 2e-4;
  write(knife(), tmp("design.stl"));
  write(lower_part(knife(), 0.25), tmp("noisy_open_scan.stl"), Eigen::Isometry3d::Identity(), 1, sigma);
  CompareSettings s;
  s.predicted = tmp("design.stl"), s.scan = tmp("noisy_open_scan.stl"), s.reference = tmp("design.stl");
  s.output               = tmp("noisy_open");
  s.registration.enabled = false;
  const auto   r       = compare(s);
  const double area    = 2 * L * 0.25 + 2 * T * 0.25; // the faces and ends below 0.25 m, about
  const double clipped = sigma / std::sqrt(2 * M_PI) * area;
  std::cout << "noisy unworn open scan: worn volume " << r.measured_volume << " m^3 (clipping gave about " << clipped
            << ")\n";
  EXPECT_LT(std::abs(r.measured_volume), 0.1 * clipped) << "clipping would give " << clipped;
  EXPECT_EQ(r.predicted_volume, 0);
  // registered without a region, the unworn scan's noise is not taken for wear (no warning)
  s.registration.enabled = true;
  s.output               = tmp("noisy_open_registered");
  for (const auto &w : compare(s).warnings)
    EXPECT_EQ(w.find("worn part included"), std::string::npos) << w;
}

// The W interval's coverage with what field data and DEM runs have: the measurements' errors are
// correlated along the knife (a 10 mm correlation length: an AR(1) sequence over 200 points 2 mm
// apart, 5 % of the depth), and the run's wear rate is the mean of three beds that scatter by
// 10 % (normal). Over 400 synthetic calibrations the 95 % interval (blocks of 50 mm, the beds'
// spread from their own sample) contains the true W in 90-99 % of them. Treating the points as
// independent and leaving out the beds, as before, covers it far less often (printed).
namespace
{
  /// The triangles of @p m whose centroid satisfies @p keep.
  template <typename F>
  dem::TriangleMesh part(const dem::TriangleMesh &m, F &&keep)
  {
    dem::TriangleMesh out = m;
    out.triangles.clear();
    for (const auto &t : m.triangles)
      if (keep((m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3))
        out.triangles.push_back(t);
    return out;
  }

  /// Every third triangle of @p m turned round (an export that mixed the orientations).
  dem::TriangleMesh mixed(dem::TriangleMesh m)
  {
    for (std::size_t k = 0; k < m.triangles.size(); k += 3)
      std::swap(m.triangles[k][1], m.triangles[k][2]);
    return m;
  }

  CompareResult compare_unregistered(const std::string &predicted, const std::string &scan, const std::string &design,
                                     const std::string &output)
  {
    CompareSettings s;
    s.predicted = tmp(predicted), s.scan = tmp(scan), s.reference = tmp(design), s.output = tmp(output);
    s.registration.enabled = false;
    return compare(s);
  }
} // namespace

// Scans that see one side of the knife (the usual field case): the half-space behind such a scan
// is "inside" it, beyond the design's far face too; that must not count. The -y face of an
// unworn knife has no worn volume; the +y side and the cut face of the 10 mm cut tip give its
// 1.0e-5 m^3 (within 5 %). (Counting behind the scan gave -1.5e-3 and -1.0e-3 m^3.)
TEST(FieldCompare, OneSidedOpenScans)
{
  const double cut = 0.01, removed = L * 0.5 * cut * (T * cut / bevel);
  write(knife(), tmp("design.stl"));
  write(knife(cut), tmp("worn.stl"));
  write(part(knife(), [](const Eigen::Vector3d &c) { return c[1] < -T / 2 + 1e-9 && c[2] < 0.25; }), tmp("minus_y.stl"));
  write(part(knife(cut), [](const Eigen::Vector3d &c) { return c[1] > -T / 2 + 1e-9 && c[2] < 0.25; }), tmp("plus_y_cut.stl"));
  const auto unworn = compare_unregistered("design.stl", "minus_y.stl", "design.stl", "minus_y");
  std::cout << "one-sided scans: unworn -y face " << unworn.measured_volume << " m^3\n";
  EXPECT_LT(std::abs(unworn.measured_volume), 0.01 * removed) << unworn.measured_volume;
  const auto worn = compare_unregistered("worn.stl", "plus_y_cut.stl", "design.stl", "plus_y_cut");
  EXPECT_NEAR(worn.measured_volume / removed, 1, 0.05) << worn.measured_volume;
}

// Mixed orientations: a design and a scan with every third triangle turned round are oriented
// consistently (and outward) before anything is measured: the design gets a warning and gives
// the same depths as the right one, the open scan the cut tip's volume.
TEST(FieldCompare, MixedOrientationsAreRepaired)
{
  const double cut = 0.01, removed = L * 0.5 * cut * (T * cut / bevel);
  write(knife(), tmp("design.stl"));
  write(mixed(knife()), tmp("design_mixed.stl"));
  write(knife(cut), tmp("worn.stl"));
  write(mixed(lower_part(knife(cut), 0.25)), tmp("open_scan_mixed.stl"));
  write(lower_part(knife(cut), 0.25), tmp("open_scan.stl"));
  const auto right = compare_unregistered("worn.stl", "open_scan.stl", "design.stl", "orientation_right");
  const auto fixed = compare_unregistered("worn.stl", "open_scan_mixed.stl", "design_mixed.stl", "orientation_mixed");
  bool       warned = false;
  for (const auto &w : fixed.warnings)
    warned = warned || w.find("face inward in part") != std::string::npos;
  EXPECT_TRUE(warned);
  EXPECT_NEAR(fixed.to_reference.mean, right.to_reference.mean, 1e-12);
  EXPECT_NEAR(fixed.to_reference.max_abs, right.to_reference.max_abs, 1e-12);
  EXPECT_NEAR(fixed.measured_volume / removed, 1, 0.05);
}

namespace
{
  struct Coverage
  {
    int covered = 0, naive = 0, trials = 0;
  };

  /// Synthetic calibrations (see the test below): @p beds_sd the beds' relative scatter, points
  /// beyond x = @p worn_to unworn (rate 0: no information on W).
  Coverage interval_coverage(double beds_sd, double worn_to)
  {
  const int    n_points = 200, trials = 400;
  const double W_true = 3e-14, W0 = 2e-14, spacing = 0.002, corr = 0.01, noise = 0.05;
  std::mt19937                     rng(11);
  std::normal_distribution<double> z(0, 1);
  auto rate = [&](double x) { return x < worn_to ? 1e-9 * (1 + 0.5 * std::sin(15 * x)) : 0.0; }; // m/t at W_true
  int covered = 0, covered_naive = 0;
  for (int trial = 0; trial < trials; ++trial)
    {
      // the run: made with W0 on three beds whose mean rate is off by their scatter
      std::vector<double> bed(3);
      double              mean_bed = 0;
      for (double &b : bed)
        b = 1 + beds_sd * z(rng), mean_bed += b / 3;
      double var = 0;
      for (double b : bed)
        var += (b - mean_bed) * (b - mean_bed) / 2;
      RunSeries run;
      run.archard_coefficient   = W0;
      run.seeds                 = 3;
      run.replicate_relative_sd = std::sqrt(var) / mean_bed;
      run.tonnes                = {0, 1e5, 2e5, 3e5, 4e5};
      std::vector<Measurement> ms;
      double                   e = 0; // AR(1) error along the knife
      const double             a = std::exp(-spacing / corr);
      for (int p = 0; p < n_points; ++p)
        {
          const double x = p * spacing;
          e              = a * e + std::sqrt(1 - a * a) * z(rng);
          const double T = 2.5e5;
          Measurement m;
          m.point = {x, 0, 0}, m.tonnes = T, m.depth = rate(x) * T * (1 + noise * e);
          ms.push_back(m);
        }
      for (double T : run.tonnes)
        {
          std::vector<double> d;
          for (int p = 0; p < n_points; ++p)
            d.push_back(rate(p * spacing) * W0 / W_true * mean_bed * T);
          run.depth.push_back(d);
        }
      const auto r = calibrate(run, ms, 0.05);
      covered += r.low <= W_true && W_true <= r.high;
      // the naive interval: independent points, no beds (as the fit's t-interval was before)
      double jj = 0, sse = 0;
      for (std::size_t i = 0; i < ms.size(); ++i)
        {
          const double j = run.at(i, ms[i].tonnes) ; // d depth / d s at s ~ scale: depth is linear in s
          jj += j * j;
          const double res = run.at(i, r.scale * ms[i].tonnes) - ms[i].depth;
          sse += res * res;
        }
      const double se_naive = std::sqrt(sse / (ms.size() - 1) / jj);
      covered_naive += std::abs(r.scale * W0 - W_true) <= 1.97 * se_naive * W0;
    }
  return {covered, covered_naive, trials};
  }
} // namespace

TEST(FieldCalibrate, IntervalCoversTheTrueWWithCorrelatedErrorsAndBeds)
{
  // the beds' scatter dominates; then the fit's correlated errors dominate (beds within 0.5 %),
  // on a knife whose far half does not wear (blocks without information on W)
  for (const auto &[beds_sd, worn_to] : {std::pair<double, double>{0.1, 1.0}, {0.005, 0.2}})
    {
      const Coverage c        = interval_coverage(beds_sd, worn_to);
      const double   coverage = double(c.covered) / c.trials;
      std::cout << "W interval coverage (beds " << 100 * beds_sd << " %, worn to x = " << worn_to << " m): " << c.covered
                << " of " << c.trials << " (" << 100 * coverage << " %); independent points without the beds: " << c.naive
                << "\n";
      EXPECT_GE(coverage, 0.90);
      EXPECT_LE(coverage, 0.99);
      EXPECT_LT(c.naive, 0.8 * c.trials);
    }
}

TEST(FieldCompare, PredictionWithoutWearAgainstWornScan)
{
  const double cut = 0.01;
  write(knife(), tmp("design.stl"));
  write(knife(cut), tmp("worn_scan2.stl"), some_move());
  CompareSettings s;
  s.predicted = tmp("design.stl"), s.scan = tmp("worn_scan2.stl"), s.output = tmp("unworn_prediction");
  s.registration.region = Box{{-1, -1, 0.1}, {1, 1, 1}};
  const auto r          = compare(s);
  EXPECT_LT(r.to_predicted.mean, 0);                 // the scan lies inside: more wear than predicted
  EXPECT_GT(r.to_predicted.max_abs, 0.3 * cut * T / std::hypot(T, bevel));
  EXPECT_LE(r.to_predicted.max_abs, cut + 1e-6);
}

namespace
{
  /// The message of the InputError that compare() throws ("no error" when it does not).
  std::string error_of(const CompareSettings &s)
  {
    try
      {
        compare(s);
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "no error";
  }
} // namespace

TEST(FieldCompare, BadScansAreClearErrors)
{
  write(knife(), tmp("design.stl"));
  std::ofstream(tmp("empty.stl")).close();
  CompareSettings s;
  s.predicted = tmp("design.stl"), s.output = tmp("bad");
  s.scan = tmp("empty.stl");
  EXPECT_THROW(compare(s), InputError);
  s.scan = tmp("missing.ply");
  EXPECT_THROW(compare(s), InputError);
  // ten times too large: neither metres nor millimetres
  write(knife(), tmp("scan_x10.stl"), Eigen::Isometry3d::Identity(), 10);
  s.scan = tmp("scan_x10.stl");
  EXPECT_NE(error_of(s).find("wrong file or unit"), std::string::npos) << error_of(s);
  // a point table with a bad line names it
  {
    std::ofstream xyz(tmp("bad.xyz"));
    xyz << "x y z\n";
    for (int i = 0; i < 20; ++i)
      xyz << 0.01 * i << " 0 0.1\n";
    xyz << "0.3 oops 0.1\n";
  }
  s.scan = tmp("bad.xyz");
  EXPECT_NE(error_of(s).find("bad.xyz:22"), std::string::npos) << error_of(s);
  // no overlap: a ball of points is no knife
  {
    std::ofstream xyz(tmp("ball.xyz"));
    std::mt19937  rng(3);
    std::normal_distribution<double> g(0, 1);
    for (int i = 0; i < 2000; ++i)
      {
        Eigen::Vector3d p(g(rng), g(rng), g(rng));
        p = 0.3 * p.normalized();
        xyz << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
      }
  }
  s.scan = tmp("ball.xyz");
  EXPECT_NE(error_of(s).find("does not overlap"), std::string::npos) << error_of(s);
}

// Legacy .vtk files are read by abrade's own checked reader: what VTK's writer wrote (version 5,
// ASCII and BINARY) must come back point for point and triangle for triangle (an independent
// path: VTK's writer against abrade's reader), a version-4 file with a triangle strip gives its
// triangles, and damaged files name the line.
TEST(LegacyVtk, VtksOwnFilesComeBackAndDamageIsNamed)
{
  vtkNew<vtkPoints>    points;
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < 6; ++i)
    points->InsertNextPoint(0.1 * i, 0.3 * std::sin(i), 1.0 / (i + 3));
  const vtkIdType quad[4] = {0, 1, 2, 3}, tri[3] = {3, 4, 5};
  polys->InsertNextCell(3, tri);
  polys->InsertNextCell(4, quad);
  vtkNew<vtkPolyData> original;
  original->SetPoints(points);
  original->SetPolys(polys);
  for (const bool binary : {false, true})
    {
      const std::string path = tmp(binary ? "legacy_binary.vtk" : "legacy_ascii.vtk");
      vtkNew<vtkPolyDataWriter> w;
      w->SetInputData(original);
      w->SetFileName(path.c_str());
      if (binary)
        w->SetFileTypeToBinary();
      else
        w->SetFileTypeToASCII();
      w->Write();
      const auto back = abrade::io::read_polydata(path);
      ASSERT_EQ(back->GetNumberOfPoints(), 6) << path;
      for (vtkIdType i = 0; i < 6; ++i)
        for (int k = 0; k < 3; ++k) // the writer writes floats, in ASCII with 6 digits
          EXPECT_NEAR(back->GetPoint(i)[k], original->GetPoint(i)[k], binary ? 1e-7 : 1e-6) << path;
      ASSERT_EQ(back->GetNumberOfCells(), 2) << path;
      vtkIdType        n;
      const vtkIdType *ids;
      back->GetCellPoints(1, n, ids);
      EXPECT_EQ(std::vector<vtkIdType>(ids, ids + n), (std::vector<vtkIdType>{0, 1, 2, 3})) << path;
    }
  const std::string v4 = "# vtk DataFile Version 3.0\nstrip\nASCII\nDATASET POLYDATA\nPOINTS 5 float\n"
                         "0 0 0 1 0 0 0 1 0 1 1 0 0 2 0\nTRIANGLE_STRIPS 1 6\n5 0 1 2 3 4\n"
                         "POINT_DATA 5\nSCALARS s float\nLOOKUP_TABLE default\n1 2 3 4 5\n";
  std::ofstream(tmp("strip.vtk")) << v4;
  const auto strip = abrade::io::read_polydata(tmp("strip.vtk"));
  ASSERT_EQ(strip->GetNumberOfCells(), 3);
  vtkIdType        n;
  const vtkIdType *ids;
  strip->GetCellPoints(1, n, ids); // the second triangle of a strip is turned: 1 3 2
  EXPECT_EQ(std::vector<vtkIdType>(ids, ids + n), (std::vector<vtkIdType>{1, 3, 2}));
  auto error_of = [&](const std::string &text) {
    std::ofstream(tmp("damaged.vtk")) << text;
    try
      {
        abrade::io::read_polydata(tmp("damaged.vtk"));
      }
    catch (const InputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  auto replaced = [&](const std::string &from, const std::string &to) {
    std::string t = v4;
    return t.replace(t.find(from), from.size(), to);
  };
  EXPECT_NE(error_of(replaced("5 0 1 2 3 4", "5 0 1 2 3 9")).find("damaged.vtk:8: TRIANGLE_STRIPS: point index 9 out of range"),
            std::string::npos) << error_of(replaced("5 0 1 2 3 4", "5 0 1 2 3 9"));
  EXPECT_NE(error_of(replaced("TRIANGLE_STRIPS 1 6", "TRIANGLE_STRIPS 1 2147483647")).find("more than the rest of the file"),
            std::string::npos);
  EXPECT_NE(error_of(replaced("5 0 1 2 3 4", "2147483647 0 1 2 3 4")).find("cell 0 of 1 does not fit"), std::string::npos);
  EXPECT_NE(error_of(v4.substr(0, 80)).find("damaged.vtk:"), std::string::npos);
  EXPECT_NE(error_of(replaced("POLYDATA", "UNSTRUCTURED_GRID")).find("only DATASET POLYDATA"), std::string::npos);
  // cells read against the first points, then POINTS again (a crash when it was let through)
  EXPECT_NE(error_of(replaced("POINT_DATA", "POINTS 3 float\n0 0 0 1 0 0 0 1 0\nPOINT_DATA")).find("POINTS given twice"),
            std::string::npos);
  // what VTK's and ParaView's writers add: FIELD data before the points, METADATA after them,
  // an empty title, a format word in lower case
  const std::string extras = "# vtk DataFile Version 5.1\n\nascii\nDATASET POLYDATA\nFIELD FieldData 2\n"
                             "TimeValue 1 1 double\n0.5\nNAMES 2 1 float\n1 2\nPOINTS 3 float\n0 0 0 1 0 0 0 1 0\n"
                             "METADATA\nINFORMATION 1\nNAME L2_NORM_RANGE LOCATION vtkDataArray\nDATA 2 0 1\n\n"
                             "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n";
  EXPECT_EQ(error_of(extras), "no error");
}

// PLY files are read by abrade's own checked reader: what VTK's writer wrote (ASCII, binary
// little- and big-endian) comes back exactly; a file whose last line has no newline (VTK's reader
// freed a pointer twice on it) is read; a face past the vertices names the line.
TEST(PlyFile, VtksOwnFilesComeBackAndDamageIsNamed)
{
  vtkNew<vtkPoints>    points;
  vtkNew<vtkCellArray> polys;
  for (int i = 0; i < 5; ++i)
    points->InsertNextPoint(0.25 * i, 0.5 * std::sin(i), 0.125 * i * i);
  const vtkIdType quad[4] = {0, 1, 2, 3}, tri[3] = {2, 3, 4};
  polys->InsertNextCell(4, quad);
  polys->InsertNextCell(3, tri);
  vtkNew<vtkPolyData> original;
  original->SetPoints(points);
  original->SetPolys(polys);
  for (const int format : {0, 1, 2})
    {
      const std::string path = tmp("ply_" + std::to_string(format) + ".ply");
      vtkNew<vtkPLYWriter> w;
      w->SetInputData(original);
      w->SetFileName(path.c_str());
      if (format == 0)
        w->SetFileTypeToASCII();
      else
        {
          w->SetFileTypeToBinary();
          w->SetDataByteOrder(format == 1 ? VTK_LITTLE_ENDIAN : VTK_BIG_ENDIAN);
        }
      w->Write();
      const auto back = abrade::io::read_polydata(path);
      ASSERT_EQ(back->GetNumberOfPoints(), 5) << path;
      for (vtkIdType i = 0; i < 5; ++i)
        for (int k = 0; k < 3; ++k) // floats
          EXPECT_NEAR(back->GetPoint(i)[k], original->GetPoint(i)[k], 1e-6) << path;
      ASSERT_EQ(back->GetNumberOfCells(), 2) << path;
      vtkIdType        n;
      const vtkIdType *ids;
      back->GetCellPoints(0, n, ids);
      EXPECT_EQ(std::vector<vtkIdType>(ids, ids + n), (std::vector<vtkIdType>{0, 1, 2, 3})) << path;
    }
  const std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                           "property float z\nproperty uchar red\nelement face 1\nproperty list uchar int "
                           "vertex_indices\nend_header\n0 0 0 255\n1 0 0 0\n0 1 0 9\n3 0 1 2";
  std::ofstream(tmp("no_newline.ply")) << text;
  EXPECT_EQ(abrade::io::read_polydata(tmp("no_newline.ply"))->GetNumberOfCells(), 1);
  std::ofstream(tmp("bad_face.ply")) << text.substr(0, text.size() - 1) << "3\n";
  try
    {
      abrade::io::read_polydata(tmp("bad_face.ply"));
      ADD_FAILURE() << "a face past the vertices was read";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("bad_face.ply:14: vertex index 3"), std::string::npos) << e.what();
    }
}

TEST(FieldCompare, NonManifoldScanIsAWarning)
{
  auto m = knife();
  m.vertices.emplace_back(0.2, 0.1, 0.3); // a fin on an existing edge: three triangles share it
  m.triangles.push_back({m.triangles[0][0], m.triangles[0][1], int(m.vertices.size() - 1)});
  write(m, tmp("fin.stl"));
  std::vector<std::string> warnings;
  const auto               g = read_geometry(tmp("fin.stl"), warnings);
  EXPECT_GT(g.non_manifold_edges, 0);
  EXPECT_FALSE(g.closed);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("non-manifold"), std::string::npos);
}

TEST(FieldMeasurements, TablesAndTheirErrors)
{
  {
    std::ofstream t(tmp("m.csv"));
    t << "location,tonnes,depth_mm\nA,1000,1.5\nB,2000,3\n";
    std::ofstream l(tmp("locations.csv"));
    l << "name,x,y,z\nA,0.1,0,0\nB,0.2,0,0.01\n";
  }
  const auto m = read_measurements(tmp("m.csv"), tmp("locations.csv"));
  ASSERT_EQ(m.size(), 2u);
  EXPECT_DOUBLE_EQ(m[1].depth, 0.003);
  EXPECT_DOUBLE_EQ(m[1].point[2], 0.01);
  auto error_of_table = [](const std::string &text) {
    std::ofstream(tmp("e.csv")) << text;
    try
      {
        read_measurements(tmp("e.csv"));
      }
    catch (const InputError &e)
      {
        return std::string(e.what());
      }
    return std::string("no error");
  };
  EXPECT_NE(error_of_table("x,y,z,depth\n0,0,0,1\n").find("missing column 'tonnes'"), std::string::npos);
  EXPECT_NE(error_of_table("x,y,z,tonnes\n0,0,0,1\n").find("'depth'"), std::string::npos);
  EXPECT_NE(error_of_table("x,y,z,tonnes,depth\n0,0,0,1,0.1\n0,0,zero,1,0.1\n").find("e.csv:3"), std::string::npos);
  EXPECT_NE(error_of_table("x,y,z,tonnes,depth\n").find("no measurements"), std::string::npos);
  EXPECT_NE(error_of_table("").find("empty table"), std::string::npos);
}

TEST(FieldStatistics, KnownValues)
{
  std::vector<double> d;
  for (int i = 1; i <= 100; ++i)
    d.push_back(i % 2 ? -0.001 * i : 0.001 * i);
  const auto s = statistics(d);
  EXPECT_EQ(s.n, 100u);
  EXPECT_NEAR(s.mean, 0.0005, 1e-15);
  EXPECT_NEAR(s.max_abs, 0.1, 1e-15);
  EXPECT_NEAR(s.p95, 0.095, 1e-15);
  EXPECT_NEAR(s.rms, 0.001 * std::sqrt(101.0 * 201 / 6), 1e-12);
  EXPECT_NEAR(student_t95(10), 2.228, 1e-12);
}
