#pragma once
// Subsection Output: the output directory (read where the run's directory is made), the
// snapshots and force files, and the wear field with its profile and filter, declared and read
// into a DemCase.
#include <abrade/coupling/parameters.h>

namespace abrade::coupling
{
  void declare_output_parameters(dealii::ParameterHandler &prm);
  /// Reads subsection Output's entries that the DEM job uses into @p c.
  void read_output_parameters(ParameterFile &f, DemCase &c);
} // namespace abrade::coupling
