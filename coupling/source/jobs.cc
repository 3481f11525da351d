#include <abrade/coupling/jobs.h>

namespace abrade::coupling
{
  const std::vector<JobInfo> &registered_jobs()
  {
    static const std::vector<JobInfo> jobs = {
      {"dem", "one DEM simulation of the operating cycle's phases", &run_dem_job},
    };
    return jobs;
  }
} // namespace abrade::coupling
