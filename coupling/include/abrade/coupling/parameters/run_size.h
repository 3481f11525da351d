#pragma once
// How big a DEM run is, before it starts: its particles, time step, steps and memory, from the
// parameters alone. A run that would take years (a time step of 1e-9 s, a density of 1e-12) or
// more memory than the machine has (1e9 particles) is refused with the estimate, before the
// bed is generated (read_dem_case calls check_run_size).
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>

namespace abrade::coupling
{
  struct RunSize
  {
    double particles      = 0; ///< Count, or the solid fraction of the fill region's box
    double time_step      = 0; ///< [s] Time step, or the Rayleigh fraction of the smallest particle's
    double simulated_time = 0; ///< [s] settling (when the bed is generated) and the phases
    double steps          = 0;
    double particle_steps = 0;
    double bytes          = 0; ///< about 1 kB per particle (state, neighbour lists, contacts)
  };

  /// One DEM run (one operating cycle) of case @p c.
  RunSize estimate_run_size(const DemCase &c);

  /// The memory this machine has available [bytes] (MemAvailable of /proc/meminfo; 0: unknown).
  double available_memory();

  /// Refuses a run above Simulation/Maximum particle-steps or above the available memory, with
  /// the estimate (errors name the parameter file).
  void check_run_size(const DemCase &c, ParameterFile &file);
} // namespace abrade::coupling
