#pragma once
// What a wear law's file needs (wear_law.h): the interface with its registration line, the
// simulation it reads and a helper (parameter_section.h gives the laws `unbounded`).
#include <abrade/dem/simulation.h>
#include <abrade/dem/wear_law.h>

#include <cmath>
#include <limits>
#include <memory>

namespace abrade::dem::wear_laws
{
  /// |v| of a 3-vector.
  inline double length(const double *v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }
} // namespace abrade::dem::wear_laws
