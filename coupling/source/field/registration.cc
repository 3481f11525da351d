// Rigid registration of a scan to a surface: coarse alignment, then ICP on the closest points
// (field/registration.h).
#include <abrade/common/error.h>
#include <abrade/field/registration.h>

#include <vtkCellLocator.h>
#include <vtkGenericCell.h>
#include <vtkIterativeClosestPointTransform.h>
#include <vtkLandmarkTransform.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkTransform.h>
#include <vtkTriangle.h>

#include <Eigen/Dense>

#include <cmath>

namespace abrade::field
{
  namespace
  {
    using Mat4 = Eigen::Matrix4d;

    /// Scan points, subsampled evenly to at most @p n, optionally only those inside @p box after
    /// the transform @p t.
    vtkSmartPointer<vtkPolyData> landmarks(const Geometry &scan, std::size_t n, const Mat4 &t,
                                           const std::optional<Box> &box = {})
    {
      vtkNew<vtkPoints> pts;
      const vtkIdType   total  = scan.data->GetNumberOfPoints();
      const vtkIdType   stride = std::max<vtkIdType>(1, total / vtkIdType(n));
      for (vtkIdType i = 0; i < total; i += stride)
        {
          const double   *p = scan.data->GetPoint(i);
          Eigen::Vector4d q = t * Eigen::Vector4d(p[0], p[1], p[2], 1);
          if (box && !box->contains(q.data()))
            continue;
          pts->InsertNextPoint(q[0], q[1], q[2]);
        }
      auto poly = vtkSmartPointer<vtkPolyData>::New();
      poly->SetPoints(pts);
      return poly;
    }

    /// Principal axes (columns, descending variance) of area-weighted triangle centroids or of
    /// the points.
    Eigen::Matrix3d principal_axes(const Geometry &g, const Eigen::Vector3d &c)
    {
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      auto            add = [&](const double *p, double w) {
        const Eigen::Vector3d d(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
        cov += w * d * d.transpose();
      };
      if (g.point_cloud)
        for (vtkIdType i = 0; i < g.data->GetNumberOfPoints(); ++i)
          add(g.data->GetPoint(i), 1.0);
      else
        for (vtkIdType t = 0; t < g.data->GetNumberOfCells(); ++t)
          {
            vtkIdType        n;
            const vtkIdType *ids;
            g.data->GetCellPoints(t, n, ids);
            double a[3], b[3], d[3], m[3];
            g.data->GetPoint(ids[0], a), g.data->GetPoint(ids[1], b), g.data->GetPoint(ids[2], d);
            for (int k = 0; k < 3; ++k)
              m[k] = (a[k] + b[k] + d[k]) / 3;
            add(m, vtkTriangle::TriangleArea(a, b, d));
          }
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
      Eigen::Matrix3d                                axes = eig.eigenvectors().rowwise().reverse();
      if (axes.determinant() < 0)
        axes.col(2) *= -1;
      return axes;
    }

    double rms_distance(vtkPolyData *points, vtkPolyData *target, const Mat4 &t = Mat4::Identity());

    /// The rigid transform that ICP finds from @p source (points) onto @p target; it stops when
    /// the landmarks move less than 1e-9 of the target's size (RMS) in an iteration.
    Mat4 icp(vtkPolyData *source, vtkPolyData *target, int iterations)
    {
      vtkNew<vtkIterativeClosestPointTransform> icp;
      icp->SetSource(source);
      icp->SetTarget(target);
      icp->GetLandmarkTransform()->SetModeToRigidBody();
      icp->SetMaximumNumberOfIterations(iterations);
      icp->SetMaximumNumberOfLandmarks(int(source->GetNumberOfPoints()));
      icp->StartByMatchingCentroidsOff();
      icp->CheckMeanDistanceOn();
      icp->SetMeanDistanceModeToRMS();
      icp->SetMaximumMeanDistance(1e-9 * target->GetLength());
      icp->Modified();
      icp->Update();
      Mat4 m;
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
          m(i, j) = icp->GetMatrix()->GetElement(i, j);
      return m;
    }

    /// RMS distance of @p points, moved by @p t, to the surface @p target.
    double rms_distance(vtkPolyData *points, vtkPolyData *target, const Mat4 &t)
    {
      vtkNew<vtkCellLocator> loc;
      loc->SetDataSet(target);
      loc->BuildLocator();
      double sum = 0;
      for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
        {
          double     closest[3], d2;
          vtkIdType  cell;
          int        sub;
          const double   *p = points->GetPoint(i);
          Eigen::Vector4d q = t * Eigen::Vector4d(p[0], p[1], p[2], 1);
          loc->FindClosestPoint(q.data(), closest, cell, sub, d2);
          sum += d2;
        }
      return std::sqrt(sum / std::max<vtkIdType>(1, points->GetNumberOfPoints()));
    }

    Mat4 translation(const Eigen::Vector3d &d)
    {
      Mat4 t = Mat4::Identity();
      t.block<3, 1>(0, 3) = d;
      return t;
    }

    /// The starts of the registration: the scan as it is, and (@p coarse) its principal axes
    /// onto the model's, each of the four proper rotations that does that.
    std::vector<Mat4> starts(const Geometry &scan, const Geometry &model, bool coarse)
    {
      std::vector<Mat4> candidates = {Mat4::Identity()};
      if (!coarse)
        return candidates;
      const auto            cs = scan.centroid(), cm = model.centroid();
      const Eigen::Vector3d c_scan(cs[0], cs[1], cs[2]), c_model(cm[0], cm[1], cm[2]);
      const Eigen::Matrix3d a_scan = principal_axes(scan, c_scan), a_model = principal_axes(model, c_model);
      for (const auto &signs : {Eigen::Vector3d(1, 1, 1), Eigen::Vector3d(-1, -1, 1), Eigen::Vector3d(-1, 1, -1),
                                Eigen::Vector3d(1, -1, -1)})
        {
          Mat4 r               = Mat4::Identity();
          r.block<3, 3>(0, 0) = a_model * signs.asDiagonal() * a_scan.transpose();
          candidates.push_back(translation(c_model) * r * translation(-c_scan));
        }
      return candidates;
    }

    /// The transform from the best of @p candidates after a short ICP from each (at most 2,000
    /// landmarks, 40 iterations).
    Mat4 best_start(const Geometry &scan, const Geometry &model, const std::vector<Mat4> &candidates,
                    const RegistrationSettings &settings)
    {
      const std::size_t coarse_points = std::min<std::size_t>(settings.max_points, 2000);
      Mat4              best          = Mat4::Identity();
      double            best_rms      = std::numeric_limits<double>::infinity();
      // Each start is judged where the scan should fit: in the registration region if one is
      // given (the unworn part), else everywhere. The scan as it is wins unless another start
      // fits clearly better (by 5 %): a part symmetric under a half turn (a double-bevel knife)
      // fits its design turned round almost as well, and which of the two a worn scan's noise
      // preferred flipped a scan already in the model's frame (field/round_trip: registered on
      // the unworn top, a half turn about z)
      // (@p src: the scan's landmarks moved by the start, @p m: ICP's transform from there)
      auto judged = [&](const Mat4 &start, vtkPolyData *src, const Mat4 &m) {
        if (settings.region)
          if (auto inside = landmarks(scan, coarse_points, m * start, settings.region); inside->GetNumberOfPoints() >= 10)
            return rms_distance(inside, model.data);
        return rms_distance(src, model.data, m);
      };
      double as_it_is = std::numeric_limits<double>::infinity();
      Mat4   kept     = Mat4::Identity();
      for (const Mat4 &start : candidates)
        {
          auto         src = landmarks(scan, coarse_points, start);
          const Mat4   m   = icp(src, model.data, 40);
          const double rms = judged(start, src, m);
          if (&start == &candidates.front())
            as_it_is = rms, kept = m * start;
          if (rms < best_rms)
            best_rms = rms, best = m * start;
        }
      return as_it_is <= 1.05 * best_rms ? kept : best;
    }

    /// The model's triangles with a vertex in @p region.
    vtkSmartPointer<vtkPolyData> model_in(const Geometry &model, const Box &region)
    {
      auto                 part = vtkSmartPointer<vtkPolyData>::New();
      vtkNew<vtkCellArray> cells;
      for (vtkIdType t = 0; t < model.data->GetNumberOfCells(); ++t)
        {
          vtkIdType        n;
          const vtkIdType *ids;
          model.data->GetCellPoints(t, n, ids);
          bool inside = false;
          for (vtkIdType k = 0; k < n; ++k)
            inside = inside || region.contains(model.data->GetPoint(ids[k]));
          if (inside)
            cells->InsertNextCell(n, ids);
        }
      part->SetPoints(model.data->GetPoints());
      part->SetPolys(cells);
      return part;
    }

    /// Every point of @p scan moved by @p t.
    void move(Geometry &scan, const Mat4 &t)
    {
      vtkPoints *pts = scan.data->GetPoints();
      for (vtkIdType i = 0; i < pts->GetNumberOfPoints(); ++i)
        {
          const double   *p = pts->GetPoint(i);
          Eigen::Vector4d q = t * Eigen::Vector4d(p[0], p[1], p[2], 1);
          pts->SetPoint(i, q[0], q[1], q[2]);
        }
      pts->Modified();
      scan.data->Modified();
    }
  } // namespace

  Registration register_scan(Geometry &scan, const Geometry &model, const RegistrationSettings &settings)
  {
    Registration r;
    if (!settings.enabled) // the scan is in the model's frame already: measured as it is
      {
        for (int i = 0; i < 16; ++i)
          r.matrix[i] = i % 5 == 0 ? 1.0 : 0.0;
        r.points_used = std::min<std::size_t>(settings.max_points, std::size_t(scan.data->GetNumberOfPoints()));
        r.rms         = rms_distance(landmarks(scan, settings.max_points, Mat4::Identity()), model.data);
        return r;
      }
    Mat4 best = best_start(scan, model, starts(scan, model, settings.coarse), settings);
    // full ICP from the best start
    {
      auto src = landmarks(scan, settings.max_points, best);
      best     = icp(src, model.data, settings.iterations) * best;
    }
    // then on the registration region only: the scan's points there onto the model's part there
    if (settings.region)
      {
        auto src = landmarks(scan, settings.max_points, best, settings.region);
        if (src->GetNumberOfPoints() < 10)
          throw InputError("--register-on", "fewer than 10 scan points lie in the registration region after the "
                                            "coarse alignment: is the region in model coordinates and on the scan?");
        best          = icp(src, model_in(model, *settings.region), settings.iterations) * best;
        r.points_used = std::size_t(src->GetNumberOfPoints());
      }
    else
      r.points_used = std::min<std::size_t>(settings.max_points, std::size_t(scan.data->GetNumberOfPoints()));
    move(scan, best); // into the model's frame
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)
        r.matrix[4 * i + j] = best(i, j);
    r.rms = rms_distance(landmarks(scan, settings.max_points, Mat4::Identity()), model.data);
    return r;
  }
} // namespace abrade::field
