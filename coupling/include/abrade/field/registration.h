#pragma once
// Rigid registration of a scan to a model surface: a coarse alignment (the scan as it is, and
// its principal axes turned onto the model's in the four proper ways), each refined by a short
// ICP; the best is refined by a full ICP (VTK's vtkIterativeClosestPointTransform, rigid body,
// point to surface). Optionally a last ICP uses only the parts that do not wear (a box in model
// coordinates: the back face, the bolt holes), so that the worn region does not pull the fit.
#include <abrade/field/scan.h>

#include <array>
#include <optional>

namespace abrade::field
{
  struct Box
  {
    std::array<double, 3> lo, hi;
    bool contains(const double *p) const
    {
      return p[0] >= lo[0] && p[0] <= hi[0] && p[1] >= lo[1] && p[1] <= hi[1] && p[2] >= lo[2] && p[2] <= hi[2];
    }
  };

  struct RegistrationSettings
  {
    bool               enabled = true;         ///< false: the scan is in the model's frame already (no registration)
    bool               coarse = true;          ///< principal-axes candidates; false: ICP from the scan as it is
    std::optional<Box> region;                 ///< register on this part of the model only
    int                iterations = 300;
    std::size_t        max_points = 20000;     ///< ICP landmarks (scan points, subsampled evenly)
  };

  struct Registration
  {
    std::array<double, 16> matrix;   ///< scan -> model, row-major 4x4
    double                 rms = 0;  ///< of the scan points' distances to the model after it
    std::size_t            points_used = 0;
    /// With a registration region: the RMS distance of the scan points inside it (what the fit
    /// saw) and of the rest (wear and misfit), and how many points each has.
    double                 rms_region = 0, rms_rest = 0;
    std::size_t            points_region = 0, points_rest = 0;
  };

  /// Registers @p scan onto @p model and moves the scan's points into the model's frame.
  Registration register_scan(Geometry &scan, const Geometry &model, const RegistrationSettings &settings);
} // namespace abrade::field
