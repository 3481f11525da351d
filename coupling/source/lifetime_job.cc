// The `lifetime` job: the knife's wear over its working life (lifetime/lifetime_loop.h).
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/lifetime/lifetime_loop.h>

namespace abrade::coupling
{
  void run_lifetime_job(JobContext &ctx) { lifetime::LifetimeLoop(ctx).run(); }
} // namespace abrade::coupling
