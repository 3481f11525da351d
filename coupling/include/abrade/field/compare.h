#pragma once
// `abrade compare`: a field scan of a worn knife against the predicted worn surface (and the
// unworn design). The scan is brought into the model's units and frame (scan.h,
// registration.h), then every scan point gets its signed distance to the prediction (> 0: the
// scan lies outside the predicted surface, i.e. less wear than predicted) and, with a design,
// its measured wear depth (its distance inside the design). Statistics, the measured and the
// predicted worn volume, a deviation-coloured .vtp and profile plots go to the output folder.
#include <abrade/field/registration.h>

#include <string>
#include <vector>

namespace abrade::field
{
  struct CompareSettings
  {
    std::string          predicted, scan, reference; ///< reference (the design) is optional
    std::string          output;
    std::string          scan_units = "auto";       ///< auto | m | mm
    RegistrationSettings registration;
    int                  profile_axis = 0;          ///< planes normal to x (0), y (1) or z (2)
    std::vector<double>  profile_planes;            ///< coordinates along the axis [m]
    double               tonnes = -1;               ///< the scan's tonnage, written with the measured depths
  };

  struct DeviationStatistics
  {
    std::size_t n = 0;
    double      rms = 0, mean = 0, max_abs = 0, p95 = 0;
    double      hausdorff = 0; ///< symmetric, over the model's part within the scan's bounding box
  };

  struct CompareResult
  {
    Registration             registration;
    double                   scan_scale = 1;
    DeviationStatistics      to_predicted, to_reference;
    bool                     has_reference = false;
    double                   measured_volume = 0, predicted_volume = 0; ///< worn volume [m^3]
    std::string              volume_method;                             ///< how the volumes were found
    std::vector<std::string> warnings;
  };

  /// Runs the comparison and writes DIR/comparison.json, DIR/deviation.vtp, DIR/profile_*.csv
  /// and .png, and (with a design) DIR/measured_depths.csv for `abrade calibrate`.
  CompareResult compare(const CompareSettings &settings);

  /// Statistics of signed distances; the 95th percentile and the maximum are of |d|.
  DeviationStatistics statistics(std::vector<double> d);
} // namespace abrade::field
