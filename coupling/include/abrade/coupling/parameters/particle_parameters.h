#pragma once
// Subsection Particles: the particles' material and contacts, how the bed is generated (the fill
// region and the sizes), coarse graining (dem/coarse_graining.h), and the settling with its bed
// file, declared and read into a DemCase.
#include <abrade/coupling/parameters/parameters.h>

namespace abrade::coupling
{
  void declare_particle_parameters(dealii::ParameterHandler &prm);
  /// Reads and checks subsection Particles into @p c, after subsection Simulation (the fill box
  /// must lie in its domain; coarse graining scales its skin) and applies coarse graining;
  /// errors name the file, line and entry.
  void read_particle_parameters(ParameterFile &f, DemCase &c);
} // namespace abrade::coupling
