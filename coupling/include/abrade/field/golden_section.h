#pragma once
// The minimum of a unimodal function on an interval by golden sections: one new evaluation per
// step (the calibration's scale of W, the footprint profile's minimum).
#include <cmath>

namespace abrade::field
{
  /// The x in [@p a, @p b] where @p f is least, to @p tolerance or after @p steps steps.
  template <typename Function>
  double golden_section_minimum(const Function &f, double a, double b, double tolerance, int steps)
  {
    const double g  = (std::sqrt(5.0) - 1) / 2;
    double       xc = b - g * (b - a), xd = a + g * (b - a), fc = f(xc), fd = f(xd);
    for (int it = 0; it < steps && b - a > tolerance; ++it)
      if (fc < fd)
        b = xd, xd = xc, fd = fc, xc = b - g * (b - a), fc = f(xc);
      else
        a = xc, xc = xd, fc = fd, xd = a + g * (b - a), fd = f(xd);
    return 0.5 * (a + b);
  }
} // namespace abrade::field
