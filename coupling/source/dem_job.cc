// The `dem` job: one DEM simulation of an operating cycle.
//
// 1. Read the case (materials, walls, phases) and build the simulation.
// 2. Bed: load the settled bed if a bed file exists; otherwise generate particles in the fill
//    region, pour and settle them, and save the bed for later runs.
// 3. Attach the wear laws and the contact-layer probes of the walls that ask for them.
// 4. Run the phases in order, writing ParaView snapshots (with per-triangle wear fields) and
//    wall forces at their intervals.
// 5. Write the wear and probe tables, and report throughput, loads and wear per phase in
//    summary.json.
#include <abrade/common/error.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/coupling/parameters.h>
#include <abrade/coupling/wear_profile.h>
#include <abrade/coupling/wear_tables.h>
#include <abrade/common/csv_writer.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/layer_probe.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/dem/output.h>
#include <abrade/dem/wear.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    void flush_warnings(dem::Simulation &sim, io::Log &log)
    {
      for (const auto &w : sim.take_warnings())
        log.warning(w);
    }

    std::string fmt(double v, int precision = 4)
    {
      std::ostringstream s;
      s.precision(precision);
      s << v;
      return s.str();
    }

  } // namespace

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
      const bool   two     = bool(c.fine_fill); // a fine region: its radii too
      if (two)
        want_lo = std::min(want_lo, constant ? c.fine_fill->sizes.radius : c.fine_fill->sizes.min);
      const double tol = 1e-9 * want_hi;
      if (lo < want_lo - tol || hi > want_hi + tol || (constant && !two && lo < want_hi - tol))
        throw InputError(bed, "the bed's radii are " + fmt(lo) + (hi > lo ? ".." + fmt(hi) : std::string()) +
                                " m, the parameters give " + fmt(want_lo) +
                                (want_hi > want_lo ? ".." + fmt(want_hi) : std::string()) +
                                " m (Particles/Generation, x Particles/Coarse graining/Factor " +
                                fmt(c.coarse_graining) +
                                "): it was made for other particles; name another Particles/Settling/Bed file or "
                                "delete this one");
    }
  } // namespace

  namespace
  {
    /// Generates the particles of @p c into @p sim (the fine region first, if any) and lets
    /// them settle.
    void generate_and_settle(const DemCase &c, dem::Simulation &sim, JobContext &ctx)
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
      {
        io::ScopedTimer t(ctx.timers, "generate");
        if (c.fine_fill) // multi-level coarse graining: the finer particles first, in their box
          {
            dem::FillRegion fine = *c.fine_fill;
            fine.avoid           = fill.avoid;
            const long n         = dem::fill_region(sim, fine);
            ctx.log.line("Generated " + std::to_string(n) + " particles of radius " + fmt(fine.sizes.largest()) +
                         " m in the fine region (seed " + std::to_string(fine.seed) + ")");
          }
        const long n = dem::fill_region(sim, fill);
        ctx.log.line("Generated " + std::to_string(n) + " particles (seed " + std::to_string(fill.seed) + ")");
      }
      sim.setup();
      flush_warnings(sim, ctx.log);
      {
        io::ScopedTimer  t(ctx.timers, "settle");
        io::ProgressLine progress("settling", c.settle_max_time);
        const double     t0 = sim.time();
        sim.settle(c.settle_ke, c.settle_max_time, [&](const dem::Simulation &s) {
          const double ke = s.kinetic_energy() / std::max<std::size_t>(1, s.n_particles());
          progress.update(s.time() - t0, "kinetic energy " + fmt(ke, 3) + " J per particle");
        });
      }
      const double ke = sim.kinetic_energy() / std::max<std::size_t>(1, sim.n_particles());
      ctx.log.line("Settled for " + fmt(sim.time()) + " s: kinetic energy " + fmt(ke) + " J per particle, top at z = " +
                   fmt(bed_top(sim), 4) + " m");
      if (c.settle_ke > 0 && ke > c.settle_ke)
        ctx.log.warning("the bed did not settle below " + fmt(c.settle_ke) +
                        " J per particle within Particles/Settling/Maximum time");
    }
  } // namespace

  bool prepare_bed(const DemCase &c, dem::Simulation &sim, JobContext &ctx, std::string bed)
  {
    if (dem::is_imported_bed(bed)) // another code's bed, as it is (read_dem_case checked it is there)
      {
        io::ScopedTimer t(ctx.timers, "import bed");
        const auto      imported = dem::import_bed(sim, bed, c.fill.material);
        sim.setup();
        ctx.log.line("Imported the bed " + bed + " (" + imported.format +
                     (imported.timestep >= 0 ? ", timestep " + std::to_string(imported.timestep) : std::string()) +
                     "): " + std::to_string(sim.n_particles()) + " particles, top at z = " + fmt(bed_top(sim), 4) +
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
        dem::save_bed(settling, bed);
        ctx.log.line("Saved the settled bed to " + bed);
        if (!saved())
          throw RunError("the settled bed " + bed + " was saved but is not there");
      }
    {
      io::ScopedTimer t(ctx.timers, "load bed");
      dem::load_bed(sim, bed);
      check_bed_sizes(c, sim, bed);
      sim.setup();
    }
    if (!made)
      ctx.log.line("Loaded settled bed " + bed + ": " + std::to_string(sim.n_particles()) + " particles, top at z = " +
                   fmt(bed_top(sim), 4) + " m");
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
    ctx.log.line("Coarse graining: the particles are " + fmt(c.coarse_graining) + " times the real ones (largest radius " +
                 fmt(r) + " m for " + fmt(r / c.coarse_graining) + " m)");
    io::Json &j             = ctx.results["coarse_graining"];
    j["factor"]             = c.coarse_graining;
    j["largest_radius"]     = r;
    j["real_largest_radius"] = r / c.coarse_graining;
  }

  void run_dem_job(JobContext &ctx)
  {
    DemCase c = read_dem_case(ctx.parameters);
    report_coarse_graining(c, ctx);
    fill_solid_model_walls(c, ctx.parameters, ctx.output.subdirectory("knife"), ctx.log);
    dem::Simulation sim(c.settings);
    build_simulation(c, sim);

    const bool loaded = prepare_bed(c, sim, ctx, c.bed_file);
    sim.set_time(0);
    flush_warnings(sim, ctx.log);
    ctx.log.line("Particles: " + std::to_string(sim.n_particles()) + ", time step " + fmt(sim.dt()) +
                 " s (" + fmt(sim.dt() / sim.rayleigh_time_step()) + " x Rayleigh)");

    // wear laws and contact-layer probes
    std::vector<dem::WallWearLaws> laws;
    for (const auto &wc : c.walls)
      laws.push_back(wc.wear);
    auto wear = std::make_shared<dem::WearRecorder>(sim, laws);
    sim.add_hook(wear);
    std::vector<std::shared_ptr<dem::LayerProbe>> probes;
    const double r_max = sim.largest_radius();
    for (std::size_t w = 0; w < c.walls.size(); ++w)
      if (c.walls[w].probe)
        {
          const double thickness = c.walls[w].probe_thickness > 0 ? c.walls[w].probe_thickness : 1.5 * r_max;
          probes.push_back(std::make_shared<dem::LayerProbe>(
            sim, w, thickness, c.walls[w].probe_axis, std::max(1L, std::lround(c.walls[w].probe_interval / sim.dt()))));
          sim.add_hook(probes.back());
        }

    dem::DemOutput output(ctx.output.root(), sim, c.write_particles);
    add_wear_fields(output, wear, c);
    output.write_snapshot(sim);
    const long snapshot_every = c.snapshot_interval > 0 ? std::max(1L, std::lround(c.snapshot_interval / sim.dt())) : 0;
    const long force_every    = std::max(1L, std::lround(c.force_interval / sim.dt()));

    double total = 0;
    for (const auto &p : c.phases)
      total += p.second;
    io::ProgressLine progress("dem", total);
    io::Json        &phases = ctx.results["phases"];
    std::map<std::string, std::vector<double>> path_length; // per phase and wall: how far its centroid moved [m]
    for (const auto &p : c.phases)
      path_length[p.first].assign(sim.n_walls(), 0.0);
    const auto       stats0 = sim.statistics();
    std::unique_ptr<io::CsvWriter> payload_table; // payload.csv: phase, mass above the payload height
    if (c.payload_height)
      payload_table = std::make_unique<io::CsvWriter>(ctx.output.file("payload.csv"),
                                                      std::vector<std::string>{"phase", "mass_above_payload_height"});
    for (const auto &[name, duration] : c.phases)
      {
        io::ScopedTimer   timer(ctx.timers, "phase " + name);
        const auto        before = sim.statistics();
        std::vector<dem::Vec3> force_sum(sim.n_walls(), dem::Vec3::Zero()), torque_sum = force_sum;
        std::vector<double>    peak(sim.n_walls(), 0.0), peak_torque = peak;
        // the path of each wall's centroid (the mean of its vertices: a hinge's rotation moves it)
        auto centroid = [](const dem::Wall &w) {
          dem::Vec3 c = dem::Vec3::Zero();
          for (std::size_t v = 0; v < w.current.size(); v += 3)
            c += dem::Vec3(&w.current[v]);
          return dem::Vec3(c / std::max<std::size_t>(1, w.current.size() / 3));
        };
        std::vector<dem::Vec3> centre(sim.n_walls());
        for (std::size_t w = 0; w < sim.n_walls(); ++w)
          centre[w] = centroid(sim.wall(w));
        long                   steps = 0;
        sim.run_phase(name, duration, [&](const dem::Simulation &s) {
          ++steps;
          for (std::size_t w = 0; w < s.n_walls(); ++w)
            {
              if (s.wall(w).motion.kind != dem::WallMotion::Kind::fixed)
                {
                  const dem::Vec3 now = centroid(s.wall(w));
                  path_length[name][w] += (now - centre[w]).norm();
                  centre[w] = now;
                }
              force_sum[w] += s.wall(w).force;
              peak[w] = std::max(peak[w], s.wall(w).force.norm());
              torque_sum[w] += s.wall(w).torque; // about the wall's rotation centre (a hinge)
              peak_torque[w] = std::max(peak_torque[w], s.wall(w).torque.norm());
            }
          if (s.step_number() % force_every == 0)
            output.write_forces(s);
          if (snapshot_every && s.step_number() % snapshot_every == 0)
            output.write_snapshot(s);
          progress.update(s.time(), name + "  t = " + fmt(s.time(), 3) + " s");
        });
        if (!snapshot_every)
          output.write_snapshot(sim);
        flush_warnings(sim, ctx.log);
        const auto   after = sim.statistics();
        const double rate  = sim.throughput(before, after);
        io::Json &ph          = phases[name];
        ph["duration"]        = duration;
        ph["steps"]           = steps;
        ph["particle_steps_per_second"] = rate;
        ph["particles"]       = static_cast<long>(sim.n_particles());
        // the threads that worked on the steps (fewer than the shares on a busy machine)
        const double mean_threads = sim.parallel().sum(double(after.thread_steps - before.thread_steps) /
                                                       std::max(1.0, double(after.steps - before.steps))) /
                                    sim.parallel().size();
        ph["centre_of_mass_z"] = sim.centre_of_mass_height();
        ph["threads"]      = static_cast<long>(sim.threads());
        ph["shares"]       = static_cast<long>(sim.shares());
        ph["mean_threads"] = mean_threads;
        if (c.payload_height)
          {
            const double held = sim.mass_above(*c.payload_height);
            ph["mass_above_payload_height"] = held;
            payload_table->row(name, {held});
            ctx.log.line("Phase " + name + ": " + fmt(held, 4) + " kg above the payload height");
          }
        for (std::size_t w = 0; w < sim.n_walls(); ++w)
          {
            const dem::Vec3 mean = steps ? dem::Vec3(force_sum[w] / steps) : dem::Vec3::Zero();
            io::Json       &wj   = ph["walls"][sim.wall(w).name];
            wj["mean_force"]     = std::vector<double>{mean[0], mean[1], mean[2]};
            wj["peak_force"]     = peak[w];
            const dem::Vec3 torque = steps ? dem::Vec3(torque_sum[w] / steps) : dem::Vec3::Zero();
            wj["mean_torque"]    = std::vector<double>{torque[0], torque[1], torque[2]};
            wj["peak_torque"]    = peak_torque[w];
          }
        ctx.log.line("Phase " + name + ": " + std::to_string(steps) + " steps, " + fmt(rate, 3) +
                     " particle-steps/s" +
                     (mean_threads < sim.threads() - 0.05
                        ? ", on " + fmt(mean_threads, 2) + " of " + std::to_string(sim.threads()) +
                            " threads on average: the machine was busy and fewer threads were faster"
                        : std::string()));
      }
    progress.finish();
    if (snapshot_every && sim.step_number() % snapshot_every != 0)
      output.write_snapshot(sim); // the final state, with the complete wear fields
    output.close();
    if (payload_table)
      payload_table->close();

    // wear per wall and phase: walls/NAME_wear.csv and summary.json
    ctx.results["wear_field"] = c.wear_field;
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        if (laws[w].empty())
          continue;
        write_wear_table(ctx, sim, *wear, w, c.phases, path_length);
        if (wear->tracks(w, c.wear_field))
          write_wear_profile(ctx.output.file("walls/" + sim.wall(w).name + "_wear_profile.csv"), sim.wall(w).mesh,
                             c.wear_field, wear->values(w, c.wear_field), wear->vertex_values(w, c.wear_field),
                             {c.wear_profile_band, c.wear_filter_length, sim.largest_radius()});
      }
    // contact-layer probes: walls/NAME_layer.csv, and the mean slip of the layer per phase
    for (const auto &probe : probes)
      {
        const std::string &name = sim.wall(probe->wall_index()).name;
        io::CsvWriter      csv(ctx.output.file("walls/" + name + "_layer.csv"),
                               {"phase", "time", "count", "mean_velocity", "wall_velocity", "contacts"});
        std::map<std::string, std::array<double, 4>> per_phase; // samples, sums of velocity, count, contacts
        for (const auto &smp : probe->samples())
          {
            csv.row(smp.phase, {smp.time, double(smp.count), smp.mean_velocity, smp.wall_velocity, double(smp.contacts)});
            auto &a = per_phase[smp.phase];
            a[0] += 1, a[1] += smp.mean_velocity, a[2] += smp.count, a[3] += smp.contacts;
          }
        csv.close();
        for (const auto &[phase, a] : per_phase)
          {
            io::Json &j            = ctx.results["layer"][name][phase];
            j["mean_velocity"]     = a[1] / a[0];
            j["mean_count"]        = a[2] / a[0];
            j["mean_contacts"]     = a[3] / a[0];
          }
      }
    const auto stats = sim.statistics();
    io::Json  &r     = ctx.results;
    r["particles"]   = static_cast<long>(sim.n_particles());
    r["ranks"]       = static_cast<long>(sim.parallel().size());
    r["rebalances"]  = stats.rebalances;
    r["migrated_particles"] = sim.parallel().sum(stats.migrated); // moves to another rank
    if (sim.parallel().distributed())
      {
        // communication per rank and step, for the scaling estimate (docs/benchmarks.md)
        const double steps = std::max(1.0, double(stats.steps));
        r["mean_ghosts_per_rank"]         = sim.parallel().sum(double(stats.ghost_steps)) / steps / sim.parallel().size();
        r["mean_bytes_sent_per_rank_step"] = sim.parallel().sum(sim.parallel().bytes_sent()) / steps / sim.parallel().size();
        // time in MPI calls (the waits for slower ranks included) over the time in the loop
        const double mpi = sim.parallel().seconds_in_mpi(), loop = stats.loop_seconds;
        r["mpi_share_of_loop_max"]  = sim.parallel().max(mpi / std::max(1e-12, loop));
        r["mpi_share_of_loop_mean"] = sim.parallel().sum(mpi / std::max(1e-12, loop)) / sim.parallel().size();
      }
    r["bed_loaded"]  = loaded;
    r["time_step"]   = sim.dt();
    r["steps"]       = stats.steps - stats0.steps;
    r["neighbour_rebuilds"] = stats.rebuilds;
    r["particle_steps_per_second"] = sim.throughput(stats0, stats);
  }
} // namespace abrade::coupling
