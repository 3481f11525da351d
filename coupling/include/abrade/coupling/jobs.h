#pragma once
// What `abrade run` can do. Each job is a named, self-describing entry in one registry
// (jobs.cc); the parameter `Job` selects one. A job reads its parameters, writes its files into
// the output directory, and fills the "results" object of summary.json.
#include <abrade/common/json.h>
#include <abrade/common/log.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/timer.h>
#include <abrade/coupling/parameter_file.h>

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

  // the jobs
  void run_dem_job(JobContext &ctx);
  void run_knife_job(JobContext &ctx);
} // namespace abrade::coupling
