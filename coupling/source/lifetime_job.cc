// The `lifetime` job: a knife's wear over its working life, by alternating DEM cycles and FEM
// geometry updates (shared/reference/design-notes.md).
//
// Every update:
//  1. DEM: one operating cycle per bed seed on the knife's current surface (each cycle restarts
//     from that seed's saved bed, so cycles are comparable); the per-triangle Archard volume of
//     the knife, averaged over the seeds, is the wear of one cycle.
//  2. Filter and map: each triangle's volume goes to its vertices (a third each), is smoothed
//     over the surface with a Gaussian of the particle scale (volume conserving: every vertex's
//     volume is spread with weights that sum to one) and divided by the vertex's area (a third
//     of its triangles'): the depth per cycle, along the inward normal.
//  3. Cycles per update: fixed, or adaptive so that the largest depth increment is a set
//     fraction of the mesh size.
//  4. FEM: move the knife (KnifeModel: the surface moves as its offset surface does, so the
//     swept volume is the Archard volume, also at the edge; mesh motion, quality, remesh,
//     worn-through check). The ratio swept / Archard volume is recorded as a check.
//     Wear on the border of the clamped region is lost (clamped vertices do not move).
//     Nothing is rescaled: a mismatch shows in the column swept_over_archard.
//  5. Record the trajectory; stop at the maximum depth, a worn-through knife, the target tonnes
//     or the maximum number of updates.
//  6. Checkpoint (the knife's exact mesh and fields, the loop's state) after every update;
//     `abrade run ... --resume` continues from the last one (under mpirun: the newest that all
//     ranks completed, lifetime_checkpoints.h), and, since every cycle restarts from a saved
//     bed, produces the same trajectory as an uninterrupted run.
#include <abrade/common/csv_writer.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/hash.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/coupling/lifetime_checkpoints.h>
#include <abrade/coupling/parameters.h>
#include <abrade/dem/parallel.h>
#include <abrade/dem/wear.h>
#include <abrade/fem/knife_model.h>

#include <deal.II/base/function_parser.h>
#include <deal.II/base/utilities.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <filesystem>
#include <numeric>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    /// What one DEM cycle gives the loop.
    struct CycleResult
    {
      std::vector<double> per_triangle; ///< Archard volume per knife triangle, mean of the knife walls
      std::vector<double> per_phase;    ///< the same, summed over the knife, per phase
      double              r_max   = 0;  ///< largest particle radius
      double              payload = 0;  ///< [kg] most mass above the payload height at a phase's end
    };

    /// One DEM cycle on the current knife surface, placed on every knife wall (a grab carries
    /// two: their wear is averaged, triangle by triangle, as two more replicates).
    CycleResult run_cycle(DemCase c, const fem::SolidSurface &surface, int seed, JobContext &ctx)
    {
      c.fill.seed = static_cast<std::uint64_t>(seed);
      std::vector<std::size_t> knives;
      for (std::size_t w = 0; w < c.walls.size(); ++w)
        if (c.walls[w].solid_model)
          {
            c.walls[w].wall.mesh = place_surface(surface, c.walls[w]);
            knives.push_back(w);
          }
      c.settings.stop_on_error = false; // a cycle reports overlaps and lost particles, and goes on
      dem::Simulation sim(c.settings);
      build_simulation(c, sim);
      io::Log quiet;
      JobContext cycle_ctx{ctx.parameters, ctx.output, ctx.results, ctx.timers, quiet, false};
      prepare_bed(c, sim, cycle_ctx, "beds/bed-seed" + std::to_string(seed) + ".bed");
      sim.set_time(0);
      std::vector<dem::WearLaws> laws;
      for (const auto &wc : c.walls)
        laws.push_back(wc.wear);
      auto wear = std::make_shared<dem::WearRecorder>(sim, laws);
      sim.add_hook(wear);
      CycleResult r;
      for (const auto &[name, duration] : c.phases)
        {
          sim.run_phase(name, duration);
          if (c.payload_height)
            r.payload = std::max(r.payload, sim.mass_above(*c.payload_height));
        }
      r.r_max = sim.largest_radius();
      r.per_triangle.assign(surface.triangles.size(), 0.0);
      r.per_phase.assign(c.phases.size(), 0.0);
      for (std::size_t k : knives)
        {
          const auto v = wear->values(k, dem::WearRecorder::archard_volume);
          for (std::size_t t = 0; t < v.size(); ++t)
            r.per_triangle[t] += v[t] / knives.size();
          for (std::size_t p = 0; p < c.phases.size(); ++p)
            r.per_phase[p] += wear->total(k, dem::WearRecorder::archard_volume, c.phases[p].first) / knives.size();
        }
      return r;
    }

    /// The knife's cross-sections at x = f L: segments (y, z) where surface triangles cross the
    /// plane, appended per update (blank-line separated blocks) to knife/profile_F.csv.
    void write_profiles(const fem::SolidSurface &s, double length, const std::vector<double> &planes, long update,
                        const std::string &dir)
    {
      for (double f : planes)
        {
          const double x0 = f * length;
          char         name[64];
          std::snprintf(name, sizeof name, "/profile_%.2f.csv", f);
          const bool    first = update == 1;
          std::ofstream out(dir + name, first ? std::ios::trunc : std::ios::app);
          if (first)
            out << "# update y0 z0 y1 z1 (one segment per line; a block per update)\n";
          out.precision(10);
          for (const auto &t : s.triangles)
            {
              std::vector<dealii::Point<3>> cut;
              for (int e = 0; e < 3; ++e)
                {
                  const auto &a = s.vertices[t[e]], &b = s.vertices[t[(e + 1) % 3]];
                  if ((a[0] - x0) * (b[0] - x0) < 0)
                    cut.push_back(a + (x0 - a[0]) / (b[0] - a[0]) * (b - a));
                }
              if (cut.size() == 2)
                out << update << ' ' << cut[0][1] << ' ' << cut[0][2] << ' ' << cut[1][1] << ' ' << cut[1][2] << '\n';
            }
          out << "\n\n";
        }
    }

    /// trajectory.png (depth and worn volume vs tonnes) and knife/profile_F.png, with gnuplot.
    void plot_lifetime(const std::string &dir, const std::vector<double> &planes, const fem::KnifeGeometry &k)
    {
      std::ofstream gp(dir + "/lifetime.gp");
      gp << "set terminal pngcairo size 900,600\nset grid\nset datafile separator ','\n"
            "set output 'trajectory.png'\nset xlabel 'handled material [t]'\n"
            "set ylabel 'largest wear depth [mm]'\nset y2label 'worn volume [cm^3]'\nset y2tics\nset key left top\n"
            "plot 'trajectory.csv' using 3:($4*1000*(1-$13)):($4*1000*(1+$13)) with filledcurves "
            "fs transparent solid 0.25 noborder title 'depth +- spread of the beds', "
            "'' using 3:($4*1000) with linespoints title 'largest depth', "
            "'' using 3:($12*1000) with linespoints title 'recession of the followed point', "
            "'' using 3:($6*1e6) axes x1y2 with linespoints title 'worn volume'\n"
            "set datafile separator whitespace\nunset y2tics\nunset y2label\nset size ratio -1\n";
      for (double f : planes)
        {
          char name[64];
          std::snprintf(name, sizeof name, "knife/profile_%.2f", f);
          // the worn end of the knife: three bevel heights, at its true shape
          gp << "set output '" << name << ".png'\nset xlabel 'y [mm]'\nset ylabel 'z [mm]'\nset key outside\n"
             << "set xrange [" << -1000 * k.thickness << ":" << 1000 * k.thickness << "]\nset yrange [-2:"
             << 3000 * k.bevel << "]\n"
             << "stats '" << name << ".csv' nooutput\n"
             << "plot for [i=0:STATS_blocks-1] '" << name
             << ".csv' index i using ($2*1000):($3*1000):(($4-$2)*1000):(($5-$3)*1000) with vectors nohead "
                "title sprintf('update %d', i+1)\n";
        }
      gp.close();
      io::run_gnuplot(dir, "lifetime.gp");
    }
  } // namespace

  void run_lifetime_job(JobContext &ctx)
  {
    init_mpi_once();
    auto           &prm = ctx.parameters.handler();
    DemCase         c   = read_dem_case(ctx.parameters);
    KnifeParameters kp  = read_knife_parameters(ctx.parameters);

    if (kp.from_file)
      ctx.parameters.fail({"Knife"}, "Geometry", "lifetime runs use the parametric knife for now");
    prm.enter_subsection("Lifetime");
    const double tonnes_per_cycle = prm.get_double("Tonnes per cycle");
    const bool   payload_from_dem = tonnes_per_cycle == 0; // the DEM's payload (a grab)
    std::vector<int> seeds;
    for (const auto &s : dealii::Utilities::split_string_list(prm.get("Seeds")))
      seeds.push_back(std::stoi(s));
    const long   fixed_cycles  = prm.get_integer("Cycles per update");
    const double fraction      = prm.get_double("Depth increment fraction");
    double       smoothing     = prm.get_double("Smoothing radius");
    const double max_depth     = prm.get_double("Maximum depth");
    std::vector<double> planes;
    for (const auto &p : dealii::Utilities::split_string_list(prm.get("Profile planes")))
      planes.push_back(std::stod(p));
    const double target_tonnes = prm.get_double("Target tonnes");
    const double max_worn_mass = prm.get_double("Maximum worn mass");
    const double max_recession = prm.get_double("Maximum recession");
    std::vector<dealii::Point<3>> recession_points;
    for (const auto &point : dealii::Utilities::split_string_list(prm.get("Recession points"), ';'))
      {
        const auto xyz = dealii::Utilities::split_string_list(point);
        recession_points.emplace_back(std::stod(xyz[0]), std::stod(xyz[1]), std::stod(xyz[2]));
      }
    const long   max_updates   = prm.get_integer("Maximum updates");
    const bool   analytic      = prm.get("Wear source") == "analytic";
    const std::string rate_expression = prm.get("Analytic wear rate");
    prm.leave_subsection();
    if (payload_from_dem && !analytic && !c.payload_height)
      ctx.parameters.fail({"Lifetime"}, "Tonnes per cycle",
                          "0 takes the tonnes from the DEM's payload: set Simulation/Payload height");
    if (!analytic && std::none_of(c.walls.begin(), c.walls.end(), [](const auto &w) { return w.solid_model; }))
      ctx.parameters.fail({}, "Walls", "a lifetime run needs a wall with Geometry = solid model (the knife)");
    dealii::FunctionParser<3> analytic_rate;
    if (analytic)
      {
        if (tonnes_per_cycle <= 0)
          ctx.parameters.fail({"Lifetime"}, "Tonnes per cycle", "the analytic wear rate is per tonne: set Tonnes per cycle > 0");
        try
          {
            analytic_rate.initialize("x,y,z", rate_expression, {});
            analytic_rate.value(dealii::Point<3>());
          }
        catch (const std::exception &e)
          {
            ctx.parameters.fail({"Lifetime"}, "Analytic wear rate",
                                "cannot evaluate '" + rate_expression + "' as a function of x, y, z");
          }
      }
    if (seeds.empty())
      ctx.parameters.fail({"Lifetime"}, "Seeds", "at least one seed is needed");

    ctx.output.subdirectory("beds");
    fem::KnifeModel::Settings ks;
    ks.mesh_size      = kp.mesh_size;
    ks.density        = kp.density;
    ks.work_directory = ctx.output.subdirectory("knife/work");
    fem::KnifeModel knife(kp.geometry, ks);
    fem::SolidOutput knife_output(ctx.output.subdirectory("knife"), "knife");

    // --- resume: the last checkpoint, and the outputs cut back to it ---
    const LifetimeCheckpoints checkpoints(ctx.output.subdirectory("checkpoint"));
    const dem::Parallel       ranks = dem::Parallel::world();
    const std::string         hash  = io::fnv1a_hex(ctx.parameters.canonical_text());
    long              first_update = 1;
    long        cycles = 0;
    double      tonnes = 0; // handled so far
    double      archard_total = 0;
    std::vector<double> seed_volume;   // Archard volume per cycle of each seed (this update)
    std::vector<double> phase_volume;  // Archard volume per cycle and phase (seed mean)
    double              relative_spread = 0; // std / mean of seed_volume, over all updates
    double              relative_spread_last = 0;
    int                 spread_samples  = 0;
    double              volume0 = knife.volume();
    std::vector<std::string> kept_rows;
    std::vector<double>      output_times; // of the knife series already written (resume)
    if (const long done = ctx.resume ? checkpoints.resume_point(ranks) : 0; done > 0)
      {
        const std::string state_file = checkpoints.state_file(done);
        std::ifstream     in(state_file);
        std::string       saved_hash;
        long              saved_update = 0;
        in >> saved_hash >> saved_update >> cycles >> tonnes >> archard_total >> relative_spread >> spread_samples >>
          smoothing >> volume0;
        if (!in || saved_update != done)
          throw InputError(state_file, "corrupt lifetime checkpoint");
        if (saved_hash != hash)
          throw InputError(state_file, "the checkpoint was made with other parameters (hash " + saved_hash +
                                         ", now " + hash + "); resume with the same parameter file and --set options");
        knife.load(checkpoints.knife_file(done));
        first_update = done + 1;
        std::ifstream old(ctx.output.file("trajectory.csv"));
        std::string   line;
        std::getline(old, line); // header
        while (std::getline(old, line) && static_cast<long>(kept_rows.size()) < done)
          kept_rows.push_back(line);
        output_times.push_back(0.0); // the fresh knife
        for (const auto &row : kept_rows)
          output_times.push_back(std::stod(row.substr(row.find(',', row.find(',') + 1) + 1)));
        for (double f : planes) // profile blocks after the checkpoint go
          {
            char name[64];
            std::snprintf(name, sizeof name, "/knife/profile_%.2f.csv", f);
            std::ifstream      pin(ctx.output.root() + name);
            std::ostringstream keep;
            bool               kept = true; // the block the line is in (blank lines end blocks)
            for (std::string l; std::getline(pin, l);)
              {
                if (!l.empty() && l[0] != '#')
                  kept = std::stol(l.substr(0, l.find(' '))) <= done;
                if (kept || (!l.empty() && l[0] == '#'))
                  keep << l << '\n';
              }
            pin.close();
            std::ofstream(ctx.output.root() + name) << keep.str();
          }
        ctx.log.line("Resuming after update " + std::to_string(done) + " (" + std::to_string(cycles) + " cycles)");
      }
    knife_output.adopt(output_times);
    if (first_update == 1)
      {
        checkpoints.clear();
        knife.write(knife_output, 0);
        io::write_stl(ctx.output.file("knife/knife_00000.stl"), knife.surface().as_polydata()); // the design
        knife.save(checkpoints.knife_file(0)); // the state a rejected first update returns to
      }

    std::vector<std::string> columns = {"update", "cycles", "tonnes", "max_depth", "mean_depth", "worn_volume", "worn_mass",
                                        "archard_volume", "swept_over_archard", "min_scaled_jacobian", "remeshed",
                                        "point_recession", "wear_rate_spread"};
    for (const auto &phase : c.phases)
      columns.push_back("archard_volume_" + phase.first); // this update's wear per phase of the cycle
    for (std::size_t p = 1; p < recession_points.size(); ++p)
      columns.push_back("point_recession_" + std::to_string(p + 1));
    columns.push_back("tonnes_per_cycle"); // nominal, or the DEM's payload (Tonnes per cycle = 0)
    io::CsvWriter trajectory(ctx.output.file("trajectory.csv"), columns);
    ctx.log.line("Lifetime: knife of " + std::to_string(knife.triangulation().n_active_cells()) + " cells, " +
                 std::to_string(seeds.size()) + " bed seed(s) per update");
    for (const auto &row : kept_rows)
      trajectory.raw_row(row);
    io::ProgressLine progress("lifetime", double(max_updates));
    std::string end         = "maximum updates reached";
    bool        end_of_life = false; // an end-of-life criterion was met (not a target or a limit)
    for (long update = first_update; update <= max_updates; ++update)
      {
        // 1. DEM cycles on the current surface, averaged over the seeds
        const fem::SolidSurface &surface = knife.surface();
        std::vector<double>      per_triangle(surface.triangles.size(), 0.0);
        double                   r_max       = 0;
        double                   update_tonnes_per_cycle = tonnes_per_cycle;
        seed_volume.clear();
        phase_volume.assign(c.phases.size(), 0.0);
        if (analytic)
          {
            // a known wear rate instead of DEM (verification): depth per tonne at the triangle's
            // centroid, on the wearable surface
            for (std::size_t t = 0; t < surface.triangles.size(); ++t)
              if (surface.boundary_id[t] == fem::KnifeGeometry::wearable_boundary)
                {
                  const auto &tri = surface.triangles[t];
                  const dealii::Point<3> centroid(
                    (surface.vertices[tri[0]] + surface.vertices[tri[1]] + surface.vertices[tri[2]]) / 3);
                  per_triangle[t] = analytic_rate.value(centroid) * tonnes_per_cycle * surface.triangle_area(t);
                }
            seed_volume.push_back(std::accumulate(per_triangle.begin(), per_triangle.end(), 0.0));
          }
        else
        {
          io::ScopedTimer t(ctx.timers, "dem cycles");
          double          payload = 0;
          for (int seed : seeds)
            {
              const CycleResult cr = run_cycle(c, surface, seed, ctx);
              for (std::size_t p = 0; p < cr.per_phase.size(); ++p)
                phase_volume[p] += cr.per_phase[p] / seeds.size();
              for (std::size_t t = 0; t < cr.per_triangle.size(); ++t)
                per_triangle[t] += cr.per_triangle[t] / seeds.size();
              seed_volume.push_back(std::accumulate(cr.per_triangle.begin(), cr.per_triangle.end(), 0.0));
              r_max = cr.r_max;
              payload += cr.payload / seeds.size();
            }
          if (payload_from_dem)
            {
              update_tonnes_per_cycle = payload / 1000;
              if (!(update_tonnes_per_cycle > 0))
                {
                  end = "no payload: nothing above Simulation/Payload height at the end of any phase";
                  break;
                }
            }
        }
        if (smoothing <= 0 && !analytic)
          smoothing = r_max; // analytic rates: no smoothing unless asked for

        // 2. per-vertex volume, smoothed (volume conserving), depth per cycle
        const std::size_t   nv = surface.vertices.size();
        std::vector<double> vertex_volume(nv, 0.0), vertex_area(nv, 0.0);
        for (std::size_t t = 0; t < surface.triangles.size(); ++t)
          {
            const double a = surface.triangle_area(t);
            for (unsigned v : surface.triangles[t])
              {
                vertex_area[v] += a / 3;
                if (surface.boundary_id[t] == fem::KnifeGeometry::wearable_boundary)
                  vertex_volume[v] += per_triangle[t] / 3;
              }
          }
        std::vector<double> smoothed(smoothing > 0 ? std::vector<double>(nv, 0.0) : vertex_volume);
        for (std::size_t u = 0; u < nv && smoothing > 0; ++u)
          {
            if (vertex_volume[u] == 0)
              continue;
            std::vector<std::pair<std::size_t, double>> w;
            double                                      sum = 0;
            for (std::size_t v = 0; v < nv; ++v)
              {
                const double d2 = surface.vertices[u].distance_square(surface.vertices[v]);
                if (d2 < 9 * smoothing * smoothing)
                  {
                    const double k = std::exp(-0.5 * d2 / (smoothing * smoothing)) * vertex_area[v];
                    w.emplace_back(v, k), sum += k;
                  }
              }
            for (const auto &[v, k] : w)
              smoothed[v] += vertex_volume[u] * k / sum;
          }
        std::vector<double> depth_per_cycle(nv, 0.0);
        double              max_rate = 0;
        for (std::size_t v = 0; v < nv; ++v)
          {
            depth_per_cycle[v] = vertex_area[v] > 0 ? smoothed[v] / vertex_area[v] : 0.0;
            max_rate           = std::max(max_rate, depth_per_cycle[v]);
          }
        const double archard_cycle = std::accumulate(per_triangle.begin(), per_triangle.end(), 0.0);
        if (!(max_rate > 0))
          {
            end = "no wear on the knife (does the DEM cycle touch it?)";
            break;
          }

        // 3. cycles this update stands for
        long n = fixed_cycles > 0 ? fixed_cycles
                                        : std::max(1L, long(std::floor(fraction * kp.mesh_size / max_rate)));
        std::vector<double> depth(nv);
        for (std::size_t v = 0; v < nv; ++v)
          depth[v] = n * depth_per_cycle[v];

        // 4. move the knife. A surface that cannot be remeshed (it folds where the wear is deepest)
        //    rejects the step: the knife goes back to its last checkpoint (the state before this
        //    update) and the update is retried with half the cycles, up to three times.
        const double volume_before = knife.volume();
        fem::KnifeModel::UpdateResult r;
        bool                          moved = false;
        // Under MPI every rank moves its own copy of the knife: the ranks agree on the outcome
        // (a failure on one is a failure on all), so that their knives stay the same.
        for (int attempt = 0; !moved; ++attempt)
          {
            std::string error;
            try
              {
                io::ScopedTimer t(ctx.timers, "fem update");
                if (attempt > 0)
                  knife.load(checkpoints.knife_file(update - 1));
                r = knife.apply_wear(depth);
              }
            catch (const std::exception &e)
              {
                error = e.what();
              }
            if (!(ranks.max(error.empty() ? 0.0 : 1.0) > 0))
              {
                moved = true;
                break;
              }
            if (error.empty())
              error = "the knife could not be moved on another MPI rank";
            if (attempt == 3 || n == 1)
              break;
            n = std::max(1L, n / 2);
            for (std::size_t v = 0; v < nv; ++v)
              depth[v] = n * depth_per_cycle[v];
            ctx.log.warning("update " + std::to_string(update) + ": " + error + "; retried with " + std::to_string(n) +
                            " cycles");
          }
        if (!moved)
          {
            end = "the worn surface could not be remeshed at update " + std::to_string(update) +
                  ", also with an eighth of the cycles (it folds where the wear is deepest; a larger Lifetime/Smoothing "
                  "radius or a finer Knife/Mesh size helps)";
            ctx.log.warning(end);
            break;
          }
        if (!r.worn_through.empty())
          {
            end = "worn through at update " + std::to_string(update);
            end_of_life = true;
            break;
          }
        cycles += n;
        archard_total += n * archard_cycle;

        // 5. record
        if (seed_volume.size() > 1)
          {
            const double mean = std::accumulate(seed_volume.begin(), seed_volume.end(), 0.0) / seed_volume.size();
            double       var  = 0;
            for (double x : seed_volume)
              var += (x - mean) * (x - mean) / (seed_volume.size() - 1);
            relative_spread_last = std::sqrt(var) / mean;
            relative_spread += relative_spread_last, ++spread_samples;
          }
        write_profiles(knife.surface(), kp.geometry.length, planes, update, ctx.output.root() + "/knife");
        const auto  &acc  = knife.accumulated_depth();
        const double dmax = *std::max_element(acc.begin(), acc.end());
        const double dmean = std::accumulate(acc.begin(), acc.end(), 0.0) / acc.size();
        const double swept = volume_before - knife.volume();
        // the recession of the followed points (the surface points that were there on the fresh knife)
        const std::vector<double> recession = knife.recession_at(recession_points);
        const double update_spread = seed_volume.size() > 1 ? relative_spread_last : 0.0;
        tonnes += n * update_tonnes_per_cycle;
        std::vector<double> row = {double(update), double(cycles), tonnes, dmax, dmean,
                                   volume0 - knife.volume(), (volume0 - knife.volume()) * kp.density, n * archard_cycle,
                                   swept / (n * archard_cycle), r.quality.min_scaled_jacobian, r.remeshed ? 1.0 : 0.0,
                                   recession[0], update_spread};
        for (double pv : phase_volume)
          row.push_back(n * pv);
        row.insert(row.end(), recession.begin() + 1, recession.end());
        row.push_back(update_tonnes_per_cycle);
        trajectory.row(row);
        trajectory.flush();
        knife.write(knife_output, tonnes);
        char stl[64];
        std::snprintf(stl, sizeof stl, "knife/knife_%05ld.stl", update);
        io::write_stl(ctx.output.file(stl), knife.surface().as_polydata());
        std::ostringstream s;
        s << "update " << update << ": " << n << " cycles (" << tonnes << " t), max depth "
          << dmax << " m, swept/Archard volume " << swept / (n * archard_cycle)
          << (r.remeshed ? ", remeshed" : "");
        ctx.log.line(s.str());
        progress.update(double(update), "update " + std::to_string(update) + "/" + std::to_string(max_updates) + ", " +
                                          std::to_string(long(tonnes)) + " t");

        // 6. checkpoint: written aside, then renamed, so a kill never leaves half of one (the
        //    knife and the state of one update, lifetime_checkpoints.h)
        knife.save(checkpoints.knife_file_aside(update));
        {
          std::ofstream state(checkpoints.state_file_aside(update));
          state.precision(17);
          state << hash << ' ' << update << ' ' << cycles << ' ' << tonnes << ' ' << archard_total << ' '
                << relative_spread << ' ' << spread_samples << ' ' << smoothing << ' ' << volume0 << '\n';
        }
        checkpoints.commit(update);
        if (dmax >= max_depth)
          {
            end = "maximum depth reached";
            end_of_life = true;
            break;
          }
        if (max_recession > 0 && *std::max_element(recession.begin(), recession.end()) >= max_recession)
          {
            end = "maximum recession of a followed point reached";
            end_of_life = true;
            break;
          }
        if (max_worn_mass > 0 && (volume0 - knife.volume()) * kp.density >= max_worn_mass)
          {
            end = "maximum worn mass reached";
            end_of_life = true;
            break;
          }
        if (target_tonnes > 0 && tonnes >= target_tonnes)
          {
            end = "target tonnes reached";
            break;
          }
      }
    progress.finish();
    const auto  &acc  = knife.accumulated_depth();
    const double dmax = acc.empty() ? 0.0 : *std::max_element(acc.begin(), acc.end());
    io::Json    &r    = ctx.results["lifetime"];
    r["end"]          = end;
    r["cycles"]       = cycles;
    r["tonnes"]       = tonnes;
    r["max_depth"]    = dmax;
    r["worn_volume"]  = volume0 - knife.volume();
    r["worn_mass"]    = (volume0 - knife.volume()) * kp.density;
    r["archard_volume"] = archard_total;
    r["remeshes"]     = static_cast<long>(knife.n_remeshes());
    for (const auto &wc : c.walls) // the W the depths scale with (abrade calibrate rescales it)
      if (wc.solid_model && !analytic)
        r["archard_coefficient"] = wc.wear.archard_coefficient;
    // the tonnes to end of life: where an end-of-life criterion was met, or extrapolated linearly
    // from the depth rate so far (to the maximum depth) when the run stopped before one was (at
    // the target tonnes, the maximum updates, or a surface that could not be remeshed)
    const bool reached = end_of_life;
    r["predicted_tonnes_to_end_of_life"] =
      reached ? tonnes : (dmax > 0 ? tonnes * max_depth / dmax : 0.0);
    r["extrapolated"] = !reached;
    // uncertainty from the replicate beds: the wear rate's relative spread carries to the life
    const double spread = spread_samples ? relative_spread / spread_samples : 0.0;
    const double life   = r["predicted_tonnes_to_end_of_life"].number();
    r["wear_rate_relative_spread"] = spread;
    r["predicted_tonnes_low"]      = life / (1 + spread);
    r["predicted_tonnes_high"]     = spread < 1 ? life / (1 - spread) : 0.0;
    plot_lifetime(ctx.output.root(), planes, kp.geometry);
    std::ostringstream s;
    s << "Lifetime: " << end << " after " << cycles << " cycles; predicted life " << life << " t";
    if (spread_samples)
      s << " (" << life / (1 + spread) << " ... " << (spread < 1 ? life / (1 - spread) : 0.0) << " t from "
        << seeds.size() << " beds)";
    ctx.log.line(s.str());
  }
} // namespace abrade::coupling
