#pragma once
// What `abrade run` can do. Each job is a named, self-describing entry in one registry
// (jobs.cc); the parameter `Job` selects one. A job reads its parameters, writes its files into
// the output directory, and fills the "results" object of summary.json.
#include <abrade/common/json.h>
#include <abrade/common/log.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/timer.h>
#include <abrade/coupling/parameter_file.h>
#include <abrade/dem/simulation.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  struct JobContext
  {
    ParameterFile          &parameters;
    const io::OutputDirectory &output;
    io::Json               &results;
    io::Timers             &timers;
    io::Log                &log;
    bool                    resume = false;
  };

  struct JobInfo
  {
    std::string name;
    std::string description;
    void (*run)(JobContext &);
  };

  /// All jobs, in one place.
  const std::vector<JobInfo> &registered_jobs();

  struct DemCase;
  /// Loads the settled bed from @p bed_file if it exists (relative: in the output directory),
  /// otherwise generates, settles and saves it there (empty: generate, save nothing); sets the
  /// simulation up. Returns true when the bed was loaded.
  bool prepare_bed(const DemCase &c, dem::Simulation &sim, JobContext &ctx, std::string bed_file);
  /// Logs the case's coarse graining (and records it in summary.json) and the parameters that
  /// do not follow it.
  void report_coarse_graining(const DemCase &c, JobContext &ctx);

  // the jobs
  void run_dem_job(JobContext &ctx);
  void run_lifetime_job(JobContext &ctx);
  void run_knife_job(JobContext &ctx);
  /// Job 'bed': generate and settle the particles and save the bed, nothing else.
  void run_bed_job(JobContext &ctx);
} // namespace abrade::coupling
