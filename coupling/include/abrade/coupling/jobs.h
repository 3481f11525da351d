#pragma once
// What `abrade run` can do: each job is a plugin, a class in its own file of
// coupling/source/jobs/ registered with one line, and the parameter `Job` selects one. A job
// reads its parameters, writes its files into the output directory, and fills the "results"
// object of summary.json.
#include <abrade/common/json.h>
#include <abrade/common/plugin_registry.h>
#include <abrade/common/log.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/timer.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/dem/simulation.h>

#include <memory>
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

  /// A job: what `Job = NAME` makes `abrade run` do. One class in a file of its own in
  /// coupling/source/jobs/, registered there with one line, ABRADE_REGISTER_JOB(MyJob).
  class Job
  {
  public:
    virtual ~Job() = default;
    /// The name written in Job ("dem").
    virtual std::string name() const = 0;
    /// What it does, a phrase for Job's documentation.
    virtual std::string documentation() const = 0;
    /// Reads its parameters from @p ctx, writes its files and fills the results.
    virtual void run(JobContext &ctx) const = 0;

    /// What `abrade run` makes of the job's files after it, on rank 0 (report/report.h).
    struct Report
    {
      bool page            = false; ///< report.html
      bool paraview_script = false; ///< a ParaView script of the worn states
      bool after_a_failure = false; ///< the page also of what a failed run wrote before it
    };
    /// None unless the job says otherwise.
    virtual Report report() const { return {}; }
  };

  using JobFactory = std::unique_ptr<Job> (*)();

  /// One new instance of every registered job, in the order of their names.
  std::vector<std::unique_ptr<Job>> make_jobs();
  /// A new job of that name; nullptr if there is none.
  std::unique_ptr<Job> make_job(const std::string &name);

  /// Adds a job (ABRADE_REGISTER_JOB); a name registered twice is a bug.
  struct JobRegistration
  {
    explicit JobRegistration(JobFactory make);
  };
} // namespace abrade::coupling

/// One line in a job's file registers it (at namespace scope).
#define ABRADE_REGISTER_JOB(Class) ABRADE_REGISTER_PLUGIN(::abrade::coupling::JobRegistration, ::abrade::coupling::Job, Class)
