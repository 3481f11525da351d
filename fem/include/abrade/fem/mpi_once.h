#pragma once
// MPI for the FEM side (PETSc, deal.II's parallel triangulations) in a process that did not
// start it: initialised on the first call, finalised when the process ends.

namespace abrade::fem
{
  /// Initialises MPI (through deal.II, for PETSc) on its first call; every later call does
  /// nothing. A process that started MPI itself must not call it (deal.II refuses a second
  /// start). A process started under mpirun gets its ranks as usual.
  void init_mpi_once();
} // namespace abrade::fem
