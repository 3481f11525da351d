#pragma once
// Subsection Output: the output directory (read where the run's directory is made), the
// snapshots and force files, and the wear field with its profile and filter, declared and read
// into a DemCase.
#include <abrade/coupling/parameters/parameters.h>

#include <string>

namespace abrade::coupling
{
  void declare_output_parameters(dealii::ParameterHandler &prm);
  /// Reads subsection Output's entries that the DEM job uses into @p c.
  void read_output_parameters(ParameterFile &f, DemCase &c);

  /// Output/Directory of @p f: where the run writes.
  std::string output_directory(ParameterFile &f);
  /// Sets Output/Directory of @p f to @p directory (the command line's --output over the file's).
  void set_output_directory(ParameterFile &f, const std::string &directory);
} // namespace abrade::coupling
