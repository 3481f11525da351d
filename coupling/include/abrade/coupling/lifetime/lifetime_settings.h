#pragma once
// Subsection Lifetime: the tonnes, the beds and the updates, the filter, the gauges, the wear
// source and the end-of-life criteria, the interval asked for and a calibration (read by
// LifetimeLoop::read_settings(), in the same file as the declaration).
#include <deal.II/base/parameter_handler.h>

namespace abrade::coupling::lifetime
{
  void declare_lifetime_parameters(dealii::ParameterHandler &prm);
} // namespace abrade::coupling::lifetime
