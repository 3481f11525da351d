// The job registry: what `abrade run` can do, one line per job (jobs.h).
#include <abrade/coupling/jobs.h>

namespace abrade::coupling
{
  const std::vector<JobInfo> &registered_jobs()
  {
    static const std::vector<JobInfo> jobs = {
      {"dem", "one DEM simulation of the operating cycle's phases", &run_dem_job},
      {"bed", "the settled bed alone, saved to Particles/Settling/Bed file for later runs", &run_bed_job},
      {"knife", "the knife's solid model: mesh, quality, VTU/STL, volume and mass", &run_knife_job},
      {"lifetime", "wear progression over the knife's life: DEM cycles and FEM geometry updates", &run_lifetime_job},
    };
    return jobs;
  }
} // namespace abrade::coupling
