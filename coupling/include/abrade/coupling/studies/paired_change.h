#pragma once
// A variant against a baseline, pair by pair (common random numbers): both ran on the same beds,
// one value per bed each. The change is the geometric mean of the per-bed ratios variant /
// baseline, with the 95 % Student t-interval of the mean log ratio over the beds (n - 1 degrees
// of freedom). The bed-to-bed scatter both share cancels in each ratio, so differences far
// smaller than the beds' spread are resolved. Used by `abrade concepts` and `abrade sweep`.
#include <vector>

namespace abrade::coupling
{
  struct PairedChange
  {
    double      ratio = 1, low = 1, high = 1; ///< the ratio and its 95 % interval
    bool        interval    = false;          ///< there is one (not with one bed)
    bool        significant = false;          ///< the interval excludes 1
    std::size_t pairs = 0;                    ///< beds with both values positive
  };

  /// @p variant and @p baseline: one value per bed, the same beds in the same order (values <= 0
  /// leave their pair out). One pair gives the ratio without an interval.
  PairedChange paired_change(const std::vector<double> &variant, const std::vector<double> &baseline);
} // namespace abrade::coupling
