// The particle bed a DEM run starts from: generated, poured and settled, or loaded from a saved
// bed, or imported from another code's file (bed_preparation.h); shared by the dem and bed jobs
// and the lifetime loop's cycles.
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/dem_run/bed_preparation.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/mesh_io.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <filesystem>
#include <limits>

namespace abrade::coupling
{
  void flush_warnings(dem::Simulation &sim, io::Log &log)
  {
    for (const auto &w : sim.take_warnings())
      log.warning(w);
  }

  namespace
  {
    /// The bed's top: the highest particle's top [m].
    double bed_top(const dem::Simulation &sim) // collective
    {
      const auto &P   = sim.particles();
      double      top = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < P.size(); ++i)
        top = std::max(top, P.z[i] + P.radius[i]);
      return sim.parallel().max(top);
    }
  } // namespace

  namespace
  {
    /// A saved bed must hold the particles the parameters describe: a bed made at another
    /// radius or coarse-graining factor (the same Bed file, rerun with another Factor) would
    /// otherwise run silently with the old particles.
    void check_bed_sizes(const DemCase &c, const dem::Simulation &sim, const std::string &bed) // collective
    {
      const auto &P  = sim.particles();
      double      lo = std::numeric_limits<double>::infinity(), hi = 0;
      for (std::size_t i = 0; i < P.size(); ++i)
        lo = std::min(lo, P.radius[i]), hi = std::max(hi, P.radius[i]);
      lo = -sim.parallel().max(-lo), hi = sim.parallel().max(hi);
      const auto  &d        = c.fill.sizes;
      const bool   constant = d.kind == dem::SizeDistribution::Kind::constant;
      double       want_lo = constant ? d.radius : d.min, want_hi = constant ? d.radius : d.max;
      const bool   two     = !c.finer_levels.empty(); // multi-level: their radii too
      for (const auto &level : c.finer_levels)
        want_lo = std::min(want_lo, constant ? level.fill.sizes.radius : level.fill.sizes.min);
      const double tol = 1e-9 * want_hi;
      // a multi-level bed holds the finest level's particles (a uniform bed of the bulk's does not)
      const bool finest_missing = two && lo > c.finer_levels.front().fill.sizes.largest() + tol;
      if (lo < want_lo - tol || hi > want_hi + tol || (constant && !two && lo < want_hi - tol) || finest_missing)
        throw InputError(bed, "the bed's radii are " + io::format_number(lo) + (hi > lo ? ".." + io::format_number(hi) : std::string()) +
                                " m, the parameters give " + io::format_number(want_lo) +
                                (want_hi > want_lo ? ".." + io::format_number(want_hi) : std::string()) +
                                " m (Particles/Generation, x Particles/Coarse graining/Factor " +
                                io::format_number(c.coarse_graining) +
                                "): it was made for other particles; name another Particles/Settling/Bed file or "
                                "delete this one");
    }
  } // namespace

  namespace
  {
    /// A saved multi-level bed holds the case's counts if it was poured once, other counts if it
    /// was refilled (Fine region pours): one made by another setting (or by an abrade before the
    /// refill) is used as it is, with a warning. So is one whose finest pellets are more than 10 %
    /// off the case's count (the refill changes it by 3 %; a fine box 0.06 m wider on each side of
    /// the knife-bed's 0.72 m adds 17 %; constant sizes only, where the levels' radii are apart):
    /// a bed made with another Fine region, whose box the run's checks (fine_region_margin.h)
    /// would otherwise take for the bed's. What it finds goes to @p findings.
    void check_bed_pours(const DemCase &c, const dem::Simulation &sim, const std::string &bed,
                         std::vector<std::string> &findings)
    {
      if (c.finer_levels.empty())
        return;
      const auto &finest = c.finer_levels.front().fill;
      if (finest.sizes.kind == dem::SizeDistribution::Kind::constant) // (the sizes of two levels apart)
        {
          const double r        = finest.sizes.radius * (1 + 1e-9);
          const double expected = std::round(dem::expected_particles(finest)); // (Count, or Solid fraction)
          long         count    = 0;
          for (double radius : sim.particles().radius) // (every rank holds the whole file until setup)
            count += radius <= r ? 1 : 0;
          if (expected > 0 && std::abs(double(count) / expected - 1) > 0.1)
            findings.push_back(bed + ": its " + std::to_string(count) + " finest particles (radius " + io::format_number(finest.sizes.radius) +
                            " m) are not within 10 % of the " + io::format_number(expected, 10) +
                            " the case's fine region holds: it was made with another Particles/Coarse graining/Fine region "
                            "(delete the bed to pour it anew); the run's checks of the fine region take the case's box for the bed's");
        }
      double case_count = std::lround(dem::expected_particles(c.fill));
      for (const auto &level : c.finer_levels)
        case_count += std::lround(dem::expected_particles(level.fill));
      const double n       = double(sim.particles().size()); // (every rank holds the whole file until setup)
      const bool   refills = c.fine_region_pours > 1, refilled = n != case_count;
      if (refills != refilled)
        findings.push_back(bed + ": its " + io::format_number(n, 10) + " particles are " + (refilled ? "not " : "") +
                        "the case's " + io::format_number(case_count, 10) + ": it was poured " +
                        (refilled ? "more than once" : "once") + ", and Particles/Coarse graining/Fine region pours is " +
                        std::to_string(c.fine_region_pours) + " (delete the bed to pour it anew)");
    }
  } // namespace

  namespace
  {
    /// What one pour generated: each level's count and mean particle mass (the finest first,
    /// the bulk's last; one level without a fine region) and the mass over each level's
    /// footprint (dem::footprint_masses).
    struct Pour
    {
      std::vector<long>   counts;
      std::vector<double> mean_mass, footprint;
    };

    /// Generates the particles of @p c into @p sim, the fine region's levels first (with
    /// @p counts, each level's count instead of the case's: a second pour), and sets it up.
    Pour generate(const DemCase &c, dem::Simulation &sim, JobContext &ctx, const std::vector<long> &counts = {})
    {
      dem::FillRegion   fill = c.fill;
      dem::TriangleMesh region;
      if (!c.region_mesh_file.empty())
        {
          region      = dem::read_surface_mesh(c.region_mesh_file);
          fill.inside = &region;
        }
      for (std::size_t w = 0; w < sim.n_walls(); ++w)
        fill.avoid.push_back(sim.wall(w).current_mesh());
      Pour        pour;
      const auto &P    = sim.particles(); // (every rank generates all of them until setup)
      const auto  pour_level = [&](dem::FillRegion part) {
        const std::size_t k = pour.counts.size();
        if (k < counts.size())
          part.count = counts[k];
        const std::size_t first = P.size();
        const long        n     = dem::fill_region(sim, part);
        double            mass  = 0;
        for (std::size_t i = first; i < P.size(); ++i)
          mass += P.mass[i];
        pour.counts.push_back(n);
        pour.mean_mass.push_back(n > 0 ? mass / double(n) : 0.0);
        return n;
      };
      {
        io::ScopedTimer t(ctx.timers, "generate");
        for (const auto &level : c.finer_levels) // multi-level coarse graining: the finest first
          {
            dem::FillRegion part = level.fill;
            part.avoid           = fill.avoid;
            const long n         = pour_level(part);
            ctx.log.line("Generated " + std::to_string(n) + " particles of radius " + io::format_number(part.sizes.largest()) +
                         " m (coarse-grained by " + io::format_number(level.factor, 4) + ") in the fine region" +
                         (&level == &c.finer_levels.front() ? std::string() : "'s shell") + " (seed " +
                         std::to_string(part.seed) + ")");
          }
        const long n = pour_level(fill);
        ctx.log.line("Generated " + std::to_string(n) + " particles (seed " + std::to_string(fill.seed) + ")");
      }
      pour.footprint = dem::footprint_masses(c.finer_levels, P);
      sim.setup();
      flush_warnings(sim, ctx.log);
      return pour;
    }

    /// Lets the particles of @p sim settle (Particles/Settling).
    void settle(const DemCase &c, dem::Simulation &sim, JobContext &ctx)
    {
      {
        io::ScopedTimer  t(ctx.timers, "settle");
        io::ProgressLine progress("settling", c.settle_max_time);
        const double     t0 = sim.time();
        sim.settle(c.settle_ke, c.settle_max_time, [&](const dem::Simulation &s) {
          const double ke = s.kinetic_energy() / std::max<std::size_t>(1, s.n_particles());
          progress.update(s.time() - t0, "kinetic energy " + io::format_number(ke, 3) + " J per particle");
        });
      }
      const double ke = sim.kinetic_energy() / std::max<std::size_t>(1, sim.n_particles());
      ctx.log.line("Settled for " + io::format_number(sim.time()) + " s: kinetic energy " + io::format_number(ke) + " J per particle, top at z = " +
                   io::format_number(bed_top(sim), 4) + " m");
      if (c.settle_ke > 0 && ke > c.settle_ke)
        ctx.log.warning("the bed did not settle below " + io::format_number(c.settle_ke) +
                        " J per particle within Particles/Settling/Maximum time");
    }

    /// The mass over each level's footprint of the settled bed of @p sim, all ranks'.
    std::vector<double> settled_footprint(const DemCase &c, const dem::Simulation &sim) // collective
    {
      std::vector<double> mass = dem::footprint_masses(c.finer_levels, sim.particles());
      sim.parallel().sum(mass);
      return mass;
    }

    /// "96.7 %, 101.8 %, ...": each finer level's settled footprint mass over its poured one.
    std::string footprint_shares(const std::vector<double> &poured, const std::vector<double> &settled)
    {
      std::string out;
      for (std::size_t k = 0; k + 1 < poured.size(); ++k)
        out += (k ? ", " : "") + io::format_number(100 * settled[k] / std::max(poured[k], 1e-300), 4) + " %";
      return out;
    }

    /// Generates the particles of @p c into @p sim (the fine region first, if any) and lets
    /// them settle. A multi-level bed is poured Particles/Coarse graining/Fine region pours
    /// times: each pour but the last, in a simulation of its own, measures the mass the levels'
    /// footprints lack once settled (the finer particles spread into the coarser ones' voids),
    /// and the next is poured with each level's count refilled by it (dem::refill_counts), so
    /// that the fine region holds the mass per area the case pours over it, as the uniform bed
    /// of its particles would. The last pour is the bed.
    void generate_and_settle(const DemCase &c, dem::Simulation &sim, JobContext &ctx)
    {
      const int           pours = c.finer_levels.empty() ? 1 : c.fine_region_pours;
      std::vector<long>   counts;  // of the next pour (empty: the case's)
      std::vector<double> nominal; // the case's mass over each footprint: the first pour's
      // each pour's shares and counts in summary.json, with the bed's seed (a lifetime run makes
      // a bed per seed into the same results)
      const auto record = [&](int p, const std::vector<long> &poured, const std::vector<double> &settled) {
        io::Json pour;
        pour["seed"] = double(c.fill.seed), pour["pour"] = double(p);
        for (std::size_t k = 0; k + 1 < settled.size(); ++k)
          pour["footprint_share"].push_back(settled[k] / std::max(nominal[k], 1e-300));
        for (long n : poured)
          pour["counts"].push_back(double(n));
        ctx.results["coarse_graining"]["pours"].push_back(pour);
      };
      // a refilled count the random placement cannot hold says which pour asked for it
      const auto pour_into = [&](dem::Simulation &into, int p) {
        try
          {
            return generate(c, into, ctx, counts);
          }
        catch (const InputError &e)
          {
            if (p == 1)
              throw;
            throw InputError("Particles/Coarse graining/Fine region pours",
                             "pour " + std::to_string(p) + " of " + std::to_string(pours) + ", refilled by what the fine region " +
                               "lacked after the one before: " + e.what() + " (or pour fewer times)");
          }
      };
      for (int p = 1; p < pours; ++p)
        {
          dem::Simulation trial(c.settings);
          build_simulation(c, trial);
          ctx.log.line("Multi-level bed, pour " + std::to_string(p) + " of " + std::to_string(pours) +
                       ": what settling carries across the levels' footprints");
          const Pour pour = pour_into(trial, p);
          settle(c, trial, ctx);
          flush_warnings(trial, ctx.log);
          if (nominal.empty())
            nominal = pour.footprint;
          const std::vector<double> settled = settled_footprint(c, trial);
          record(p, pour.counts, settled);
          counts = dem::refill_counts(pour.counts, pour.mean_mass, nominal, settled);
          std::string change;
          for (std::size_t k = 0; k < counts.size(); ++k)
            change += (k ? ", " : "") + std::string(counts[k] >= pour.counts[k] ? "+" : "") +
                      std::to_string(counts[k] - pour.counts[k]);
          ctx.log.line("Multi-level bed: the levels' footprints (finest first) held " + footprint_shares(nominal, settled) +
                       " of the mass the case pours over them; poured again with what they lacked (" + change +
                       " particles per level, the bulk's last)");
        }
      const Pour pour = pour_into(sim, pours);
      settle(c, sim, ctx);
      if (c.finer_levels.empty())
        return;
      if (nominal.empty())
        nominal = pour.footprint;
      const std::vector<double> settled = settled_footprint(c, sim);
      record(pours, pour.counts, settled);
      ctx.log.line("Multi-level bed: the levels' footprints (finest first) hold " + footprint_shares(nominal, settled) +
                   " of the mass the case pours over them");
    }
  } // namespace

  bool prepare_bed(const DemCase &c, dem::Simulation &sim, JobContext &ctx, std::string bed,
                   std::vector<std::string> *provenance)
  {
    if (dem::is_imported_bed(bed)) // another code's bed, as it is (read_dem_case checked it is there)
      {
        io::ScopedTimer t(ctx.timers, "import bed");
        const auto      imported = dem::import_bed(sim, bed, c.fill.material);
        sim.setup();
        ctx.log.line("Imported the bed " + bed + " (" + imported.format +
                     (imported.timestep >= 0 ? ", timestep " + std::to_string(imported.timestep) : std::string()) +
                     "): " + std::to_string(sim.n_particles()) + " particles, top at z = " + io::format_number(bed_top(sim), 4) +
                     " m");
        return true;
      }
    if (bed.empty()) // no bed file: generated for this run alone
      {
        generate_and_settle(c, sim, ctx);
        return false;
      }
    if (std::filesystem::path(bed).is_relative())
      bed = ctx.output.shared_file(bed);
    // rank 0 writes the beds: its view decides (a rank must not look while rank 0 writes; the
    // reduction is also what makes the others wait for a bed rank 0 has just saved)
    const auto saved = [&] {
      const bool here = std::filesystem::exists(bed);
      return sim.parallel().max(sim.parallel().rank() == 0 && here ? 1.0 : 0.0) > 0;
    };
    const bool made = !saved();
    if (made)
      {
        // The bed is made in a simulation of its own and the run goes on from the file, as a
        // later run, a resumed one and every cycle of a lifetime run do: the settling leaves
        // contact histories and wall states that the file does not hold (a lifetime run killed
        // before its first update once resumed to a life of 1.4e7 t against 5.0e6 t
        // uninterrupted: its first cycle had gone on from the settled simulation)
        dem::Simulation settling(c.settings);
        build_simulation(c, settling);
        generate_and_settle(c, settling, ctx);
        flush_warnings(settling, ctx.log);
        // rank 0 writes it alone: a failed write (a full disk) is every rank's, or the others
        // would wait for rank 0 in the check below for ever
        std::exception_ptr failure;
        try
          {
            dem::save_bed(settling, bed);
          }
        catch (...)
          {
            failure = std::current_exception();
          }
        sim.parallel().fail_together(failure);
        ctx.log.line("Saved the settled bed to " + bed);
        if (!saved())
          throw RunError("the settled bed " + bed + " was saved but is not there");
      }
    {
      io::ScopedTimer t(ctx.timers, "load bed");
      dem::load_bed(sim, bed);
      check_bed_sizes(c, sim, bed);
      std::vector<std::string> findings;
      check_bed_pours(c, sim, bed, findings);
      for (auto &text : findings)
        if (provenance)
          provenance->push_back(std::move(text));
        else
          ctx.log.warning(text);
      sim.setup();
    }
    if (!made)
      ctx.log.line("Loaded settled bed " + bed + ": " + std::to_string(sim.n_particles()) + " particles, top at z = " +
                   io::format_number(bed_top(sim), 4) + " m");
    return !made;
  }

  void report_coarse_graining(const DemCase &c, JobContext &ctx)
  {
    for (const auto &n : c.notes)
      ctx.log.line(n);
    for (const auto &w : c.warnings)
      ctx.log.warning(w);
    if (c.coarse_graining == 1)
      return;
    const double r = c.fill.sizes.largest();
    ctx.log.line("Coarse graining: the particles are " + io::format_number(c.coarse_graining) + " times the real ones (largest radius " +
                 io::format_number(r) + " m for " + io::format_number(r / c.coarse_graining) + " m)");
    io::Json &j             = ctx.results["coarse_graining"];
    j["factor"]             = c.coarse_graining;
    j["largest_radius"]     = r;
    j["real_largest_radius"] = r / c.coarse_graining;
    if (c.finer_levels.empty())
      return;
    j["tool_particle_radius"] = c.tool_particle_radius; // the finest level's
    io::Json &levels          = j["levels"]; // the case's counts; "pours" has what each pour poured
    for (const auto &level : c.finer_levels)
      {
        io::Json l;
        l["factor"] = level.factor, l["largest_radius"] = level.fill.sizes.largest(), l["count"] = double(level.fill.count);
        levels.push_back(l);
      }
  }
} // namespace abrade::coupling
