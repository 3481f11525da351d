// The lifetime loop (lifetime_loop.h): the part's wear over its working life. This file holds
// the loop's bookkeeping; the arithmetic of every step is in its own file (end_of_life.cc,
// life_interval.cc, update_size.cc, fem/surface_filter.cc, fem/part_model.cc).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/hash.h>
#include <abrade/common/input_file.h>
#include <abrade/common/progress.h>
#include <abrade/common/timer.h>
#include <abrade/coupling/dem_run/bed_preparation.h>
#include <abrade/coupling/lifetime/lifetime_loop.h>
#include <abrade/coupling/lifetime/lifetime_outputs.h>
#include <abrade/coupling/lifetime/paired_life.h>
#include <abrade/coupling/lifetime/state_file.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/coupling/lifetime/update_size.h>
#include <abrade/coupling/lifetime/wear_rates.h>
#include <abrade/coupling/parameters/earlier_printings.h>
#include <abrade/dem/wear.h>
#include <abrade/dem/parallel.h>
#include <abrade/fem/mpi_once.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/base/utilities.h>

#include <deal.II/base/bounding_box.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <sstream>
#include <tuple>

namespace abrade::coupling::lifetime
{
  namespace
  {
    /// The lifetime state file's format, raised whenever what a state holds changes (a state of
    /// another format is refused: start afresh). It holds the trajectory's rows and a checksum,
    /// the updates' records of every criterion (beds, relative variance) and the beds of the
    /// next, the beds' deviations at every criterion's places (place_scatter.h), each
    /// criterion's entries under its name (end_of_life_criterion.h), and the wear so far as
    /// wear_total (of whichever Wear field).
    const std::string state_format = "abrade lifetime state 7";

    /// A criterion's entries in the state file: "history_" + this ("maximum_depth").
    std::string state_key(const EndOfLifeCriterion &c)
    {
      std::string k = c.name();
      std::replace(k.begin(), k.end(), ' ', '_');
      return k;
    }
  } // namespace

  LifetimeLoop::LifetimeLoop(JobContext &ctx) : ctx(ctx) {}
  LifetimeLoop::~LifetimeLoop() = default;

  // ---------------------------------------------------------------------------------------------
  // The algorithm.
  void LifetimeLoop::run()
  {
    set_up();
    // the part's share of the run, by kind of work, in summary.json's timings: added as run()
    // is left, so that a failed run has them too (an interrupted one exits without its timings)
    struct PartTimings
    {
      const LifetimeLoop &loop;
      ~PartTimings()
      {
        for (const auto &[name, seconds] : loop.part_model->timings().all())
          loop.ctx.timers.add("part: " + name, seconds);
      }
    } part_timings{*this};
    io::ProgressLine progress("lifetime", double(s.max_updates));
    const bool finished = update > 0 && stop_here(); // a resumed run that had ended
    if (!finished && update == 0 && s.fixed_cycles <= 0)
      size_first_update();
    for (++update; !finished && update <= s.max_updates; ++update)
      {
        const CycleWear wear = run_cycles();
        if (!wear.stop.empty())
          {
            end = wear.stop;
            break;
          }
        const Rates rates = filter(wear);
        if (!(rates.largest > 0))
          {
            end = "no wear on the part (does the cycle touch it?)";
            break;
          }
        const Step step = move_part(rates, choose_cycles(rates));
        previous_largest = rates.largest;
        if (!step.moved)
          {
            end = step.error;
            ctx.log.warning(end);
            warnings.push_back(end);
            break;
          }
        if (worn_through)
          break;
        record(wear, rates, step);
        choose_beds();
        checkpoint();
        progress.update(double(update), "update " + std::to_string(update) + "/" + std::to_string(s.max_updates) +
                                          ", " + std::to_string(long(tonnes)) + " t");
        if (stop_here())
          break;
      }
    progress.finish();
    finish();
  }

  // ---------------------------------------------------------------------------------------------
  // Set-up: parameters (read_settings(): lifetime_settings.cc), part, wear source, outputs, and
  // the resume.
  void LifetimeLoop::set_up()
  {
    fem::init_mpi_once();
    dem_case         = read_dem_case(ctx.parameters);
    report_coarse_graining(dem_case, ctx);
    part_parameters = read_part_parameters(ctx.parameters);
    read_settings();
    {
      io::ScopedTimer t(ctx.timers, "part: first mesh");
      build_part();
    }
    source = source_choice->make(
      {ctx, dem_case, s.seeds, s.tonnes_per_cycle, part_model->design_surface(), part_parameters.mesh_size});
    take_calibration();

    ctx.output.subdirectory("beds");
    part_output = std::make_unique<fem::SolidOutput>(ctx.output.subdirectory(ctx.output.part_folder(ctx.resume)),
                                                     ctx.output.part_folder(ctx.resume));
    checkpoints       = std::make_unique<LifetimeCheckpoints>(ctx.output.subdirectory("checkpoint"));
    // (a calibration's numbers too: a resume with another calibration.json behind the same name
    // would mix two coefficients)
    const std::string calibrated = calibration.coefficient > 0 ? "\ncalibration " +
                                                                   io::format_number(calibration.coefficient, 17) + " " +
                                                                   io::format_number(calibration.relative_sd, 17) + " " +
                                                                   io::format_number(calibration.smoothing_radius, 17)
                                                                 : std::string();
    hash = io::fnv1a_hex(ctx.parameters.identity_text() + calibrated);
    // (a checkpoint of an earlier abrade hashed the parameters as it printed them)
    for (const std::string &text : earlier_printings(ctx.parameters.identity_text()))
      earlier_hashes.push_back(io::fnv1a_hex(text + calibrated));
    volume0           = part_model->volume();
    const std::size_t n_criteria = criteria.size();
    history           = {{0.0, std::vector<double>(n_criteria, 0.0)}};
    records.assign(n_criteria, {});
    place_scatter.assign(n_criteria, {});
    place_values.assign(n_criteria, {});
    place_factor.assign(n_criteria, 1.0);
    beds_now          = long(s.seeds.size());

    field_columns = WearFieldColumns(dem_case.wear_field);
    std::vector<std::string> columns = {"update", "cycles", "tonnes", "max_depth", "mean_depth",
                                        "max_vertex_displacement", "worn_volume", "worn_mass", field_columns.volume,
                                        field_columns.swept_over, "min_scaled_jacobian", "remeshed", "point_recession",
                                        "wear_rate_spread"};
    for (const auto &phase : source->phases())
      columns.push_back(field_columns.volume + "_" + phase); // this update's wear per phase of the cycle
    for (std::size_t p = 1; p < s.recession_points.size(); ++p)
      columns.push_back("point_recession_" + std::to_string(p + 1));
    columns.insert(columns.end(), {"tonnes_per_cycle", "deepest_x", "deepest_y", "deepest_z", "dem_warnings", "beds",
                                   "edge_recession", "edge_recession_x", "plate_thickness", "plate_thickness_x"});
    // the wear depth (below the design) at the followed points: what a gauge there measures
    for (std::size_t p = 0; p < s.recession_points.size(); ++p)
      columns.push_back(p == 0 ? std::string("point_depth") : "point_depth_" + std::to_string(p + 1));

    // trajectory.csv is an output, never read back: a resumed run writes it anew from the rows
    // the checkpoint holds (a file edited, cut or emptied by a second crash cannot leak in)
    if (!(ctx.resume && resume()))
      start_afresh();
    trajectory.open(ctx.output.file("trajectory.csv"), columns);
    for (const auto &row : trajectory_rows)
      trajectory.raw_row(row);
    trajectory.flush();
    ctx.log.line("Lifetime: part of " + std::to_string(part_model->triangulation().n_active_cells()) + " cells, " +
                 std::to_string(beds_now) + " fresh bed(s) per update, wear from " +
                 source_choice->description());
  }

  // The part: the parametric one or a user's part (its faces chosen, placed), checked against
  // the criteria that need to know where it is.
  void LifetimeLoop::build_part()
  {
    fem::PartModel::Settings ks;
    ks.mesh_size      = part_parameters.mesh_size;
    ks.density        = part_parameters.density;
    ks.work_directory = ctx.output.subdirectory(ctx.output.part_folder(ctx.resume) + "/work");
    if (part_parameters.from_file)
      {
        PartMesh m = mesh_part(part_parameters, ctx.parameters, ks.work_directory);
        report_part_mesh(part_parameters, m, ctx.log, &warnings);
        part_model = std::make_unique<fem::PartModel>(std::move(m.tria), ks);
        if (const std::string w = fit_mounted_parts(dem_case, part_model->design_surface()); !w.empty())
          {
            ctx.log.warning(w);
            warnings.push_back(w);
          }
      }
    else
      part_model = std::make_unique<fem::PartModel>(part_parameters.geometry, ks);
    frame = profile_frame(part_model->design_surface());
    // the gauges' stations on the design: its edge heights and the plate's thickness at the
    // gauge height
    if (s.gauge_height <= 0)
      {
        // a plate thickness above where the design is first whole (a chisel's bevel top, whose
        // worn corner rises as the faces beside it wear): where calipers read the flat plate
        const double whole = full_thickness_height(part_model->design_surface(), frame.x0, frame.x1, frame.z0, frame.z1);
        s.gauge_height     = whole + part_model->thickness();
      }
    design_sections = worn_and_design_sections(part_model->design_surface(), part_model->design_surface(),
                                               int(s.gauge_stations), frame.z0 + s.gauge_height, part_parameters.mesh_size)
                        .second;
    design_thickness = *std::max_element(design_sections.thickness.begin(), design_sections.thickness.end());
    // every criterion's limit on the design: one the design makes impossible is refused, one
    // it makes implausible said (on the terminal, in the summary's warnings and beside the life)
    std::vector<std::string> said;
    limits.clear();
    for (const auto &c : criteria)
      try
        {
          limits.push_back({c->name(), c->limit(design_now(), said)});
        }
      catch (const CriterionRefused &e)
        {
          ctx.parameters.fail({"Lifetime"}, e.key, e.what());
        }
    for (const auto &w : said)
      {
        ctx.log.warning(w);
        warnings.push_back(w);
      }
    // a followed point away from the part would follow the nearest surface point without a word
    const std::vector<double> off = part_model->depth_below_design(s.recession_points);
    std::vector<double>       points;
    for (const auto &p : s.recession_points)
      points.insert(points.end(), {p[0], p[1], p[2]});
    for (std::size_t k = 0; k < off.size(); ++k)
      if (std::abs(off[k]) > part_parameters.mesh_size)
        ctx.parameters.fail({"Lifetime"}, "Recession points",
                            "point " + std::to_string(k + 1) + " (" + io::format_number(points[3 * k]) + ", " +
                              io::format_number(points[3 * k + 1]) + ", " + io::format_number(points[3 * k + 2]) + ") lies " +
                              io::format_number(std::abs(off[k])) + " m from the part's surface (more than its Mesh size): "
                              "give points on the edge in the part's frame (after its placement)");
  }

  void LifetimeLoop::start_afresh()
  {
    update   = 0;
    sections = design_at_sections = design_sections;
    checkpoints->clear();
    // (the stored wear of an earlier run in this directory: its update files only)
    std::error_code ec;
    for (const auto &e : std::filesystem::directory_iterator(ctx.output.subdirectory("wear"), ec))
      if (const std::string name = e.path().filename().string();
          name.rfind("update_", 0) == 0 && e.path().extension() == ".wear")
        std::filesystem::remove(e.path(), ec);
    part_output->adopt({});
    part_model->write(*part_output, 0);
    const std::string part = ctx.output.part_folder(ctx.resume);
    io::write_stl(ctx.output.file(part + "/" + part_surface_name(part, 0)), part_model->surface().as_polydata()); // the design
    part_model->save(checkpoints->part_file(0)); // the state a rejected first update returns to
  }

  bool LifetimeLoop::resume()
  {
    const long done = checkpoints->resume_point(dem::Parallel::world());
    if (done <= 0)
      return false;
    const std::string file  = checkpoints->state_file(done);
    const StateFile   state = read_checkpoint(file, done);
    const auto        t     = take_loop_state(state, file, done);
    for (std::size_t c = 0; c < criteria.size(); ++c)
      take_criterion_state(state, file, c, t, done);
    trajectory_rows.clear();
    for (long k = 1; k <= done; ++k)
      trajectory_rows.push_back(state.text("trajectory_row_" + std::to_string(k)));
    part_model->load(checkpoints->part_file(done));
    gauge_the_part();
    std::vector<double> output_times;
    for (const auto &p : history)
      output_times.push_back(p.tonnes);
    part_output->adopt(output_times);
    for (const auto &path : truncate_profiles(s.planes, done, ctx.output.file(ctx.output.part_folder(ctx.resume))))
      {
        warnings.push_back(path + " is missing: its profiles start at update " + std::to_string(done + 1));
        ctx.log.warning(warnings.back());
      }
    ctx.log.line("Resuming after update " + std::to_string(done) + " (" + std::to_string(cycles) + " cycles)");
    return true;
  }

  StateFile LifetimeLoop::read_checkpoint(const std::string &file, long done) const
  {
    StateFile state = StateFile::read(file);
    if (!state.has("format") || state.text("format") != state_format)
      throw InputError(file, "a lifetime checkpoint of another abrade version (format '" +
                               (state.has("format") ? state.text("format") : std::string("1")) + "', this one reads '" +
                               state_format + "'); start afresh without --resume");
    // (a checkpoint of an earlier abrade hashed the parameters with the output directory's
    // name: resumed when made in the directory of this run's name)
    const std::string kept = state.text("parameter_hash");
    if (kept != hash && std::find(earlier_hashes.begin(), earlier_hashes.end(), kept) == earlier_hashes.end() &&
        kept != io::fnv1a_hex(ctx.parameters.canonical_text()))
      throw InputError(file, "the checkpoint was made with other parameters (hash " + kept +
                               ", now " + hash + "); resume with the same parameter file and --set options" +
                               (calibration.coefficient > 0 ? " and the same Lifetime/Calibration file content" : ""));
    if (state.number("update") != double(done))
      throw InputError(file, "corrupt lifetime checkpoint (it says update " + state.text("update") + ")");
    return state;
  }

  std::vector<double> LifetimeLoop::take_loop_state(const StateFile &state, const std::string &file, long done)
  {
    update           = done;
    cycles           = long(state.number("cycles"));
    tonnes           = state.number("tonnes");
    wear_total       = state.number("wear_total");
    s.smoothing      = state.number("smoothing_radius");
    volume0          = state.number("design_volume");
    deepest          = state.numbers("deepest_point");
    beds_now         = long(state.number("beds_next"));
    previous_largest = state.number("previous_largest_rate");
    if (beds_now < long(s.seeds.size()))
      throw InputError(file, "corrupt lifetime checkpoint (" + state.text("beds_next") + " beds for the next update)");
    const auto t = state.numbers("history_tonnes");
    if (long(t.size()) != done + 1 || deepest.size() != 3)
      throw InputError(file, "corrupt lifetime checkpoint (history of " + std::to_string(t.size()) + " points)");
    if (cycles < 0 || tonnes < 0 || t.front() != 0 || !std::is_sorted(t.begin(), t.end()) || t.back() != tonnes)
      throw InputError(file, "corrupt lifetime checkpoint (negative or decreasing tonnes or cycles)");
    history.assign(t.size(), {0.0, std::vector<double>(criteria.size(), 0.0)});
    for (std::size_t k = 0; k < t.size(); ++k)
      history[k].tonnes = t[k];
    return t;
  }

  void LifetimeLoop::take_criterion_state(const StateFile &state, const std::string &file, std::size_t c,
                                          const std::vector<double> &t, long done)
  {
    const std::string key = state_key(*criteria[c]);
    if (!state.has("history_" + key))
      throw InputError(file, "the checkpoint has no history of the end-of-life criterion '" + criteria[c]->name() +
                               "' (made by an abrade without it); start afresh without --resume");
    const auto v = state.numbers("history_" + key);
    if (v.size() != t.size())
      throw InputError(file, "corrupt lifetime checkpoint (criterion history " + key + ")");
    for (std::size_t k = 0; k < v.size(); ++k)
      history[k].values[c] = v[k];
    // its update records: per update the beds, their seeds and rates, the relative variance
    const auto beds = state.numbers("record_beds_" + key);
    const auto var  = state.numbers("record_relative_variance_" + key);
    if (long(beds.size()) != done || var.size() != beds.size())
      throw InputError(file, "corrupt lifetime checkpoint (update records of criterion " + key + ")");
    const auto   seeds = state.numbers("record_bed_seeds_" + key);
    const auto   rates = state.numbers("record_bed_rates_" + key);
    const double all   = std::accumulate(beds.begin(), beds.end(), 0.0);
    if (seeds.size() != rates.size() || double(seeds.size()) != all)
      throw InputError(file, "corrupt lifetime checkpoint (the beds of criterion " + key + ")");
    records[c].clear();
    for (long k = 0, first = 0; k < done; first += long(beds[k]), ++k)
      records[c].push_back({t[k + 1], v[k + 1], std::size_t(beds[k]), var[k],
                            std::vector<int>(seeds.begin() + first, seeds.begin() + first + long(beds[k])),
                            std::vector<double>(rates.begin() + first, rates.begin() + first + long(beds[k]))});
    // its places' scatter
    try
      {
        place_scatter[c].set_numbers(state.numbers("place_scatter_" + key));
      }
    catch (const std::invalid_argument &e)
      {
        throw InputError(file, std::string("corrupt lifetime checkpoint (") + e.what() + ")");
      }
    place_values[c] = state.numbers("place_values_" + key);
    place_factor[c] = state.number("place_factor_" + key);
    if (place_scatter[c].updates() != std::size_t(done) || place_values[c].size() != place_scatter[c].places() ||
        !(place_factor[c] >= 0 && place_factor[c] <= 1))
      throw InputError(file, "corrupt lifetime checkpoint (the places of criterion " + key + ")");
  }

  // ---------------------------------------------------------------------------------------------
  // 1. One cycle's wear, per bed: fresh beds for every update, their seeds derived from the
  //    run's seeds, the update number and (for beds beyond the seeds) a round.
  CycleWear LifetimeLoop::run_cycles()
  {
    std::vector<int> &beds = beds_of_update;
    beds.clear();
    for (long k = 0; k < beds_now; ++k)
      beds.push_back(bed_seed(s.seeds[k % s.seeds.size()], update, k / long(s.seeds.size())));
    CycleWear wear;
    try
      {
        wear = source->cycle(part_model->surface(), tonnes, beds);
      }
    catch (const std::domain_error &e) // an analytic rate that is negative or not a number
      {
        source_choice->fail_on_rate(ctx.parameters, e.what());
      }
    store_wear(wear, beds);
    // the DEM's warnings (Simulation/On error = continue): each kind logged once, all counted
    dem_warnings_now = source->name() == "DEM" ? long(wear.warnings.size()) : 0; // (a replay's are its own)
    dem_warnings_total += dem_warnings_now;
    log_cycle_messages(wear, "update " + std::to_string(update));
    resolve_smoothing(wear);
    return wear;
  }

  // A cycle's warnings (each kind once) and notes (each text once) in the log and summary.json.
  void LifetimeLoop::log_cycle_messages(const CycleWear &wear, const std::string &cycle)
  {
    const auto warn = [&](const std::string &w) {
      warnings.push_back(cycle + ", " + source->name() + ": " + w);
      ctx.log.warning(warnings.back());
    };
    for (const auto &w : wear.warnings)
      if (warning_kinds.insert(w.substr(0, w.find(" at step "))).second) // (the step and time vary)
        warn(w);
    for (const auto &w : wear.notes) // (the run's set-up: each text once, not counted)
      if (notes_given.insert(w).second)
        warn(w);
  }

  // Before the first update: a pilot cycle on beds of its own (update 0's seeds) gives the rate
  // the first update is sized by, as every later update is sized by the one before (update_size.h:
  // sized by its own beds, an update's tonnes carry their scatter as 1 / rate).
  void LifetimeLoop::size_first_update()
  {
    std::vector<int> beds;
    for (int seed : s.seeds)
      beds.push_back(bed_seed(seed, 0));
    CycleWear wear;
    try
      {
        wear = source->cycle(part_model->surface(), 0, beds);
      }
    catch (const std::domain_error &e)
      {
        source_choice->fail_on_rate(ctx.parameters, e.what());
      }
    store_wear(wear, beds);
    // (logged, not counted in dem_warnings: those are the updates', trajectory.csv's rows)
    log_cycle_messages(wear, "pilot cycle");
    resolve_smoothing(wear);
    previous_largest = depth_rates(part_model->surface(), wear, s.smoothing).largest;
    ctx.log.line("pilot cycle on " + std::to_string(beds.size()) + " bed(s) of its own: the first update is sized "
                 "by its largest wear depth rate, " + io::format_number(previous_largest) + " m per cycle");
  }

  // Every cycle's wear as it came, before the filter, with the surface it fell on
  // (stored_wear.h): a replay at another footprint needs no DEM. A source that chose its own
  // beds (a replay) names them.
  void LifetimeLoop::store_wear(const CycleWear &wear, std::vector<int> &beds)
  {
    if (!wear.bed_seeds.empty())
      beds = wear.bed_seeds;
    if (!wear.stop.empty() || dem::Parallel::world().rank() != 0)
      return;
    io::ScopedTimer t(ctx.timers, "stored wear");
    StoredWear      stored;
    stored.update           = update; // (0: the pilot cycle)
    stored.tonnes_start     = tonnes;
    stored.bed_seeds        = beds;
    stored.wear             = wear;
    stored.surface          = part_model->surface();
    stored.wear_coefficient = source->wear_coefficient();
    stored.removes_volume   = source->removes_volume();
    stored.phases           = source->phases();
    stored.coarse_graining_factor = dem_case.factor_at_tools(); // (with its particle radius)
    write_stored_wear(stored_wear_file(ctx.output.root(), stored.update), stored);
  }

  // Lifetime/Calibration: the calibrated W replaces the case's (wear_calibration.h).
  void LifetimeLoop::take_calibration()
  {
    if (s.calibration_file.empty())
      return;
    if (!source_choice->from_particles())
      ctx.parameters.fail({"Lifetime"}, "Calibration", "a known wear rate (Wear source = " + source_choice->name() +
                                                         ") has no coefficient to calibrate (DEM wear only)");
    io::require_input_file(s.calibration_file);
    calibration = read_wear_calibration(s.calibration_file);
    if (!(source->wear_coefficient() > 0))
      ctx.parameters.fail({"Lifetime"}, "Calibration", "the part's wear law has no coefficient to replace");
    if (!calibration.wear_field.empty() && calibration.wear_field != dem_case.wear_field)
      ctx.parameters.fail({"Lifetime"}, "Calibration",
                          s.calibration_file + " fitted the coefficient of " + calibration.wear_field +
                            ", this run wears the part by " + dem_case.wear_field +
                            " (Output/Wear field): another law's coefficient");
    if (const double ratio = calibration.coefficient / source->wear_coefficient(); !(ratio >= 1e-3 && ratio <= 1e3))
      ctx.parameters.fail({"Lifetime"}, "Calibration",
                          s.calibration_file + " gives W = " + io::format_number(calibration.coefficient, 4) +
                            ", " + io::format_number(ratio, 3) + " times the case's: not the same law or units");
    if (calibration.extrapolated)
      {
        warnings.push_back("Lifetime/Calibration: " + s.calibration_file + " fitted W where the calibrated run was "
                           "extrapolated past its last update (run it further and calibrate again)");
        ctx.log.warning(warnings.back());
      }
    if (calibration.footprint && calibration.footprint_slope_assumed)
      {
        warnings.push_back("Lifetime/Calibration: " + s.calibration_file + "'s candidate runs had no predicted lives "
                           "(dlnlife_dlnr 0): the footprint's share of the life's interval takes the life's slope "
                           "along the ridge as d ln W / d ln r, as if the life at a fixed W did not depend on the "
                           "footprint (on the knife-bed it goes as r^0.71); run the candidates to their end of life "
                           "and calibrate again");
        ctx.log.warning(warnings.back());
      }
    if (calibration.relative_sd == 0)
      {
        warnings.push_back("Lifetime/Calibration: " + s.calibration_file + " states no uncertainty of W (a fit without "
                           "residuals or beds): the life's interval has no calibration component");
        ctx.log.warning(warnings.back());
      }
    ctx.log.line("calibration " + s.calibration_file + ": W = " + io::format_number(calibration.coefficient, 4) +
                 " 1/Pa +- " + io::format_number(100 * calibration.relative_sd, 3) + " % (the case's " +
                 io::format_number(source->wear_coefficient(), 4) + "; every cycle's wear scaled by their ratio)");
    source = make_calibrated_wear_source(std::move(source), calibration.coefficient);
    if (calibration.footprint && s.smoothing <= 0)
      {
        s.smoothing = calibration.smoothing_radius;
        ctx.log.line("calibration: the footprint fitted with W, Lifetime/Smoothing radius = " +
                     io::format_number(s.smoothing, 4) + " m (the life's share of its uncertainty +- " +
                     io::format_number(100 * calibration.footprint_relative_sd, 3) + " %)");
      }
  }

  // The wear filter's length: the particle's footprint unless given (analytic rates: no filter
  // unless asked). Wear narrower than half a cell is carried by single vertices: on the chisel's
  // tip they blunt it into a flat that Gmsh cannot remesh (docs/lifetime.md, the tip check).
  void LifetimeLoop::resolve_smoothing(const CycleWear &wear)
  {
    if (wear.particle_radius > 0)
      particle_radius = wear.particle_radius;
    // W and the footprint hold for the particle size they were fitted at (docs/coarse-graining.md)
    if (!smoothing_checked && calibration.coefficient > 0)
      {
        const bool other_factor = calibration.coarse_graining_factor > 0 &&
                                  std::abs(dem_case.factor_at_tools() / calibration.coarse_graining_factor - 1) > 0.01;
        const bool other_size = calibration.particle_radius > 0 && particle_radius > 0 &&
                                std::abs(particle_radius / calibration.particle_radius - 1) > 0.01;
        if (other_factor || other_size)
          {
            warnings.push_back(
              "Lifetime/Calibration was fitted with particles of largest radius (at the tools) " +
              io::format_number(calibration.particle_radius, 4) + " m (coarse-graining factor " +
              io::format_number(calibration.coarse_graining_factor, 4) + "), this run's are " +
              io::format_number(particle_radius, 4) + " m (factor " + io::format_number(dem_case.factor_at_tools(), 4) +
              "): W and the footprint hold for the particle size they were fitted at (the knife-bed's total wear "
              "falls 1.88x from 27.5 to 9.2 mm pellets, docs/coarse-graining.md); run at the calibrated size");
            ctx.log.warning(warnings.back());
          }
      }
    if (s.smoothing <= 0 && source_choice->from_particles())
      s.smoothing = wear.particle_radius;
    if (!smoothing_checked && s.smoothing > 0 && s.smoothing < 0.5 * part_parameters.mesh_size)
      ctx.log.warning("Lifetime/Smoothing radius (" + io::format_number(s.smoothing) + " m) is below half the "
                      "Part/Mesh size (" + io::format_number(part_parameters.mesh_size) + " m): wear narrower "
                      "than a cell is carried by single vertices, which can fold the worn surface where it "
                      "concentrates (an edge, a tip)");
    if (!smoothing_checked && calibration.smoothing_radius > 0 &&
        std::abs(s.smoothing / calibration.smoothing_radius - 1) > 0.01)
      {
        warnings.push_back("Lifetime/Calibration was fitted with a footprint (Smoothing radius) of " +
                           io::format_number(calibration.smoothing_radius, 4) + " m, this run's is " +
                           io::format_number(s.smoothing, 4) + " m: W holds for the footprint and particle size it "
                           "was fitted at (a depth or recession scales with both); run at the calibrated one");
        ctx.log.warning(warnings.back());
      }
    smoothing_checked = true;
  }

  // 2. Filtered on the surface (volume conserving), divided by the vertex areas: depth per cycle.
  Rates LifetimeLoop::filter(const CycleWear &wear)
  {
    io::ScopedTimer t(ctx.timers, "filter");
    tonnes_per_cycle_now = wear.tonnes_per_cycle;
    return depth_rates(part_model->surface(), wear, s.smoothing);
  }

  // 3. How many cycles this update stands for: sized from the previous update's largest rate,
  //    not from the beds that then move the part (update_size.h: sized by its own beds, the
  //    life was biased long by about c^2 / beds, +9 to +23 % at the DEM's bed spreads).
  long LifetimeLoop::choose_cycles(const Rates &rates) const
  {
    long n = cycles_for_update(s.fixed_cycles, s.fraction, part_parameters.mesh_size, previous_largest, rates.largest);
    if (s.target_tonnes > 0 && tonnes_per_cycle_now > 0) // the last update ends at the target
      n = std::max(1L, std::min(n, long(std::ceil((s.target_tonnes - tonnes) / tonnes_per_cycle_now))));
    return n;
  }

  // 4. Move the part. A surface that cannot be remeshed (it folds where the wear is deepest)
  //    rejects the step: the part goes back to its last checkpoint (the state before this
  //    update) and the update is retried with half the cycles, up to three times; if that fails
  //    too, the part stays at the checkpoint and the run ends there. Under MPI every rank moves
  //    its own copy of the part: the ranks agree on the outcome (a failure on one is a failure
  //    on all), so that their parts stay the same.
  LifetimeLoop::Step LifetimeLoop::move_part(const Rates &rates, long n)
  {
    Step st;
    st.volume_before = part_model->volume();
    st.beds          = rates_at_places(rates, n);
    st.before        = part_model->surface();
    int halvings     = 0;
    for (int attempt = 0;; ++attempt)
      {
        const std::string error = agreed_by_the_ranks(try_to_move(st, rates, n, attempt));
        if (error.empty())
          {
            st.moved = true;
            log_how_it_moved(st.result);
            break;
          }
        if (attempt == 3 || n == 1)
          {
            part_model->load(checkpoints->part_file(update - 1)); // the rejected step leaves no trace
            st.error = "the worn surface could not be remeshed at update " + std::to_string(update) +
                       (halvings ? ", also with " + std::to_string(n) + " cycles after " + std::to_string(halvings) +
                                     " halving(s)"
                                 : std::string()) +
                       " (" + error +
                       "; it folds where the wear is deepest; a larger Lifetime/Smoothing radius or a finer "
                       "Part/Mesh size helps)";
            return st;
          }
        n = std::max(1L, n / 2);
        ++halvings;
        ctx.log.warning("update " + std::to_string(update) + ": " + error + "; retried with " + std::to_string(n) +
                        " cycles");
      }
    st.cycles = st.beds.cycles = n;
    if (!st.result.worn_through.empty())
      note_worn_through(st, rates, n);
    return st;
  }

  std::string LifetimeLoop::try_to_move(Step &st, const Rates &rates, long n, int attempt)
  {
    std::vector<double> depth(rates.mean.size());
    for (std::size_t v = 0; v < depth.size(); ++v)
      depth[v] = n * rates.mean[v];
    try
      {
        io::ScopedTimer t(ctx.timers, "fem update");
        if (attempt > 0)
          part_model->load(checkpoints->part_file(update - 1));
        // the moved vertices are exact where they do not fold, and a smaller step often
        // does not: the surface is built anew as a set only from the third attempt on
        // a source of volumes (the DEM's): the part loses exactly the volume worn
        st.result = part_model->apply_wear(depth, attempt >= 2 || n == 1,
                                           source->removes_volume() ? n * rates.wear_volume : 0.0);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }

  std::string LifetimeLoop::agreed_by_the_ranks(std::string error) const
  {
    // every rank moved its own copy: one whose Gmsh failed where another's did not (a time
    // limit) took another way, and the copies would part; the same volume and vertex count
    // on all ranks, or the step is rejected everywhere
    // (collective: every rank asks, a failed one with -1)
    const dem::Parallel ranks = dem::Parallel::world();
    if (ranks.size() > 1)
      {
        const bool   moved    = error.empty();
        const double volume   = moved ? part_model->volume() : -1;
        const double vertices = moved ? double(part_model->surface().vertices.size()) : -1;
        const bool   differ   = ranks.max(volume) != ranks.min(volume) || ranks.max(vertices) != ranks.min(vertices);
        if (moved && differ)
          error = "the MPI ranks' parts differ after the update (a remesh went another way on one)";
      }
    if (!(ranks.max(error.empty() ? 0.0 : 1.0) > 0))
      return "";
    return error.empty() ? "the part could not be moved on another MPI rank" : error;
  }

  void LifetimeLoop::log_how_it_moved(const fem::PartModel::UpdateResult &result)
  {
    const std::string at = "update " + std::to_string(update) + ": ";
    if (!result.meshed_first.empty())
      ctx.log.line(at + "the part meshed anew before its vertices moved (" + result.meshed_first + ")");
    if (!result.rebuilt.empty())
      ctx.log.line(at + "the worn surface built anew (" + result.rebuilt + ")" +
                   (result.volume_cut_off > 0
                      ? "; " + io::format_number(result.volume_cut_off * 1e6) + " cm^3 cut off by the wear"
                      : std::string()));
    if (!result.volume_note.empty())
      ctx.log.warning(at + result.volume_note);
    if (!result.surface_kept.empty())
      {
        ++surfaces_kept;
        ctx.log.warning(at + result.surface_kept);
      }
  }

  void LifetimeLoop::note_worn_through(const Step &st, const Rates &rates, long n)
  {
    // end of life within this update: where the depth increment first reaches the local
    // thickness, as a fraction of the update
    const auto thickness = fem::local_thickness(st.before);
    double     fraction  = 1;
    unsigned   first     = st.result.worn_through.front();
    for (unsigned v : st.result.worn_through)
      if (rates.mean[v] > 0 && thickness[v] / (n * rates.mean[v]) < fraction)
        fraction = thickness[v] / (n * rates.mean[v]), first = v;
    worn_through        = true;
    worn_through_tonnes = tonnes + fraction * n * tonnes_per_cycle_now;
    end                 = "worn through within update " + std::to_string(update);
    const auto &p       = st.before.vertices[first];
    deepest             = {p[0], p[1], p[2]};
    // the other criteria within the same update, as the whole update would have left them
    // (the depth and the worn mass: projected()); whichever is reached first ends life
    TrajectoryPoint next = history.back();
    next.tonnes          = tonnes + n * tonnes_per_cycle_now;
    const PartNow now    = part_now();
    for (std::size_t c = 0; c < criteria.size(); ++c)
      next.values[c] = criteria[c]->projected(now, st.beds, next.values[c]);
    worn_through_rival = history;
    worn_through_rival.push_back(next);
  }

  // 5. Record: the wear depth below the design, volumes, followed points; each criterion's
  //    update record (its value, the beds' relative variance of its rate at the place that ends
  //    life, chosen on the beds' mean) for the interval.
  double LifetimeLoop::add_update_records(const PartNow &part, const Step &st)
  {
    const auto &now = history.back();
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        const std::vector<double> bed_rates = criteria[c]->bed_rates(part, st.beds);
        records[c].push_back(
          {now.tonnes, now.values[c], bed_rates.size(), relative_variance(bed_rates), beds_of_update, bed_rates});
      }
    return std::sqrt(records[criterion_named(depth_name)].back().relative_variance);
  }

  // 5b. The worst of many places: each criterion's quantity at all its places and the beds'
  //     rates there, for the factor on its interval (place_scatter.h): the depth at the points
  //     the design's vertices moved to, the followed points' recession, the gauge's stations'
  //     edge recession and plate thickness lost. (The worn mass is one quantity: factor 1.)
  void LifetimeLoop::add_place_scatter(const PartNow &part, const Rates &rates, const Step &st)
  {
    const std::size_t beds = rates.seed.size();
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        Places               p      = criteria[c]->places(part, st.beds);
        std::vector<double> &now    = p.values;
        std::vector<double> &before = place_values[c];
        if (before.empty())
          before.assign(now.size(), 0.0);
        if (before.size() != now.size())
          continue; // (the places cannot change: a criterion without them)
        std::vector<double> increment(now.size());
        for (std::size_t k = 0; k < now.size(); ++k)
          {
            if (!std::isfinite(now[k]))
              now[k] = before[k]; // (no reading there)
            increment[k] = now[k] - before[k];
          }
        place_scatter[c].add_update(increment, beds > 1 ? p.bed_rates : std::vector<std::vector<double>>());
        before          = now;
        place_factor[c] = place_scatter[c].maximum_factor(now);
      }
  }

  PartNow LifetimeLoop::part_now() const
  {
    return {*part_model,
            s.recession_points,
            sections,
            design_at_sections,
            gauge(sections, design_at_sections),
            design_thickness,
            s.gauge_height,
            frame.z0 + s.gauge_height,
            volume0,
            part_parameters.density};
  }

  PartNow LifetimeLoop::design_now() const
  {
    return {*part_model,
            s.recession_points,
            design_sections,
            design_sections,
            gauge(design_sections, design_sections),
            design_thickness,
            s.gauge_height,
            frame.z0 + s.gauge_height,
            part_model->volume(),
            part_parameters.density};
  }

  std::size_t LifetimeLoop::criterion_named(const std::string &name) const
  {
    for (std::size_t c = 0; c < criteria.size(); ++c)
      if (criteria[c]->name() == name)
        return c;
    throw std::logic_error("the end-of-life criterion '" + name + "' is not registered");
  }

  // Before the move: the wear depth, and each bed's depth rate where the criteria read the
  // part: the followed points, the points the design's vertices moved to (more than one bed),
  // the gauges' stations (interpolated on the surface: what moves those points; 0 where there
  // is no section).
  BedRates LifetimeLoop::rates_at_places(const Rates &rates, long n) const
  {
    BedRates b;
    b.cycles       = n;
    b.rates        = &rates;
    b.depth_before = part_model->wear_depth();
    for (const auto &seed : rates.seed)
      b.followed.push_back(part_model->at_followed_points(seed, s.recession_points));
    if (rates.seed.size() > 1) // (one bed: no scatter to keep)
      for (const auto &seed : rates.seed)
        b.design_points.push_back(part_model->at_followed_points(seed, part_model->design_surface().vertices));
    // where the gauges read the part now (its sections after the last update)
    const std::size_t stations = sections.x.size();
    const double      z        = frame.z0 + s.gauge_height;
    fem::SolidSurface at;
    std::vector<bool> edge(stations), faces(stations);
    for (std::size_t i = 0; i < stations; ++i)
      {
        edge[i]  = std::isfinite(sections.height[i]);
        faces[i] = std::isfinite(sections.y_low[i]) && std::isfinite(sections.y_high[i]);
        at.vertices.push_back(edge[i] ? sections.lowest[i] : part_model->surface().vertices.front());
        at.vertices.push_back(faces[i] ? dealii::Point<3>(sections.x[i], sections.y_low[i], z) : at.vertices.back());
        at.vertices.push_back(faces[i] ? dealii::Point<3>(sections.x[i], sections.y_high[i], z) : at.vertices.back());
      }
    const fem::SurfaceTransfer transfer(part_model->surface(), at);
    for (const auto &seed : rates.seed)
      {
        const auto there = transfer(seed);
        b.edge.emplace_back(stations, 0.0), b.faces.emplace_back(stations, 0.0);
        for (std::size_t i = 0; i < stations; ++i)
          {
            b.edge.back()[i]  = edge[i] ? there[3 * i] : 0.0;
            b.faces.back()[i] = faces[i] ? 0.5 * (there[3 * i + 1] + there[3 * i + 2]) : 0.0;
          }
      }
    return b;
  }

  void LifetimeLoop::gauge_the_part()
  {
    std::tie(sections, design_at_sections) = worn_and_design_sections(part_model->surface(), part_model->design_surface(),
                                                                      int(s.gauge_stations), frame.z0 + s.gauge_height,
                                                                      part_parameters.mesh_size);
  }

  LifeInterval LifetimeLoop::current_interval(const EndOfLife &e) const
  {
    if (e.criterion == EndOfLife::none)
      return {};
    return life_interval(limits[e.criterion].limit, records[e.criterion], 0.95, place_factor[e.criterion]);
  }

  // Lifetime/Target interval: while the life's interval is wider than asked, the next updates
  //    draw more beds (the variance an update adds falls as 1 / beds), up to Maximum beds.
  void LifetimeLoop::choose_beds()
  {
    if (!(s.target_interval > 0))
      return;
    const LifeInterval li   = current_interval(end_of_life(limits, history));
    long               want = beds_now;
    // with few degrees of freedom the interval is mostly t's width and the one-update
    // extrapolation's: three beds until it has four, then at most twice the beds per update
    // (the past updates' share of the variance stays; more beds only shrink the rest)
    if (li.dof < 4)
      want = std::max(beds_now, 3L);
    else if (li.relative_half_width > s.target_interval)
      want = std::min(2 * beds_now, long(std::ceil(beds_now * std::pow(li.relative_half_width / s.target_interval, 2))));
    want = std::min(want, s.max_beds);
    if (want > beds_now)
      {
        ctx.log.line("update " + std::to_string(update) + ": the life's interval is +-" +
                     io::format_number(100 * li.relative_half_width, 3) + " %, the target +-" +
                     io::format_number(100 * s.target_interval, 3) + " %: " + std::to_string(want) +
                     " beds from the next update");
        beds_now = want;
      }
  }

  void LifetimeLoop::record(const CycleWear &wear, const Rates &rates, const Step &st)
  {
    const long n = st.cycles;
    cycles += n;
    tonnes += n * wear.tonnes_per_cycle;
    wear_total += n * rates.wear_volume;

    const fem::SolidSurface &surface = part_model->surface();
    const auto               depth   = part_model->wear_depth();
    const auto               area    = fem::vertex_areas(surface, fem::wearable_boundary);
    std::size_t              at      = 0;
    double                   area_sum = 0, depth_area = 0;
    for (std::size_t v = 0; v < depth.size(); ++v)
      {
        if (depth[v] > depth[at])
          at = v;
        area_sum += area[v], depth_area += area[v] * depth[v];
      }
    deepest = {surface.vertices[at][0], surface.vertices[at][1], surface.vertices[at][2]};
    const auto  &travel    = part_model->vertex_displacement();
    const double dmax      = depth[at];
    const auto   recession = part_model->recession_at(s.recession_points);
    const double volume    = part_model->volume(); // (an integral over the whole mesh)
    const double worn      = volume0 - volume;
    const double swept     = st.volume_before - volume;
    gauge_the_part();
    const PartNow   part = part_now(); // (the part as the criteria read it after this update)
    const EdgeGauge &g   = part.gauge;
    history.push_back({tonnes, {}});
    for (const auto &c : criteria)
      history.back().values.push_back(c->value(part));
    const double spread = add_update_records(part, st);
    add_place_scatter(part, rates, st);

    // the row by column name (the header: set_up)
    std::vector<std::pair<std::string, double>> row = {
      {"update", double(update)},
      {"cycles", double(cycles)},
      {"tonnes", tonnes},
      {"max_depth", dmax},
      {"mean_depth", area_sum > 0 ? depth_area / area_sum : 0.0},
      {"max_vertex_displacement", *std::max_element(travel.begin(), travel.end())},
      {"worn_volume", worn},
      {"worn_mass", worn * part_parameters.density},
      {field_columns.volume, n * rates.wear_volume},
      {field_columns.swept_over, swept / (n * rates.wear_volume)},
      {"min_scaled_jacobian", st.result.quality.min_scaled_jacobian},
      {"remeshed", st.result.remeshed ? 1.0 : 0.0},
      {"wear_rate_spread", spread},
      {"tonnes_per_cycle", wear.tonnes_per_cycle},
      {"deepest_x", deepest[0]},
      {"deepest_y", deepest[1]},
      {"deepest_z", deepest[2]},
      {"dem_warnings", double(dem_warnings_now)},
      {"beds", double(rates.seed.size())},
      {"edge_recession", g.recession},
      {"edge_recession_x", sections.x[g.recession_station]},
      {"plate_thickness", g.thinnest},
      {"plate_thickness_x", sections.x[g.thinnest_station]}};
    const auto &phases = source->phases();
    for (std::size_t k = 0; k < wear.phase_volume.size(); ++k) // (a count that differs: CsvWriter says which)
      row.push_back({field_columns.volume + "_" + (k < phases.size() ? phases[k] : std::to_string(k)), n * wear.phase_volume[k]});
    const auto point_depth = part_model->wear_depth_below(s.recession_points);
    for (std::size_t p = 0; p < recession.size(); ++p)
      {
        const std::string number = p == 0 ? std::string() : "_" + std::to_string(p + 1);
        row.push_back({"point_recession" + number, recession[p]});
        row.push_back({"point_depth" + number, point_depth[p]});
      }
    trajectory_rows.push_back(trajectory.named_row(row));
    trajectory.flush();

    const std::string folder = ctx.output.part_folder(ctx.resume);
    write_profiles(surface, part_model->design_surface(), frame, s.planes, update, ctx.output.file(folder));
    part_model->write(*part_output, tonnes);
    io::write_stl(ctx.output.file(folder + "/" + part_surface_name(folder, update)), surface.as_polydata());
    log_update(rates, st, dmax, swept);
  }
  /// The update's line in the log, with the remesh's share of the swept volume, and a warning
  /// when the part did not lose the volume worn.
  void LifetimeLoop::log_update(const Rates &rates, const Step &st, double dmax, double swept)
  {
    const long  n      = st.cycles;
    const auto &travel = part_model->vertex_displacement();
    std::ostringstream line;
    line << "update " << update << ": " << n << " cycles (" << tonnes << " t), wear depth " << dmax
         << " m (largest vertex displacement " << *std::max_element(travel.begin(), travel.end())
         << " m), swept/" << field_columns.volume << " " << swept / (n * rates.wear_volume) << (st.result.remeshed ? ", remeshed" : "");
    // the depth scaled so that the offset surface removes the volume worn
    if (st.result.offset_scale != 1)
      line << " (the depth x " << io::format_number(st.result.offset_scale) << " to remove the volume worn)";
    // the remesh's own share of the swept volume (Gmsh's new surface inscribed in the old one):
    // of a remesh before the step, taken off the step's volume; of one after it, not
    const double taken_off = st.result.remesh_volume_taken_off;
    if (taken_off != 0)
      line << " (a remesh before the step took " << io::format_number(-taken_off / (n * rates.wear_volume))
           << " of it, the step the rest)";
    if (const double after = st.result.remesh_volume_change - taken_off; after != 0)
      line << " (the remesh's own share " << io::format_number(-after / (n * rates.wear_volume)) << ")";
    ctx.log.line(line.str());
    // a source of volumes: every update removes the volume worn, remeshed or not (within 2 %)
    if (const double ratio = swept / (n * rates.wear_volume);
        source->removes_volume() && rates.wear_volume > 0 && std::abs(ratio - 1) > 0.02)
      {
        ++updates_off_volume;
        ctx.log.warning("update " + std::to_string(update) + ": the part lost " + io::format_number(ratio) +
                        " times the volume worn in it (" +
                        (st.result.rebuilt.empty() ? std::string("a remesh's own share or a depth that could not be "
                                                                 "scaled")
                                                   : std::string("its surface built anew as a set")) +
                        "); the worn mass at the end counts the volume lost");
      }
  }


  // 6. Checkpoint: the part and the loop's state, written aside and then renamed, so that a
  //    kill never leaves half of one (lifetime/checkpoints.h).
  void LifetimeLoop::checkpoint()
  {
    part_model->save(checkpoints->part_file_aside(update));
    StateFile state;
    state.set("format", state_format);
    state.set("parameter_hash", hash);
    state.set("update", double(update));
    state.set("cycles", double(cycles));
    state.set("tonnes", tonnes);
    state.set("wear_total", wear_total);
    state.set("smoothing_radius", s.smoothing);
    state.set("design_volume", volume0);
    state.set("deepest_point", deepest);
    state.set("beds_next", double(beds_now));
    state.set("previous_largest_rate", previous_largest);
    std::vector<double> t;
    for (const auto &p : history)
      t.push_back(p.tonnes);
    state.set("history_tonnes", t);
    for (std::size_t c = 0; c < criteria.size(); ++c)
      {
        const std::string   key = state_key(*criteria[c]);
        std::vector<double> v;
        for (const auto &p : history)
          v.push_back(p.values[c]);
        state.set("history_" + key, v);
        std::vector<double> beds, var, seeds, rates; // (the last two: every update's beds, one after another)
        for (const auto &r : records[c])
          {
            beds.push_back(double(r.beds)), var.push_back(r.relative_variance);
            seeds.insert(seeds.end(), r.bed_seeds.begin(), r.bed_seeds.end());
            rates.insert(rates.end(), r.bed_rates.begin(), r.bed_rates.end());
          }
        state.set("record_beds_" + key, beds);
        state.set("record_relative_variance_" + key, var);
        state.set("record_bed_seeds_" + key, seeds);
        state.set("record_bed_rates_" + key, rates);
        state.set("place_scatter_" + key, place_scatter[c].numbers());
        state.set("place_values_" + key, place_values[c]);
        state.set("place_factor_" + key, place_factor[c]);
      }
    for (std::size_t k = 0; k < trajectory_rows.size(); ++k)
      state.set("trajectory_row_" + std::to_string(k + 1), trajectory_rows[k]);
    state.write(checkpoints->state_file_aside(update));
    checkpoints->commit(update);
  }

  bool LifetimeLoop::stop_here()
  {
    const EndOfLife e = end_of_life(limits, history);
    if (e.reached)
      {
        end = limits[e.criterion].name + " reached";
        return true;
      }
    if (s.target_tonnes > 0 && tonnes >= s.target_tonnes)
      {
        end = "target tonnes reached";
        return true;
      }
    return false;
  }

  // ---------------------------------------------------------------------------------------------
  // The end: the life from the whole trajectory (reached or extrapolated) and its interval, in
  // summary.json, the figures and the log.
  void LifetimeLoop::finish()
  {
    const FinalLife f = final_life();
    write_results(f);
    if (history.size() > 1) // nothing to plot before the first update
      plot(f);
    conclude(f);
  }

  /// Which criterion ended the life, when, where, and its interval (the plate worn through
  /// before or after a limit's crossing; the calibration's share).
  LifetimeLoop::FinalLife LifetimeLoop::final_life()
  {
    FinalLife    f;
    EndOfLife   &e = f.e;
    e              = end_of_life(limits, history);
    std::string &criterion = f.criterion, &method = f.method;
    std::vector<double> &where = f.where;
    LifeInterval        &li    = f.li;
    const std::vector<UpdateRecord> *&interval_records = f.interval_records;
    criterion = e.criterion == EndOfLife::none ? "none" : limits[e.criterion].name;
    method    = e.reached ? "interpolated within update " + std::to_string(e.update)
                                      : (e.extrapolated ? "extrapolated past the last update by the recent course's power "
                                                          "law (exponent " + io::format_number(e.exponent, 3) + ")"
                                                        : "none");
    // where: the criterion's place on the part as it is (the deepest point: the plate worn
    // through, or no criterion)
    where = e.criterion != EndOfLife::none && !worn_through ? criteria[e.criterion]->where(part_now(), deepest, false)
                                                            : deepest;
    li    = current_interval(e);
    // the updates the interval came from (their beds pair this run with another: life_beds.csv)
    interval_records = e.criterion == EndOfLife::none ? nullptr : &records[e.criterion];
    // an interval found for another life, carried to @p tonnes (relative, as it is)
    auto carried_to = [](LifeInterval i, double tonnes) {
      const double scale = i.life.tonnes > 0 ? tonnes / i.life.tonnes : 0.0;
      i.life.tonnes = tonnes, i.low *= scale, i.high *= scale;
      return i;
    };
    if (worn_through)
      if (const EndOfLife rival = end_of_life(limits, worn_through_rival);
          rival.reached && rival.tonnes < worn_through_tonnes)
        {
          e = rival, criterion = limits[e.criterion].name;
          method = "interpolated within update " + std::to_string(e.update) + " (before the plate wears through)";
          end    = criterion + " reached";
          where  = criteria[e.criterion]->where(part_now(), deepest, true);
          // its interval: relative, from the updates recorded before the last one
          li = carried_to(life_interval(limits[e.criterion].limit, records[e.criterion]), e.tonnes);
          interval_records = &records[e.criterion];
          worn_through = false;
        }
    if (worn_through && (!e.reached || worn_through_tonnes < e.tonnes))
      {
        e.tonnes = worn_through_tonnes, e.reached = true, e.extrapolated = false;
        criterion = "worn through", method = "interpolated within update " + std::to_string(update);
        // its interval: the depth's, relative, at the last update recorded before it
        const std::size_t depth = criterion_named(depth_name);
        li = carried_to(records[depth].empty() ? LifeInterval{}
                                               : life_interval(history.back().values[depth], records[depth]),
                        worn_through_tonnes);
        interval_records = &records[depth];
      }
    // the calibrated W's uncertainty (Lifetime/Calibration): a component of its own
    li = add_calibration(li, calibration.relative_sd, calibration.dof);
    return f;
  }

  /// summary.json's results.lifetime: the life, its interval and its parts, the run's totals,
  /// the warnings.
  void LifetimeLoop::write_results(const FinalLife &f)
  {
    io::Json &r = ctx.results["lifetime"];
    write_totals(r);
    write_life(r, f);
    write_interval(r, f.li);
    write_warnings(r, f.li);
  }

  /// What the run did: cycles, tonnes, the wear, the remeshes, where its wear came from.
  void LifetimeLoop::write_totals(io::Json &r) const
  {
    const auto  &depth = part_model->wear_depth();
    const auto  &travel = part_model->vertex_displacement();
    r["end"]           = end;
    r["cycles"]        = cycles;
    r["tonnes"]        = tonnes;
    r["max_depth"]     = depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
    r["max_vertex_displacement"] = travel.empty() ? 0.0 : *std::max_element(travel.begin(), travel.end());
    const double worn  = volume0 - part_model->volume();
    r["worn_volume"]   = worn;
    r["worn_mass"]     = worn * part_parameters.density;
    r[field_columns.volume]    = wear_total; // (named after the Wear field: archard_volume)
    r[field_columns.worn_over] = wear_total > 0 ? worn / wear_total : 0.0;
    r["remeshes"]      = static_cast<long>(part_model->n_remeshes());
    r["dem_warnings"]  = dem_warnings_total; // overlaps, lost particles, time step (this run; per update: trajectory.csv)
    // remeshes where Gmsh could not remesh the surface and the volume was filled inside it
    r["remeshes_inside_worn_surface"] = surfaces_kept;
    r["updates_off_volume"]           = updates_off_volume;
    r["smoothing_radius"] = s.smoothing;
    r["part"]             = part_parameters.from_file ? "part" : "knife"; // (what the report calls it)
    if (particle_radius > 0) // (the size W and the footprint hold for: docs/coarse-graining.md)
      r["particle_radius"] = particle_radius;
    r["coarse_graining_factor"] = dem_case.factor_at_tools(); // (a multi-level bed: the finest level's)
    r["wear_source"]      = source_choice->name();
    source_choice->add_results(r);
    r["wear_field"] = dem_case.wear_field;
    if (source->wear_coefficient() > 0) // the coefficient the depths scale with (abrade calibrate rescales it)
      {
        r["wear_coefficient"] = source->wear_coefficient();
        if (dem_case.wear_field == "archard_volume")
          r["archard_coefficient"] = source->wear_coefficient();
      }
  }

  /// The end of life: when, by which criterion, where; the beds behind it.
  void LifetimeLoop::write_life(io::Json &r, const FinalLife &f)
  {
    const EndOfLife    &e = f.e;
    const LifeInterval &li = f.li;
    if (e.criterion != EndOfLife::none)
      r["predicted_tonnes_to_end_of_life"] = e.tonnes;
    r["end_of_life_criterion"]           = f.criterion;
    r["end_of_life_method"]              = f.method;
    r["end_of_life_where"]               = f.where;
    r["extrapolated"]                    = e.extrapolated;
    r["seeds"]                           = static_cast<long>(s.seeds.size());
    std::vector<double> beds_per_update;
    for (const auto &u : records[criterion_named(depth_name)])
      beds_per_update.push_back(double(u.beds));
    r["beds_per_update"]                 = beds_per_update;
    r["wear_rate_relative_spread"]       = li.bed_relative_sd; // one bed's, at the place that ends life
    // the beds' relative standard deviation of the whole part's worn volume, as one bed's over
    // the run (abrade calibrate divides it by sqrt(seeds) for its replicate part)
    if (const std::size_t mass = criterion_named(mass_name);
        !records[mass].empty() && history.back().values[mass] > 0)
      {
        // c sqrt(sum dQ_u^2 / n_u) / Q_U: the relative standard error of the worn volume,
        // times sqrt(seeds)
        const auto [c2, dof] = pooled_relative_variance(records[mass]);
        double     sum = 0, before = 0;
        for (const auto &u : records[mass])
          sum += (u.value - before) * (u.value - before) / double(u.beds), before = u.value;
        r["worn_volume_relative_spread"] =
          std::sqrt(c2 * sum) / history.back().values[mass] * std::sqrt(double(s.seeds.size()));
      }
    r["confidence"] = li.confidence;
    // every update's beds at the place that ends life and the life's elasticity to each update:
    // `abrade concepts` pairs two runs' lives on them (paired_life.h)
    if (f.interval_records && li.life.tonnes > 0)
      write_life_beds(ctx.output.file("life_beds.csv"), life_beds(*f.interval_records, li));
    else
      std::filesystem::remove(ctx.output.file("life_beds.csv")); // (none: no older one left standing)
    if (li.dof >= 1 && li.life.tonnes > 0)
      {
        r["predicted_tonnes_low"]  = li.low;
        r["predicted_tonnes_high"] = li.high;
        r["relative_half_width"]   = li.relative_half_width;
      }
  }

  /// The life's 95 % interval, its components, the calibration it holds, the target.
  void LifetimeLoop::write_interval(io::Json &r, const LifeInterval &li)
  {
    io::Json &iv                = r["interval"];
    iv["method"]                = "the life from the whole trajectory (crossing, or a power law past the last update); "
                                  "its variance from every update's beds, carried by the gradient, interval on ln L "
                                  "with t(dof) (docs/lifetime.md)";
    iv["degrees_of_freedom"]    = li.dof;
    iv["bed_relative_sd"]       = li.bed_relative_sd;
    iv["relative_sd"]           = li.relative_sd;
    iv["components"]["beds"]          = li.relative_sd_beds;
    iv["components"]["extrapolation"] = li.relative_sd_extrapolation;
    iv["components"]["calibration"]   = li.relative_sd_calibration; // W (Lifetime/Calibration; the footprint: not yet)
    if (calibration.coefficient > 0)
      {
        io::Json &c             = r["calibration"];
        c["file"]               = calibration.file;
        c["run"]                = calibration.run;
        c["wear_coefficient"]   = calibration.coefficient;
        c["relative_sd"]        = calibration.relative_sd;
        c["degrees_of_freedom"] = calibration.dof;
        c["smoothing_radius"]   = calibration.smoothing_radius;
        c["footprint_fitted"]   = calibration.footprint;
        c["footprint_relative_sd"] = calibration.footprint_relative_sd;
      }
    // the worst of many places scatters less than one: the beds' variance at the leading place
    // scaled by phi^2 (place_scatter.h)
    iv["worst_place_factor"] = std::sqrt(li.place_factor);
    if (s.target_interval > 0)
      {
        const bool met = li.dof >= 1 && li.relative_half_width <= s.target_interval;
        iv["target_relative_half_width"] = s.target_interval;
        iv["target_met"]                 = met;
        if (!met)
          warnings.push_back("Lifetime/Target interval +-" + io::format_number(100 * s.target_interval, 3) +
                             " % not met (+-" + io::format_number(100 * li.relative_half_width, 3) + " % with at most " +
                             std::to_string(s.max_beds) + " beds per update): " +
                             (li.relative_sd_calibration >= li.relative_sd_beds
                                ? "the calibration's share (" + io::format_number(100 * li.relative_sd_calibration, 3) +
                                    " %) is the larger, and beds do not narrow it: a better calibration does"
                                : std::string("a larger Maximum beds narrows it")));
      }
  }

  /// The run's warnings, into summary.json (and the interval's and the DEM's onto the terminal).
  void LifetimeLoop::write_warnings(io::Json &r, const LifeInterval &li)
  {
    if (li.dof < 1)
      warnings.push_back("one bed per update: the predicted life has no interval; set Lifetime/Seeds = 1, 2, 3 (three "
                         "or more beds) or a Lifetime/Target interval");
    r["warnings"] = std::vector<double>{};
    for (const auto &w : warnings)
      {
        r["warnings"].push_back(w);
        if (w.rfind("one bed per update", 0) == 0 || w.rfind("Lifetime/Target interval", 0) == 0)
          ctx.log.warning(w);
      }
    if (dem_warnings_total > 0)
      ctx.log.warning(std::to_string(dem_warnings_total) +
                      " DEM warning(s) in this run's cycles (Simulation/On error = continue): the life rests on "
                      "cycles the DEM flagged; log.txt names each kind, trajectory.csv counts them per update");
  }


  /// trajectory.png and the cross-sections, the one through where the life ended with the
  /// quantity that ended it drawn.
  void LifetimeLoop::plot(const FinalLife &f)
  {
    const EndOfLife           &e     = f.e;
    const std::vector<double> &where = f.where;
    TrajectoryMarks marks;
    for (const auto &c : criteria)
      c->mark_limit(marks);
    marks.recession_points = std::max<std::size_t>(1, s.recession_points.size());
    if (e.extrapolated && criteria[e.criterion]->drawn_in_trajectory())
      {
        marks.extrapolated = true;
        marks.last_tonnes  = history.back().tonnes;
        marks.last_value   = history.back().values[e.criterion];
        marks.life         = e.tonnes;
        marks.limit        = limits[e.criterion].limit;
      }
    // the cross-section through the place that ended the life, the quantity drawn there
    WorstSection worst;
    worst.where   = where.size() == 3 ? where : deepest;
    worst.updates = long(history.size()) - 1;
    const auto mm = [](double v) { return io::format_number(1000 * v, 4) + " mm"; };
    const int  c  = e.criterion == EndOfLife::none || worn_through ? -1 : int(e.criterion);
    const std::string after = " after update " + std::to_string(worst.updates);
    const double      depth = history.back().values[criterion_named(depth_name)];
    if (c >= 0 && !criteria[c]->section_label().empty())
      worst.mark.text = criteria[c]->section_label() + mm(history.back().values[c]) + after + " (end of life at " +
                        mm(limits[c].limit) + ")";
    else
      worst.mark.text = worn_through ? "worn through (circled); the largest depth below the design " + mm(depth) + after
                                     : (c >= 0 ? criteria[c]->whole_part_note() : std::string()) +
                                         "the deepest point, " + mm(depth) + " below the design" + after;
    if (c >= 0)
      criteria[c]->section_drawing(worst.mark);
    else
      worst.mark.to_design = true;
    plot_lifetime(ctx.output.root(), s.planes, frame, marks, &worst);
  }

  /// The life's line in the log, or the error of a run that predicts none.
  void LifetimeLoop::conclude(const FinalLife &f)
  {
    const EndOfLife    &e = f.e;
    const LifeInterval &li = f.li;
    std::ostringstream line;
    if (e.criterion != EndOfLife::none && !e.reached && end.rfind("no wear", 0) == 0)
      {
        // the wear stopped (a cycle that no longer touches the part, a rate that ends): the
        // life would be extrapolated from wear that no longer happens
        ctx.log.line("Lifetime: " + end + " after " + std::to_string(cycles) + " cycles; no life predicted");
        throw RunError("no life predicted: the part stopped wearing after " + io::format_number(tonnes, 6) +
                       " t (" + end + "); the end of life is not reached");
      }
    if (e.criterion == EndOfLife::none)
      {
        // no criterion grew: there is no life to report, and a run that predicts none has failed
        // (its outputs so far are written); the summary says so, the exit code is 3
        ctx.log.line("Lifetime: " + end + " after " + std::to_string(cycles) + " cycles; no life predicted");
        throw RunError("no life predicted: " + end + " after " + std::to_string(cycles) +
                       " cycles (no end-of-life criterion grows)");
      }
    line << "Lifetime: " << end << " after " << cycles << " cycles; predicted life " << e.tonnes << " t ("
         << describe(e, limits) << ")";
    if (li.dof >= 1 && e.tonnes > 0)
      line << ", " << 100 * li.confidence << " % interval " << li.low << " ... " << li.high << " t (+-"
           << io::format_number(100 * li.relative_half_width, 3) << " %, " << li.dof << " degrees of freedom)";
    ctx.log.line(line.str());
  }
} // namespace abrade::coupling::lifetime
