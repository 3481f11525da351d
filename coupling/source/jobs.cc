// The registry of jobs (jobs.h). The jobs themselves are in jobs/, a library of their own linked
// whole.
#include <abrade/coupling/jobs.h>

namespace abrade::coupling
{
  using Registry = io::PluginRegistry<Job>;

  JobRegistration::JobRegistration(JobFactory make) { Registry::add(make, "job"); }

  std::vector<std::unique_ptr<Job>> make_jobs() { return Registry::make_all(); }

  std::unique_ptr<Job> make_job(const std::string &name) { return Registry::make(name); }
} // namespace abrade::coupling
