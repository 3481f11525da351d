// The `lifetime` job: the knife's wear over its working life (lifetime/lifetime_loop.h).
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/lifetime/lifetime_loop.h>

namespace abrade::coupling
{
  namespace
  {
    class LifetimeJob : public Job
    {
    public:
      std::string name() const override { return "lifetime"; }
      std::string documentation() const override
      {
        return "alternate DEM cycles (on the part's solid model) and geometry updates until end of life (subsection Lifetime)";
      }
      void   run(JobContext &ctx) const override;
      Report report() const override { return {true, true, true}; }
    };
  } // namespace

  void LifetimeJob::run(JobContext &ctx) const { lifetime::LifetimeLoop(ctx).run(); }

  ABRADE_REGISTER_JOB(LifetimeJob);
} // namespace abrade::coupling
