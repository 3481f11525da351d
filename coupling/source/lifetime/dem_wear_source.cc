// The DEM wear source: one operating cycle per bed seed on the knife's current surface.
#include <abrade/common/timer.h>
#include <abrade/coupling/bed_preparation.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/dem/wear.h>

#include <algorithm>
#include <filesystem>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class DemWearSource : public WearSource
    {
    public:
      DemWearSource(const DemCase &c, const std::vector<int> &base_seeds, double tonnes_per_cycle, JobContext &ctx)
        : c(c), base_seeds(base_seeds), tonnes_per_cycle(tonnes_per_cycle), ctx(ctx)
      {}

      CycleWear cycle(const fem::SolidSurface &surface, double, const std::vector<int> &seeds) override
      {
        io::ScopedTimer t(ctx.timers, "dem cycles");
        CycleWear       w;
        w.phase_volume.assign(c.phases.size(), 0.0);
        double payload = 0;
        for (int seed : seeds)
          payload += run_one(surface, seed, double(seeds.size()), w) / seeds.size();
        w.tonnes_per_cycle = tonnes_per_cycle;
        if (tonnes_per_cycle == 0) // a grab: the tonnes are the DEM's payload
          {
            w.tonnes_per_cycle = payload / 1000;
            if (!(w.tonnes_per_cycle > 0))
              w.stop = "no payload: nothing above Simulation/Payload height at the end of any phase";
          }
        return w;
      }

      std::vector<std::string> phases() const override
      {
        std::vector<std::string> names;
        for (const auto &p : c.phases)
          names.push_back(p.first);
        return names;
      }

      double wear_coefficient() const override { return case_wear_coefficient(c); }

    private:
      DemCase          c;
      std::vector<int> base_seeds; ///< their beds are kept (the first update's); derived ones deleted
      double           tonnes_per_cycle;
      JobContext      &ctx;

      /// One cycle of bed @p seed (one of @p beds), its knife wear appended to @p w; returns the
      /// payload [kg].
      double run_one(const fem::SolidSurface &surface, int seed, double beds, CycleWear &w)
      {
        DemCase run = c;
        run.fill.seed = static_cast<std::uint64_t>(seed);
        std::vector<std::size_t> knives; // a grab carries two: averaged as two more replicates
        for (std::size_t k = 0; k < run.walls.size(); ++k)
          if (run.walls[k].solid_model)
            {
              run.walls[k].wall.mesh = place_surface(surface, run.walls[k]);
              knives.push_back(k);
            }
        // the case's fault policy (Simulation/On error) holds in every cycle: stop ends the run
        // (exit 3, the last checkpoint kept), continue goes on and the warnings are counted
        dem::Simulation sim(run.settings);
        build_simulation(run, sim);
        io::Log    quiet; // the bed's lines stay out of the loop's log; its warnings do not
        quiet.set_echo(false);
        JobContext cycle_ctx{ctx.parameters, ctx.output, ctx.results, ctx.timers, quiet, false};
        const std::string bed = "beds/bed-seed" + std::to_string(seed) + ".bed";
        prepare_bed(run, sim, cycle_ctx, bed);
        sim.set_time(0);
        std::vector<dem::WallWearLaws> laws;
        for (const auto &wc : run.walls)
          laws.push_back(wc.wear);
        auto wear = std::make_shared<dem::WearRecorder>(sim, laws);
        sim.add_hook(wear);
        double payload = 0;
        for (const auto &[name, duration] : run.phases)
          {
            sim.run_phase(name, duration);
            if (run.payload_height)
              payload = std::max(payload, sim.mass_above(*run.payload_height));
          }
        w.particle_radius = sim.largest_radius();
        for (const auto &text : quiet.take_warnings()) // the bed's (generation, settling)
          w.warnings.push_back("seed " + std::to_string(seed) + ": " + text);
        for (const auto &text : sim.take_warnings()) // the cycle's
          w.warnings.push_back("seed " + std::to_string(seed) + ": " + text);
        std::vector<double> volume(surface.vertices.size(), 0.0);
        for (std::size_t k : knives)
          {
            const auto v = wear->vertex_values(k, run.wear_field);
            for (std::size_t i = 0; i < v.size(); ++i)
              volume[i] += v[i] / knives.size();
            for (std::size_t p = 0; p < run.phases.size(); ++p)
              w.phase_volume[p] += wear->total(k, run.wear_field, run.phases[p].first) /
                                   (knives.size() * beds);
          }
        w.seed_volume.push_back(std::move(volume));
        // a derived seed's bed serves this cycle only (the next update draws fresh ones; a
        // resumed run settles it again, to the same bits): rank 0 wrote it, rank 0 removes it
        // after every rank has run the cycle from it
        if (std::find(base_seeds.begin(), base_seeds.end(), seed) == base_seeds.end() && sim.parallel().rank() == 0)
          std::filesystem::remove(ctx.output.shared_file(bed));
        return payload;
      }
    };
  } // namespace

  double case_wear_coefficient(const DemCase &c)
  {
    for (const auto &wc : c.walls)
      if (wc.solid_model)
        if (const dem::WearLaw *law = dem::law_recording(wc.wear, c.wear_field))
          return law->coefficient();
    return 0;
  }

  std::unique_ptr<WearSource> make_dem_wear_source(const DemCase &c, const std::vector<int> &base_seeds,
                                                   double tonnes_per_cycle, JobContext &ctx)
  {
    return std::make_unique<DemWearSource>(c, base_seeds, tonnes_per_cycle, ctx);
  }
} // namespace abrade::coupling::lifetime
