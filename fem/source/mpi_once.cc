// MPI for the FEM side, initialised once (mpi_once.h).
#include <abrade/fem/mpi_once.h>

#include <deal.II/base/mpi.h>

namespace abrade::fem
{
  void init_mpi_once()
  {
    static int                                      argc = 1;
    static char                                     name[] = "abrade", *args[] = {name, nullptr};
    static char                                   **argv = args;
    static dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  }
} // namespace abrade::fem
