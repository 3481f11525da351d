#pragma once
// The particle bed a DEM run starts from, shared by the dem and bed jobs and the lifetime loop's
// cycles: generated, poured and settled (and saved for later runs), loaded from a saved bed, or
// imported from another code's file.
#include <abrade/common/log.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/simulation.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  /// Loads the settled bed from @p bed_file if it exists (relative: in the output directory),
  /// otherwise generates, settles and saves it there (empty: generate, save nothing); sets the
  /// simulation up. Returns true when the bed was loaded.
  ///
  /// A loaded bed that another setting made (other Fine region pours, another fine region: the
  /// particles it holds against the case's) is used as it is; what tells so is logged as a
  /// warning, or, where @p provenance is given, put there instead: the lifetime loop lists it as
  /// its set-up, not among the faults of a cycle.
  bool prepare_bed(const DemCase &c, dem::Simulation &sim, JobContext &ctx, std::string bed_file,
                   std::vector<std::string> *provenance = nullptr);

  /// Logs what the reading of the case decided, its warnings and its coarse graining (which it
  /// records in summary.json).
  void report_coarse_graining(const DemCase &c, JobContext &ctx);

  /// The simulation's warnings since the last call, into the log.
  void flush_warnings(dem::Simulation &sim, io::Log &log);
} // namespace abrade::coupling
