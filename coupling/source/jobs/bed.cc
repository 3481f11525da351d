// Job 'bed': the settled bed alone. Generates, pours and settles the particles as the dem job
// does and saves them to Particles/Settling/Bed file, without running the phases (an existing
// bed file is loaded and reported instead). Studies whose runs must start from one bed (the
// benchmarks, the decomposition checks) make it first:
//
//   abrade run cases/knife_bed/knife_bed.prm --set Job=bed --set "Particles/Settling/Bed file=$PWD/bed.bed"
#include <abrade/common/error.h>
#include <abrade/coupling/dem_run/bed_preparation.h>
#include <abrade/coupling/dem_run/fine_region_margin.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/parameters/parameters.h>

namespace abrade::coupling
{
  namespace
  {
    class BedJob : public Job
    {
    public:
      std::string name() const override { return "bed"; }
      std::string documentation() const override
      {
        return "only generate and settle the bed and save it to Particles/Settling/Bed file (for studies whose runs start from one bed)";
      }
      void run(JobContext &ctx) const override;
    };
  } // namespace

  void BedJob::run(JobContext &ctx) const
  {
    DemCase c = read_dem_case(ctx.parameters);
    report_coarse_graining(c, ctx);
    if (c.bed_file.empty())
      throw InputError(ctx.parameters.file_name(), "Job = bed needs Particles/Settling/Bed file (where the bed goes)");
    fill_solid_model_walls(c, ctx.parameters, ctx.output.subdirectory(ctx.output.part_folder()), ctx.log); // the particles avoid them
    dem::Simulation sim(c.settings);
    build_simulation(c, sim);
    const bool loaded = prepare_bed(c, sim, ctx, c.bed_file);
    check_fine_region_margins(c, sim, ctx.log);
    ctx.results["particles"]  = static_cast<long>(sim.n_particles());
    ctx.results["bed_loaded"] = loaded;
    ctx.results["bed_file"]   = c.bed_file;
  }

  ABRADE_REGISTER_JOB(BedJob);
} // namespace abrade::coupling
