#pragma once
// Subsection Simulation: the time step, the contact law's sub-models, threads and ranks, the
// domain, what an error does, the operating cycle's phases and the payload height, declared and
// read into a DemCase.
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/parallel.h>

#include <optional>

namespace abrade::coupling
{
  void declare_simulation_parameters(dealii::ParameterHandler &prm);
  /// Reads and checks subsection Simulation into @p c (its settings, phases, payload height and
  /// run-size limit); errors name the file, line and entry.
  void read_simulation_parameters(ParameterFile &f, DemCase &c);

  /// Simulation/Payload height of @p f [m] (none: the entry is empty), or an error naming it.
  std::optional<double> read_payload_height(ParameterFile &f);

  /// The threads per rank of a run of @p f: Simulation/Threads, or with 0 the machine's cores
  /// shared among @p ranks on it.
  int read_thread_count(ParameterFile &f, const dem::Parallel &ranks);
} // namespace abrade::coupling
