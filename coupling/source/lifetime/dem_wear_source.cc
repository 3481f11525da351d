// The DEM wear source: one operating cycle per bed seed on the part's current surface; under
// mpirun the beds run side by side on groups of the ranks (Lifetime/DEM/Ranks per bed).
#include <abrade/common/timer.h>
#include <abrade/coupling/dem_run/bed_preparation.h>
#include <abrade/coupling/dem_run/fine_region_margin.h>
#include <abrade/coupling/dem_run/seed_bed_file.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/dem/coarse_graining.h>
#include <abrade/dem/ensemble.h>
#include <abrade/dem/thread_governor.h>
#include <abrade/dem/wear.h>

#include <algorithm>
#include <exception>
#include <filesystem>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class DemWearSource : public WearSource
    {
    public:
      DemWearSource(const DemCase &c, const std::vector<int> &base_seeds, double tonnes_per_cycle, int ranks_per_bed,
                    JobContext &ctx)
        : c(c), base_seeds(base_seeds), tonnes_per_cycle(tonnes_per_cycle), ranks_per_bed(ranks_per_bed), ctx(ctx)
      {}

      // The beds run side by side on groups of the ranks (dem/ensemble.h), each group its
      // share; then every rank has every bed's wear, and adds them up in the order of the beds,
      // as one process running them one after another would.
      CycleWear cycle(const fem::SolidSurface &surface, double, const std::vector<int> &seeds) override
      {
        io::ScopedTimer       t(ctx.timers, "dem cycles");
        const dem::Ensemble   ensemble(dem::Parallel::world(), seeds.size(), ranks_per_bed);
        std::vector<BedWear>  beds(seeds.size());
        std::exception_ptr    failure;
        announce(ensemble);
        for (std::size_t b = 0; b < seeds.size() && !failure; ++b)
          if (ensemble.runs(b))
            try
              {
                beds[b] = run_one(surface, seeds[b], ensemble.group());
              }
            catch (...)
              {
                failure = std::current_exception();
              }
        ensemble.fail_together(failure);
        for (std::size_t b = 0; b < seeds.size(); ++b)
          beds[b].share(ensemble, b);

        CycleWear w;
        w.phase_volume.assign(c.phases.size(), 0.0);
        double payload = 0;
        for (std::size_t b = 0; b < seeds.size(); ++b)
          {
            payload += beds[b].payload / seeds.size();
            const std::size_t knives = beds[b].part_phase_volume.size() / std::max<std::size_t>(1, c.phases.size());
            for (std::size_t k = 0; k < knives; ++k)
              for (std::size_t p = 0; p < c.phases.size(); ++p)
                w.phase_volume[p] += beds[b].part_phase_volume[k * c.phases.size() + p] / (knives * seeds.size());
            w.particle_radius = beds[b].particle_radius;
            // (every rank has every bed's warnings and notes here: rank 0 logs the other groups')
            for (const auto &text : beds[b].warnings)
              w.warnings.push_back("seed " + std::to_string(seeds[b]) + ": " + text);
            for (const auto &text : beds[b].notes)
              w.notes.push_back("seed " + std::to_string(seeds[b]) + ": " + text);
            w.seed_volume.push_back(std::move(beds[b].volume));
          }
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
      int              ranks_per_bed; ///< Lifetime/DEM/Ranks per bed (0: the ranks shared out among the beds)
      bool             announced = false;
      std::shared_ptr<dem::ThreadGovernor> governor; ///< the first cycle's, carried on
      bool fine_region_logged = false; ///< a multi-level bed's margins: logged for the first bed made here
      JobContext      &ctx;

      /// One bed's cycle: what the cycle's wear is added up from.
      struct BedWear
      {
        std::vector<double>      volume; ///< wear volume per surface vertex, the knives' mean [m^3]
        /// per knife wall, per phase: its total wear volume [m^3]
        std::vector<double>      part_phase_volume;
        double                   payload         = 0; ///< [kg]
        double                   particle_radius = 0; ///< the largest [m]
        std::vector<std::string> warnings; ///< the cycle's faults (its bed's making, its run)
        /// a loaded bed that another setting made (prepare_bed's provenance): the run's set-up
        std::vector<std::string> notes;

        /// As the group that ran bed @p b holds it, on every rank.
        void share(const dem::Ensemble &ensemble, std::size_t b)
        {
          if (ensemble.groups() == 1)
            return;
          std::vector<double> numbers = part_phase_volume;
          numbers.insert(numbers.end(), {payload, particle_radius});
          ensemble.share(numbers, b);
          particle_radius = numbers.back(), numbers.pop_back();
          payload = numbers.back(), numbers.pop_back();
          part_phase_volume = std::move(numbers);
          ensemble.share(volume, b);
          share_lines(ensemble, b, warnings);
          share_lines(ensemble, b, notes);
        }

        /// @p lines as bed @p b's group holds them, on every rank.
        static void share_lines(const dem::Ensemble &ensemble, std::size_t b, std::vector<std::string> &lines)
        {
          std::string text;
          for (const auto &line : lines)
            text += line + '\x1e'; // (a record separator: a warning may hold a line break)
          ensemble.share(text, b);
          lines.clear();
          for (std::size_t at = 0, end; (end = text.find('\x1e', at)) != std::string::npos; at = end + 1)
            lines.push_back(text.substr(at, end - at));
        }
      };

      /// The log's line on the first cycle whose beds run side by side.
      void announce(const dem::Ensemble &ensemble)
      {
        if (ensemble.groups() == 1 || announced)
          return;
        announced        = true;
        const int fewest = ensemble.smallest_group(), most = ensemble.largest_group();
        ctx.log.line("beds side by side on " + std::to_string(ensemble.groups()) + " groups of ranks (" +
                     (fewest == most ? std::to_string(most) : std::to_string(fewest) + " or " + std::to_string(most)) +
                     " rank(s) each; Lifetime/DEM/Ranks per bed)");
      }

      /// One cycle of bed @p seed on the ranks of @p group.
      BedWear run_one(const fem::SolidSurface &surface, int seed, const dem::Parallel &group)
      {
        DemCase run = c;
        dem::reseed(run.fill, run.finer_levels, static_cast<std::uint64_t>(seed)); // (a fine region's levels too)
        run.settings.ranks = group;
        std::vector<std::size_t> knives; // a grab carries two: averaged as two more replicates
        for (std::size_t k = 0; k < run.walls.size(); ++k)
          if (run.walls[k].solid_model)
            {
              run.walls[k].wall.mesh = place_surface(surface, run.walls[k]);
              knives.push_back(k);
            }
        // the case's fault policy (Simulation/On error) holds in every cycle: stop ends the run
        // (exit 3, the last checkpoint kept), continue goes on and the warnings are counted
        // one governor of the threads for every simulation of the run (the beds' settling and
        // their cycles, update after update): a cycle on a busy machine starts with the team the
        // ones before found fastest instead of finding it again
        run.settings.governor = governor;
        dem::Simulation sim(run.settings);
        run.settings.governor = governor = sim.thread_governor();
        build_simulation(run, sim);
        io::Log    quiet; // the bed's lines stay out of the loop's log; its warnings do not
        quiet.set_echo(false);
        JobContext cycle_ctx{ctx.parameters, ctx.output, ctx.results, ctx.timers, quiet, false};
        const std::string bed = seed_bed_file(seed);
        BedWear           w;
        // a multi-level bed's fine box against the paths, for every bed made (collective over
        // the bed's group, whose ranks all made it: a per-process choice of whether to check
        // could split a later update's regrouped ranks), logged for the first in the loop's log
        // (not a fault of a cycle: not among the DEM's warnings)
        if (!prepare_bed(run, sim, cycle_ctx, bed, &w.notes))
          {
            io::Log unlogged; // (neither the loop's log nor the cycle's warnings)
            unlogged.set_echo(false);
            check_fine_region_margins(run, sim, fine_region_logged ? unlogged : ctx.log);
            fine_region_logged = true;
          }
        governor->carry_on(); // (after the settling's steps: the cycle's are measured afresh)
        sim.set_time(0);
        std::vector<dem::WallWearLaws> laws;
        for (const auto &wc : run.walls)
          laws.push_back(wc.wear);
        auto wear = std::make_shared<dem::WearRecorder>(sim, laws);
        sim.add_hook(wear);
        for (const auto &[name, duration] : run.phases)
          {
            sim.run_phase(name, duration);
            if (run.payload_height)
              w.payload = std::max(w.payload, sim.mass_above(*run.payload_height));
          }
        w.particle_radius = run.particle_radius_at_tools(sim); // (the filter follows it)
        w.warnings        = quiet.take_warnings(); // the bed's (generation, settling)
        for (const auto &text : sim.take_warnings()) // the cycle's
          w.warnings.push_back(text);
        w.volume.assign(surface.vertices.size(), 0.0);
        for (std::size_t k : knives)
          {
            const auto v = wear->vertex_values(k, run.wear_field);
            for (std::size_t i = 0; i < v.size(); ++i)
              w.volume[i] += v[i] / knives.size();
            for (std::size_t p = 0; p < run.phases.size(); ++p)
              w.part_phase_volume.push_back(wear->total(k, run.wear_field, run.phases[p].first));
          }
        // a derived seed's bed serves this cycle only (the next update draws fresh ones; a
        // resumed run settles it again, to the same bits): rank 0 wrote it, rank 0 removes it
        // after every rank has run the cycle from it
        if (std::find(base_seeds.begin(), base_seeds.end(), seed) == base_seeds.end() && sim.parallel().rank() == 0)
          std::filesystem::remove(ctx.output.shared_file(bed));
        return w;
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
                                                   double tonnes_per_cycle, int ranks_per_bed, JobContext &ctx)
  {
    return std::make_unique<DemWearSource>(c, base_seeds, tonnes_per_cycle, ranks_per_bed, ctx);
  }
} // namespace abrade::coupling::lifetime
