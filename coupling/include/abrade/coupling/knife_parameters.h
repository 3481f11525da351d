#pragma once
// The knife's solid model as the parameter file describes it (subsection Knife), shared by the
// knife and lifetime jobs.
#include <abrade/coupling/parameter_file.h>
#include <abrade/fem/knife_geometry.h>

#include <string>

namespace abrade::coupling
{
  struct KnifeParameters
  {
    fem::KnifeGeometry geometry;
    double             mesh_size = 0.015;
    double             density   = 7800;
    bool               from_file = false;
    std::string        file;
  };

  /// Reads and checks subsection Knife; errors name the file.
  KnifeParameters read_knife_parameters(ParameterFile &file);

  /// MPI (for PETSc) in this single process, initialised once.
  void init_mpi_once();
} // namespace abrade::coupling
