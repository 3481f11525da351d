#pragma once
// MPI for the FEM side (PETSc, deal.II's parallel triangulations) in a process that did not
// start it: initialised on the first call, finalised when the process ends.

namespace abrade::fem
{
  /// Initialises MPI (through deal.II, for PETSc) unless done before; every later call does
  /// nothing. A process started under mpirun gets its ranks as usual.
  void init_mpi_once();
} // namespace abrade::fem
