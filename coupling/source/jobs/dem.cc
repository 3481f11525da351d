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
#include <abrade/common/format_number.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/dem_run/bed_preparation.h>
#include <abrade/coupling/dem_run/fine_region_margin.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/coupling/dem_run/wear_profile.h>
#include <abrade/coupling/dem_run/wear_tables.h>
#include <abrade/common/csv_writer.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/layer_probe.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/dem/output.h>
#include <abrade/dem/wear.h>

#include <algorithm>
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
    class DemJob : public Job
    {
    public:
      std::string name() const override { return "dem"; }
      std::string documentation() const override
      {
        return "one DEM simulation of the phases in Simulation/Phases (generate or load the bed, run, write output)";
      }
      void run(JobContext &ctx) const override;
    };

    /// What the grab's mechanism did in phase @p name: summary.json's phases/NAME/grab and a
    /// line of the log.
    void report_mechanism(const dem::RopeGrabDriver &mechanism, const std::string &name, io::Json &phase, io::Log &log)
    {
      const auto it = std::find_if(mechanism.phases().rbegin(), mechanism.phases().rend(),
                                   [&](const auto &r) { return r.first == name; });
      if (it == mechanism.phases().rend())
        return;
      const auto  &r     = it->second;
      const double steps = std::max<long>(1, r.steps);
      io::Json    &g     = phase["grab"];
      g["hinge_height_start"]    = r.hinge_start;
      g["hinge_height_end"]      = r.hinge_end;
      g["hinge_height_lowest"]   = r.lowest_hinge;
      g["hinge_height_highest"]  = r.highest_hinge;
      g["shell_angle_start"]     = r.angle_start * 180 / M_PI;
      g["shell_angle_end"]       = r.angle_end * 180 / M_PI;
      g["head_distance_end"]     = r.head_distance_end;
      g["closing_rope_tension_mean"] = r.closing_tension_sum / steps;
      g["closing_rope_tension_peak"] = r.closing_tension_max;
      g["holding_rope_tension_mean"] = r.holding_tension_sum / steps;
      g["holding_rope_tension_peak"] = r.holding_tension_max;
      g["closing_rope_hauled"]   = r.closing_hauled;
      g["holding_rope_hauled"]   = r.holding_hauled;
      g["closed_fraction_of_steps"] = double(r.steps_at_closed_stop) / steps;
      if (!std::isnan(r.hinge_when_closed)) // (the lips closed in this phase)
        g["hinge_height_when_closed"] = r.hinge_when_closed;
      g["trolley_position_start"] = r.trolley_start;
      g["trolley_position_end"]   = r.trolley_end;
      log.line("Phase " + name + ": hinge " + io::format_number(r.hinge_start, 3) + " -> " +
               io::format_number(r.hinge_end, 3) + " m (lowest " + io::format_number(r.lowest_hinge, 3) +
               " m), shells " + io::format_number(r.angle_start * 180 / M_PI, 3) + " -> " +
               io::format_number(r.angle_end * 180 / M_PI, 3) + " deg, closing rope " +
               io::format_number(r.closing_tension_sum / steps / 1e3, 3) + " kN mean (peak " +
               io::format_number(r.closing_tension_max / 1e3, 3) + "), holding ropes " +
               io::format_number(r.holding_tension_sum / steps / 1e3, 3) + " kN mean");
    }

    /// The forces and torques on the walls over a phase, and how far the moving ones went.
    struct PhaseLoads
    {
      explicit PhaseLoads(const dem::Simulation &sim);
      /// After a step: the walls' loads summed and their peaks, the moving walls' paths.
      void add(const dem::Simulation &sim, std::vector<double> &path_length);

      long                   steps = 0;
      std::vector<dem::Vec3> force_sum, torque_sum;
      std::vector<double>    peak, peak_torque;
      std::vector<dem::Vec3> centre; ///< each wall's centroid at the last step
    };

    /// The centroid of a wall's vertices (a hinge's rotation moves it).
    dem::Vec3 centroid(const dem::Wall &w)
    {
      dem::Vec3 c = dem::Vec3::Zero();
      for (std::size_t v = 0; v < w.current.size(); v += 3)
        c += dem::Vec3(&w.current[v]);
      return dem::Vec3(c / std::max<std::size_t>(1, w.current.size() / 3));
    }

    PhaseLoads::PhaseLoads(const dem::Simulation &sim)
      : force_sum(sim.n_walls(), dem::Vec3::Zero()), torque_sum(force_sum), peak(sim.n_walls(), 0.0),
        peak_torque(peak), centre(sim.n_walls())
    {
      for (std::size_t w = 0; w < sim.n_walls(); ++w)
        centre[w] = centroid(sim.wall(w));
    }

    void PhaseLoads::add(const dem::Simulation &s, std::vector<double> &path_length)
    {
      ++steps;
      for (std::size_t w = 0; w < s.n_walls(); ++w)
        {
          if (s.wall(w).motion.kind != dem::WallMotion::Kind::fixed)
            {
              const dem::Vec3 now = centroid(s.wall(w));
              path_length[w] += (now - centre[w]).norm();
              centre[w] = now;
            }
          force_sum[w] += s.wall(w).force;
          peak[w] = std::max(peak[w], s.wall(w).force.norm());
          torque_sum[w] += s.wall(w).torque; // about the wall's rotation centre (a hinge)
          peak_torque[w] = std::max(peak_torque[w], s.wall(w).torque.norm());
        }
    }

    /// One DEM run of the case's phases: the dem job's work, in the order of run().
    class DemRun
    {
    public:
      explicit DemRun(JobContext &ctx) : ctx(ctx) {}

      void run()
      {
        set_up();
        attach_recorders();
        open_outputs();
        for (const auto &[name, duration] : c.phases)
          run_phase(name, duration);
        close_outputs();
        write_wear();
        write_layer_probes();
        write_statistics();
      }

    private:
      /// The case read, the simulation built with its walls (and a grab's mechanism), the bed.
      void set_up();
      /// The wear laws and the contact-layer probes of the walls that ask for them.
      void attach_recorders();
      /// Snapshots with the wear fields, the force files, the mechanism's and the payload's
      /// tables, the progress line.
      void open_outputs();
      /// One phase: its steps with their outputs, then its summary (PhaseLoads, report_phase).
      void run_phase(const std::string &name, double duration);
      /// After every step of phase @p name: the force files, the mechanism's row, a snapshot.
      void write_step(const std::string &name, const dem::Simulation &s);
      /// summary.json's phases/NAME and the phase's log lines.
      void report_phase(const std::string &name, double duration, const PhaseLoads &loads,
                        const dem::StepStatistics &before);
      void close_outputs();
      /// walls/NAME_wear.csv and NAME_wear_profile.csv, and the wear in summary.json.
      void write_wear();
      /// walls/NAME_layer.csv, and the layer's mean slip per phase in summary.json.
      void write_layer_probes();
      /// The run's particles, ranks, steps, communication and throughput in summary.json.
      void write_statistics();

      JobContext                                   &ctx;
      DemCase                                       c;
      std::unique_ptr<dem::Simulation>              sim;
      std::shared_ptr<dem::RopeGrabDriver>          mechanism;
      bool                                          loaded = false;
      std::vector<dem::WallWearLaws>                laws;
      std::shared_ptr<dem::WearRecorder>            wear;
      std::vector<std::shared_ptr<dem::LayerProbe>> probes;
      std::unique_ptr<dem::DemOutput>               output;
      long                                          snapshot_every = 0, force_every = 1;
      std::unique_ptr<io::ProgressLine>             progress;
      std::map<std::string, std::vector<double>>    path_length; // per phase and wall: how far its centroid moved [m]
      dem::StepStatistics                           stats0;
      std::unique_ptr<io::CsvWriter>                mechanism_table; // grab_mechanism.csv: the mechanism over time
      std::unique_ptr<io::CsvWriter>                payload_table;   // payload.csv: phase, mass above the payload height
    };
  } // namespace

  void DemJob::run(JobContext &ctx) const { DemRun(ctx).run(); }

  void DemRun::set_up()
  {
    c = read_dem_case(ctx.parameters);
    report_coarse_graining(c, ctx);
    fill_solid_model_walls(c, ctx.parameters, ctx.output.subdirectory(ctx.output.part_folder()), ctx.log);
    sim       = std::make_unique<dem::Simulation>(c.settings);
    mechanism = build_simulation(c, *sim);

    loaded = prepare_bed(c, *sim, ctx, c.bed_file);
    check_fine_region_margins(c, *sim, ctx.log);
    sim->set_time(0);
    flush_warnings(*sim, ctx.log);
    ctx.log.line("Particles: " + std::to_string(sim->n_particles()) + ", time step " + io::format_number(sim->dt()) +
                 " s (" + io::format_number(sim->dt() / sim->rayleigh_time_step()) + " x Rayleigh)");
  }

  void DemRun::attach_recorders()
  {
    for (const auto &wc : c.walls)
      laws.push_back(wc.wear);
    wear = std::make_shared<dem::WearRecorder>(*sim, laws);
    sim->add_hook(wear);
    const double r_max = c.particle_radius_at_tools(*sim); // (a multi-level bed: the finest)
    for (std::size_t w = 0; w < c.walls.size(); ++w)
      if (c.walls[w].probe)
        {
          const double thickness = c.walls[w].probe_thickness > 0 ? c.walls[w].probe_thickness : 1.5 * r_max;
          probes.push_back(std::make_shared<dem::LayerProbe>(
            *sim, w, thickness, c.walls[w].probe_axis, std::max(1L, std::lround(c.walls[w].probe_interval / sim->dt()))));
          sim->add_hook(probes.back());
        }
  }

  void DemRun::open_outputs()
  {
    output = std::make_unique<dem::DemOutput>(ctx.output.root(), *sim, c.write_particles);
    add_wear_fields(*output, wear, c);
    output->write_snapshot(*sim);
    snapshot_every = c.snapshot_interval > 0 ? std::max(1L, std::lround(c.snapshot_interval / sim->dt())) : 0;
    force_every    = std::max(1L, std::lround(c.force_interval / sim->dt()));

    double total = 0;
    for (const auto &p : c.phases)
      total += p.second;
    progress = std::make_unique<io::ProgressLine>("dem", total);
    ctx.results["phases"]; // (first among the results)
    for (const auto &p : c.phases)
      path_length[p.first].assign(sim->n_walls(), 0.0);
    stats0 = sim->statistics();
    if (mechanism)
      mechanism_table = std::make_unique<io::CsvWriter>(
        ctx.output.file("grab_mechanism.csv"),
        std::vector<std::string>{"phase", "time", "hinge_height", "shell_angle", "head_distance", "hinge_velocity",
                                 "closing_rope_tension", "holding_rope_tension", "trolley_position"});
    if (c.payload_height)
      payload_table = std::make_unique<io::CsvWriter>(ctx.output.file("payload.csv"),
                                                      std::vector<std::string>{"phase", "mass_above_payload_height"});
  }

  void DemRun::run_phase(const std::string &name, double duration)
  {
    io::ScopedTimer timer(ctx.timers, "phase " + name);
    const auto      before = sim->statistics();
    PhaseLoads      loads(*sim);
    sim->run_phase(name, duration, [&](const dem::Simulation &s) {
      loads.add(s, path_length[name]);
      write_step(name, s);
    });
    if (!snapshot_every)
      output->write_snapshot(*sim);
    flush_warnings(*sim, ctx.log);
    report_phase(name, duration, loads, before);
  }

  void DemRun::write_step(const std::string &name, const dem::Simulation &s)
  {
    if (s.step_number() % force_every == 0)
      {
        output->write_forces(s);
        if (mechanism_table)
          {
            const auto &m = *mechanism;
            const auto &q = m.state();
            mechanism_table->row(name, {s.time(), q.z, q.angle * 180 / M_PI, m.mechanism().head_distance(q.angle),
                                        q.z_rate, m.mechanism().closing_tension(q, m.closing_winch(name)),
                                        m.mechanism().holding_tension(q, m.holding_winch(name)),
                                        m.trolley_position()});
          }
      }
    if (snapshot_every && s.step_number() % snapshot_every == 0)
      output->write_snapshot(s);
    progress->update(s.time(), name + "  t = " + io::format_number(s.time(), 3) + " s");
  }

  void DemRun::report_phase(const std::string &name, double duration, const PhaseLoads &loads,
                            const dem::StepStatistics &before)
  {
    const long   steps = loads.steps;
    const auto   after = sim->statistics();
    const double rate  = sim->throughput(before, after);
    io::Json &ph          = ctx.results["phases"][name];
    ph["duration"]        = duration;
    ph["steps"]           = steps;
    ph["particle_steps_per_second"] = rate;
    ph["particles"]       = static_cast<long>(sim->n_particles());
    // the threads that worked on the steps (fewer than the shares on a busy machine)
    const double mean_threads = sim->parallel().sum(double(after.thread_steps - before.thread_steps) /
                                                    std::max(1.0, double(after.steps - before.steps))) /
                                sim->parallel().size();
    ph["centre_of_mass_z"] = sim->centre_of_mass_height();
    ph["threads"]      = static_cast<long>(sim->threads());
    ph["shares"]       = static_cast<long>(sim->shares());
    ph["mean_threads"] = mean_threads;
    if (mechanism)
      report_mechanism(*mechanism, name, ph, ctx.log);
    if (c.payload_height)
      {
        const double held = sim->mass_above(*c.payload_height);
        ph["mass_above_payload_height"] = held;
        payload_table->row(name, {held});
        ctx.log.line("Phase " + name + ": " + io::format_number(held, 4) + " kg above the payload height");
      }
    for (std::size_t w = 0; w < sim->n_walls(); ++w)
      {
        const dem::Vec3 mean = steps ? dem::Vec3(loads.force_sum[w] / steps) : dem::Vec3::Zero();
        io::Json       &wj   = ph["walls"][sim->wall(w).name];
        wj["mean_force"]     = std::vector<double>{mean[0], mean[1], mean[2]};
        wj["peak_force"]     = loads.peak[w];
        const dem::Vec3 torque = steps ? dem::Vec3(loads.torque_sum[w] / steps) : dem::Vec3::Zero();
        wj["mean_torque"]    = std::vector<double>{torque[0], torque[1], torque[2]};
        wj["peak_torque"]    = loads.peak_torque[w];
      }
    ctx.log.line("Phase " + name + ": " + std::to_string(steps) + " steps, " + io::format_number(rate, 3) +
                 " particle-steps/s" +
                 (mean_threads < sim->threads() - 0.05
                    ? ", on " + io::format_number(mean_threads, 2) + " of " + std::to_string(sim->threads()) +
                        " threads on average: the machine was busy and fewer threads were faster"
                    : std::string()));
  }

  void DemRun::close_outputs()
  {
    progress->finish();
    if (snapshot_every && sim->step_number() % snapshot_every != 0)
      output->write_snapshot(*sim); // the final state, with the complete wear fields
    output->close();
    if (payload_table)
      payload_table->close();
    if (mechanism_table)
      mechanism_table->close();
  }

  void DemRun::write_wear()
  {
    ctx.results["wear_field"] = c.wear_field;
    for (std::size_t w = 0; w < sim->n_walls(); ++w)
      {
        if (laws[w].empty())
          continue;
        write_wear_table(ctx, *sim, *wear, w, c.phases, path_length);
        if (wear->tracks(w, c.wear_field))
          {
            std::vector<WearVolumes> volumes{{"", wear->values(w, c.wear_field), wear->vertex_values(w, c.wear_field)}};
            for (const auto &[phase, duration] : c.phases)
              volumes.push_back({phase, wear->values(w, c.wear_field, phase), wear->vertex_values(w, c.wear_field, phase)});
            write_wear_profile(ctx.output.file("walls/" + sim->wall(w).name + "_wear_profile.csv"), sim->wall(w).mesh,
                               c.wear_field, volumes, {c.wear_profile_band, c.wear_filter_length, c.particle_radius_at_tools(*sim)});
          }
      }
  }

  void DemRun::write_layer_probes()
  {
    for (const auto &probe : probes)
      {
        const std::string &name = sim->wall(probe->wall_index()).name;
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
  }

  void DemRun::write_statistics()
  {
    const auto stats = sim->statistics();
    io::Json  &r     = ctx.results;
    r["particles"]   = static_cast<long>(sim->n_particles());
    r["ranks"]       = static_cast<long>(sim->parallel().size());
    r["rebalances"]  = stats.rebalances;
    r["migrated_particles"] = sim->parallel().sum(stats.migrated); // moves to another rank
    if (sim->parallel().distributed())
      {
        // communication per rank and step, for the scaling estimate (docs/benchmarks.md)
        const double steps = std::max(1.0, double(stats.steps));
        r["mean_ghosts_per_rank"]         = sim->parallel().sum(double(stats.ghost_steps)) / steps / sim->parallel().size();
        r["mean_bytes_sent_per_rank_step"] = sim->parallel().sum(sim->parallel().bytes_sent()) / steps / sim->parallel().size();
        // time in MPI calls (the waits for slower ranks included) over the time in the loop
        const double mpi = sim->parallel().seconds_in_mpi(), loop = stats.loop_seconds;
        r["mpi_share_of_loop_max"]  = sim->parallel().max(mpi / std::max(1e-12, loop));
        r["mpi_share_of_loop_mean"] = sim->parallel().sum(mpi / std::max(1e-12, loop)) / sim->parallel().size();
      }
    r["bed_loaded"]  = loaded;
    r["time_step"]   = sim->dt();
    r["steps"]       = stats.steps - stats0.steps;
    r["neighbour_rebuilds"] = stats.rebuilds;
    r["particle_steps_per_second"] = sim->throughput(stats0, stats);
  }

  ABRADE_REGISTER_JOB(DemJob);
} // namespace abrade::coupling
