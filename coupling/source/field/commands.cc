// The command lines of `abrade compare` and `abrade calibrate`: their options, usage texts and
// runs (field/commands.h).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/external.h>
#include <abrade/common/json.h>
#include <abrade/common/output_directory.h>
#include <abrade/field/calibration.h>
#include <abrade/field/footprint_fit.h>
#include <abrade/field/commands.h>
#include <abrade/field/compare.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <cmath>
#include <iostream>
#include <sstream>

namespace abrade::field
{
  const char *compare_usage = R"(  abrade compare --predicted WORN --scan SCAN [--reference DESIGN] --output DIR
                 [--scan-units auto|m|mm] [--register-on XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX]
                 [--no-coarse | --no-registration] [--profile-axis x|y|z] [--profile-planes A,B,...]
                 [--tonnes T]
      register a field scan (surface: .stl .ply .obj .vtp; point cloud: .ply .xyz .csv) to the
      predicted worn knife (.stl/.vtu of a run) or the design, and write the deviations
      (comparison.json, deviation.vtp, profile_*.csv/.png, measured_depths.csv)
)";
  const char *calibrate_usage = R"(  abrade calibrate --run DIR [--run DIR]... --measurements FILE.csv [--locations FILE.csv]
                   [--block SIZE] --output DIR
      fit the wear coefficient W of each lifetime run (Archard's, or its Output/Wear field's
      law's) to measured wear depths (columns
      tonnes, depth or depth_mm, x, y, z or location), with its 95 % interval (the fit's, over
      spatial blocks of SIZE m, default 0.05, and the run's bed-to-bed spread), and rank the
      runs by pattern agreement (calibration.json/.md, residuals.csv, calibration.png)
)";

  namespace
  {
    std::vector<double> numbers(const std::string &flag, const std::string &text, std::size_t count = 0)
    {
      std::vector<double> v;
      std::stringstream   s(text);
      std::string         item;
      while (std::getline(s, item, ','))
        {
          const auto x = io::finite_number(io::trimmed(item));
          if (!x)
            throw InputError(flag, "'" + item + "' is not a finite number");
          v.push_back(*x);
        }
      if (count && v.size() != count)
        throw InputError(flag, std::to_string(count) + " comma-separated numbers expected, got '" + text + "'");
      return v;
    }

    /// Walks the arguments: @p handle(flag, value-getter) returns false for an unknown flag.
    template <typename Handle>
    void parse(const std::vector<std::string> &args, const char *usage, Handle handle)
    {
      for (std::size_t k = 0; k < args.size(); ++k)
        {
          auto value = [&]() -> std::string {
            if (k + 1 >= args.size())
              throw InputError("command line", args[k] + " needs a value");
            if (args[k + 1].empty())
              throw InputError("command line", args[k] + " needs a value (it is empty)");
            return args[++k];
          };
          if (!handle(args[k], value))
            throw InputError("command line", "unknown option '" + args[k] + "'\nusage:\n" + usage);
        }
    }

    void print(const char *what, const DeviationStatistics &d)
    {
      std::printf("  %-20s %zu points: RMS %.3f mm, mean %+.3f mm, max %.3f mm, 95 %% %.3f mm, Hausdorff %.3f mm\n",
                  what, d.n, 1e3 * d.rms, 1e3 * d.mean, 1e3 * d.max_abs, 1e3 * d.p95, 1e3 * d.hausdorff);
    }
  } // namespace

  int run_compare_command(const std::vector<std::string> &args)
  {
    CompareSettings s;
    parse(args, compare_usage, [&](const std::string &flag, auto value) {
      if (flag == "--predicted")
        s.predicted = value();
      else if (flag == "--scan")
        s.scan = value();
      else if (flag == "--reference")
        s.reference = value();
      else if (flag == "--output" || flag == "-o")
        s.output = value();
      else if (flag == "--scan-units")
        s.scan_units = value();
      else if (flag == "--register-on")
        {
          const auto b         = numbers(flag, value(), 6);
          s.registration.region = Box{{b[0], b[1], b[2]}, {b[3], b[4], b[5]}};
        }
      else if (flag == "--no-coarse")
        s.registration.coarse = false;
      else if (flag == "--no-registration")
        s.registration.enabled = false;
      else if (flag == "--profile-axis")
        {
          const std::string a = value();
          if (a != "x" && a != "y" && a != "z")
            throw InputError(flag, "x, y or z expected, got '" + a + "'");
          s.profile_axis = a[0] - 'x';
        }
      else if (flag == "--profile-planes")
        s.profile_planes = numbers(flag, value());
      else if (flag == "--tonnes")
        {
          s.tonnes = numbers(flag, value(), 1)[0];
          if (!(s.tonnes > 0))
            throw InputError(flag, "the tonnes handled must be positive, got " + io::format_number(s.tonnes));
        }
      else
        return false;
      return true;
    });
    if (s.predicted.empty() || s.scan.empty() || s.output.empty())
      throw InputError("command line", std::string("compare needs --predicted, --scan and --output\nusage:\n") +
                                         compare_usage);
    const CompareResult r = compare(s);
    for (const auto &w : r.warnings)
      std::cerr << "warning: " << w << '\n';
    std::printf("Registered %s (%zu points; scale %g) with an RMS distance of %.3f mm\n", s.scan.c_str(),
                r.registration.points_used, r.scan_scale, 1e3 * r.registration.rms);
    if (s.registration.region)
      std::printf("  RMS distance in the registration region %.3f mm (%zu points), outside it %.3f mm (%zu points: "
                  "wear and misfit)\n",
                  1e3 * r.registration.rms_region, r.registration.points_region, 1e3 * r.registration.rms_rest,
                  r.registration.points_rest);
    print("scan to prediction:", r.to_predicted);
    if (r.has_reference)
      {
        print("scan to design:", r.to_reference);
        std::printf("  worn volume: measured %.4g cm^3, predicted %.4g cm^3 (%s)\n", 1e6 * r.measured_volume,
                    1e6 * r.predicted_volume, r.volume_method.c_str());
      }
    std::printf("Output in %s\n", s.output.c_str());
    return 0;
  }

  namespace
  {
    /// A run's correlation's 95 % interval (Fisher z, with the blocks as the independent
    /// samples; -1 ... 1 with too few blocks): can the data tell the runs apart? A run whose
    /// interval overlaps the best one's cannot be told apart from it by these measurements.
    std::pair<double, double> correlation_interval(const CalibrationResult &r)
    {
      if (r.blocks <= 3 || !(std::abs(r.correlation) < 1))
        return std::pair<double, double>{r.blocks <= 3 ? -1.0 : r.correlation, r.blocks <= 3 ? 1.0 : r.correlation};
      const double z = std::atanh(r.correlation), h = 1.959964 / std::sqrt(double(r.blocks - 3));
      return std::pair<double, double>{std::tanh(z - h), std::tanh(z + h)};
    }

    /// `abrade calibrate`: each run's W fitted to the measurements, the runs ranked by how well
    /// their pattern agrees, and W with the footprint fitted over the runs (footprint_fit.h).
    class Calibration
    {
    public:
      /// Reads the command line (errors: InputError naming the option).
      explicit Calibration(const std::vector<std::string> &args);

      int run()
      {
        open_outputs();
        fit_runs();
        rank_runs();
        fit_footprint_over_runs();
        write_results();
        return 0;
      }

    private:
      /// The measurements read, the output directory claimed, residuals.csv begun.
      void open_outputs();
      /// Each run's W and its residuals (residuals.csv); the warnings about each fit.
      void fit_runs();
      /// The runs by correlation, best first: calibration.md's table, calibration.json's runs,
      /// and the terminal.
      void rank_runs();
      /// W and the footprint together, from candidates at several Smoothing radius values.
      void fit_footprint_over_runs();
      /// The footprint fit in calibration.json (@p j: its "footprint").
      void footprint_json(const FootprintFit &f, io::Json &j) const;
      /// The warning about replayed candidates near the fit, if any.
      std::string replay_warning(const FootprintFit &f) const;
      /// The joint region in calibration.json (@p j: its "footprint") and footprint_region.csv;
      /// returns its outline, closed.
      std::vector<std::array<double, 2>> joint_region(const FootprintFit &f, io::Json &j) const;
      /// footprint_candidates.csv and footprint.png: the candidates and the region in (r, W).
      void plot_footprint(const FootprintFit &f, const std::vector<std::array<double, 2>> &outline_points) const;
      /// calibration.json, calibration.md, and calibration.png (measured against predicted).
      void write_results();
      /// A warning of run @p i: on the terminal, and in calibration.json (the run report shows it).
      void warn(std::size_t i, const std::string &text)
      {
        std::cerr << "warning: " << runs[i] << ": " << text << "\n";
        warnings[i].push_back(text);
      }

      std::vector<std::string>              runs;
      std::string                           table, locations, output;
      double                                block = 0.05;
      std::vector<Measurement>              ms;
      std::unique_ptr<io::OutputDirectory>  out;
      std::ofstream                         residuals, md;
      std::vector<CalibrationResult>        results;
      std::vector<RunSeries>                series;
      std::vector<std::vector<std::string>> warnings; // each run's
      std::vector<std::size_t>              order;    // the runs, best first
      io::Json                              json;
    };

    Calibration::Calibration(const std::vector<std::string> &args)
    {
      parse(args, calibrate_usage, [&](const std::string &flag, auto value) {
        if (flag == "--run")
          runs.push_back(value());
        else if (flag == "--block")
          {
            block = numbers(flag, value(), 1)[0];
            if (!(block > 0))
              throw InputError(flag, "a positive length [m] expected");
          }
        else if (flag == "--measurements")
          table = value();
        else if (flag == "--locations")
          locations = value();
        else if (flag == "--output" || flag == "-o")
          output = value();
        else
          return false;
        return true;
      });
      if (runs.empty() || table.empty() || output.empty())
        throw InputError("command line", std::string("calibrate needs --run, --measurements and --output\nusage:\n") +
                                           calibrate_usage);
    }

    void Calibration::open_outputs()
    {
      ms  = read_measurements(table, locations);
      out = std::make_unique<io::OutputDirectory>(output);
      out->claim();
      series.reserve(runs.size());
      residuals.open(out->file("residuals.csv"));
      residuals.precision(10);
      residuals << "run,x,y,z,tonnes,measured_depth,predicted_depth\n";
      warnings.resize(runs.size());
    }

    void Calibration::fit_runs()
    {
      for (std::size_t i = 0; i < runs.size(); ++i)
        {
          const std::string &dir = runs[i];
          series.push_back(read_run(dir, ms));
          const RunSeries &run = series.back();
          results.push_back(calibrate(run, ms, block));
          const auto &r = results.back();
          if (run.seeds < 2 && run.archard_coefficient > 0)
            warn(i, "one bed per update: the DEM's run-to-run noise (a few per cent to tens of per cent) is not in the "
                    "interval; run the prediction with Lifetime/Seeds = 1, 2, 3");
          if (r.correlation < 0.99)
            warn(i, "the predicted pattern does not match the measured one well (correlation " +
                      io::format_number(r.correlation) + "): W's interval assumes the run's pattern is right");
          if (r.blocks < 3)
            warn(i, "the measurements fall into " + std::to_string(r.blocks) + " block(s) of " + io::format_number(block) +
                      " m: too few for an interval (--block sets the size)");
          for (std::size_t k = 0; k < ms.size(); ++k)
            residuals << dir << ',' << ms[k].point[0] << ',' << ms[k].point[1] << ',' << ms[k].point[2] << ','
                      << ms[k].tonnes << ',' << ms[k].depth << ',' << run.at(k, r.scale * ms[k].tonnes) << '\n';
          if (r.extrapolated)
            warn(i, "at the fitted W the measurements lie beyond the run's last update (the depths there are "
                    "extrapolated linearly); run it further");
        }
      residuals.close();
    }

    void Calibration::rank_runs()
    {
      order.resize(results.size());
      for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
      std::stable_sort(order.begin(), order.end(),
                       [&](std::size_t a, std::size_t b) { return results[a].correlation > results[b].correlation; });
      const auto best_interval = correlation_interval(results[order[0]]);
      md.open(out->file("calibration.md"));
      md << "# Calibration against " << table << " (" << ms.size() << " measurements)\n\n"
         << "Runs ranked by pattern agreement (correlation of measured and predicted depth at the fitted W).\n\n"
         << "The 95 % interval combines the fit's standard error (measurements grouped in " << block
         << " m blocks, cluster-robust) and the run's bed-to-bed spread (its seeds); both are given, as "
            "relative standard errors of W.\n\n"
         << "A run whose correlation's 95 % interval (Fisher z over the blocks) overlaps the best one's cannot be "
            "told apart from it by these measurements (column 'apart').\n\n"
         << "| rank | run | correlation | W [1/Pa] | 95 % interval | scale W/W0 | RMS residual [mm] | fit | beds | blocks | apart |\n"
         << "|---|---|---|---|---|---|---|---|---|---|---|\n";
      std::printf("%zu measurements from %s\n", ms.size(), table.c_str());
      for (std::size_t k = 0; k < order.size(); ++k)
        {
          const auto &r = results[order[k]];
          io::Json    j;
          j["run"] = r.directory, j["rank"] = long(k + 1), j["correlation"] = r.correlation, j["scale"] = r.scale;
          j["scale_low"] = r.scale_low, j["scale_high"] = r.scale_high, j["rms_residual"] = r.rms_residual;
          j["scale_standard_error_fit"] = r.se_fit, j["scale_standard_error_replicates"] = r.se_replicates;
          j["blocks"] = r.blocks, j["block_size"] = block, j["degrees_of_freedom"] = r.dof;
          j["design_effect"] = r.design_effect, j["effective_blocks"] = r.effective_blocks;
          const auto ci          = correlation_interval(r);
          const bool apart       = k > 0 && ci.second < best_interval.first;
          j["correlation_low"]   = ci.first, j["correlation_high"] = ci.second;
          if (k > 0)
            j["told_apart_from_the_best"] = apart;
          char undecided[400] = "";
          if (k > 0 && !apart)
            std::snprintf(undecided, sizeof undecided,
                          "     cannot be told apart from the best by these measurements: the correlations' 95 %% "
                          "intervals, %.5f ... %.5f and %.5f ... %.5f, overlap\n",
                          ci.first, ci.second, best_interval.first, best_interval.second);
          j["archard_coefficient"] = r.archard_coefficient, j["archard_coefficient_low"] = r.low;
          j["archard_coefficient_high"] = r.high, j["extrapolated"] = r.extrapolated;
          j["smoothing_radius"] = r.smoothing_radius; // the footprint W was fitted with (Lifetime/Calibration)
          if (r.particle_radius > 0) // and the particle size: W and r hold for it (docs/coarse-graining.md)
            j["particle_radius"] = r.particle_radius, j["coarse_graining_factor"] = r.coarse_graining_factor;
          j["wear_field"]       = r.wear_field;       // the field (law) whose coefficient W is
          for (const auto &w : warnings[order[k]])
            j["warnings"].push_back(w);
          json["runs"].push_back(j);
          char line[512];
          std::snprintf(line, sizeof line,
                        "| %zu | %s | %.4f | %.4g | %.4g ... %.4g | %.4g | %.4g | %.2g %% | %.2g %% | %ld | %s |\n", k + 1,
                        r.directory.c_str(), r.correlation, r.archard_coefficient, r.low, r.high, r.scale,
                        1e3 * r.rms_residual, 100 * r.se_fit / r.scale, 100 * r.se_replicates / r.scale, r.blocks,
                        k == 0 ? "best" : (apart ? "yes" : "no"));
          md << line;
          if (r.archard_coefficient > 0) // (Archard's W in 1/Pa; another law's coefficient named by its field)
            std::printf("  %zu. %s: correlation %.4f, %s = %.4g (%.4g ... %.4g)%s, scale %.4g, RMS residual %.3g mm\n",
                        k + 1, r.directory.c_str(), r.correlation,
                        r.wear_field.empty() || r.wear_field == "archard_volume" ? "W" : ("the coefficient of " + r.wear_field).c_str(),
                        r.archard_coefficient, r.low, r.high,
                        r.wear_field.empty() || r.wear_field == "archard_volume" ? " 1/Pa" : "", r.scale, 1e3 * r.rms_residual);
          else // an analytic-wear run: no W, the rate's scale
            std::printf("  %zu. %s: correlation %.4f, scale %.4g (%.4g ... %.4g), RMS residual %.3g mm\n", k + 1,
                        r.directory.c_str(), r.correlation, r.scale, r.scale_low, r.scale_high, 1e3 * r.rms_residual);
          std::fputs(undecided, stdout);
        }
    }

    void Calibration::fit_footprint_over_runs()
    {
      std::vector<double> lives;
      for (const auto &dir : runs)
        lives.push_back(io::summary_number(dir + "/summary.json", "predicted_tonnes_to_end_of_life").value_or(0));
      const FootprintFit f = fit_footprint(series, results, lives, ms, block);
      io::Json          &j = json["footprint"];
      footprint_json(f, j);
      if (const std::string text = f.identifiable ? replay_warning(f) : std::string(); !text.empty())
        {
          j["warnings"].push_back(text);
          std::cerr << "warning: footprint: " << text << "\n";
          md << "\nWarning: " << text << "\n";
        }
      md << "\n## W and the footprint together\n\n";
      char                               line[1400];
      std::vector<std::array<double, 2>> outline_points; // the joint region's (identifiable only)
      if (f.identifiable)
        {
          outline_points = joint_region(f, j);
          std::snprintf(line, sizeof line,
                        "Footprint (Lifetime/Smoothing radius) %.4g m (95 %%: %.4g ... %.4g) and W %.4g at it (95 %%, "
                        "the footprint's uncertainty in it: %.4g ... %.4g; given the footprint +-%.2g %%, 95 %%); the "
                        "candidates' residuals against their footprints; along the ridge d ln W / d ln r = %.3g, d ln "
                        "life / d ln r = %.3g. Both intervals hold the candidates' own error (the fit without each "
                        "outer candidate in turn moved the footprint by up to %.2g %% and W by %.2g %%) and the "
                        "interpolation's between them (%.2g %%). The joint 95 %% region of both is an ellipse about "
                        "that ridge (footprint_region.csv, footprint.png). Lifetime/Calibration takes both.\n",
                        f.r, f.r_low, f.r_high, f.w, f.w_low, f.w_high, 100 * z95 * f.joint_sd_w, f.dlnw_dlnr,
                        f.dlnlife_dlnr, 100 * f.candidate_sensitivity, 100 * f.w_candidate_sensitivity,
                        100 * f.half_interpolation);
        }
      else
        std::snprintf(line, sizeof line, "Not identifiable: %s (%.4g m, W %.4g).\n", f.reason.c_str(), f.r, f.w);
      md << line;
      std::printf("footprint: %s", line);
      if (f.identifiable)
        plot_footprint(f, outline_points);
    }

    void Calibration::footprint_json(const FootprintFit &f, io::Json &j) const
    {
      j["identifiable"]    = f.identifiable;
      j["smoothing_radius"] = f.r, j["smoothing_radius_low"] = f.r_low, j["smoothing_radius_high"] = f.r_high;
      j["wear_coefficient"] = f.w, j["log_smoothing_radius_standard_error"] = f.sd_log_r;
      j["dlnw_dlnr"] = f.dlnw_dlnr, j["dlnlife_dlnr"] = f.dlnlife_dlnr, j["degrees_of_freedom"] = f.dof;
      // the interval's two widenings on ln r (footprint_fit.h): the interpolation's, and the
      // candidates' own error (r^'s largest shift without one candidate)
      j["log_smoothing_radius_interpolation"] = f.half_interpolation;
      j["log_smoothing_radius_candidate_sensitivity"] = f.candidate_sensitivity;
      j["candidates_left_out"] = f.candidates_left_out;
      j["replays_not_assessed"] = f.replays_not_assessed; // (footprints: their own error not in the interval)
      if (!f.identifiable)
        j["reason"] = f.reason;
    }

    std::string Calibration::replay_warning(const FootprintFit &f) const
    {
      // a fit on replays: their own error (the geometry feedback they leave out) is not in the
      // interval; it grows with the distance from the DEM run they replay, and those within
      // 1.25^2 of the fit enter its interpolation
      double nearest = 0; // the replay nearest the fit, on ln r
      for (std::size_t i = 0; i < runs.size(); ++i)
        if (io::summary_string(runs[i] + "/summary.json", "wear_source").value_or("") == "replay" &&
            series[i].smoothing_radius > 0 &&
            (nearest == 0 || std::abs(std::log(series[i].smoothing_radius / f.r)) < std::abs(std::log(nearest / f.r))))
          nearest = series[i].smoothing_radius;
      std::string text;
      if (!f.replays_not_assessed.empty())
        {
          std::string at;
          for (const double r : f.replays_not_assessed)
            at += (at.empty() ? "" : ", ") + io::format_number(1000 * r, 3) + " mm";
          text = "the footprint's fit (" + io::format_number(1000 * f.r, 3) + " mm) rests on replayed candidates "
                 "(Lifetime/Wear source = replay) among the best and its neighbours (" + at + ") whose own error "
                 "is NOT in the interval (without one of them the rest hold no minimum): a replay leaves out how "
                 "the DEM's wear changes with the shape (on the knife-bed the fit came out 13-20 % large on "
                 "replays of one DEM run); not a footprint to book: bracket the fit with DEM candidates (1.25^-2, "
                 "1.25^-1, 1 and 1.25 times " + io::format_number(f.r, 3) + " m) and calibrate again "
                 "(docs/field.md, the worked example)";
        }
      else if (nearest > 0 && std::abs(std::log(nearest / f.r)) < 2 * std::log(1.25) * (1 + 1e-9))
        text = "the footprint's fit (" + io::format_number(1000 * f.r, 3) + " mm) rests on replayed candidates "
               "(Lifetime/Wear source = replay; one at " + io::format_number(1000 * nearest, 3) +
               " mm): a replay leaves out how the DEM's wear changes with the shape; the interval holds that "
               "error as far as the fit without each replay shows it (" +
               io::format_number(100 * f.candidate_sensitivity, 2) + " % here); DEM candidates about the fit "
               "(1.25^-2, 1.25^-1, 1 and 1.25 times " + io::format_number(f.r, 3) + " m) give a narrower and "
               "truer interval (on the knife-bed 14.0 mm, 13.45 ... 14.54, against 14.4, 13.62 ... 15.09, with "
               "replays at 10 and 25 mm; truth 13.75; docs/field.md, the worked example)";
      return text;
    }

    std::vector<std::array<double, 2>> Calibration::joint_region(const FootprintFit &f, io::Json &j) const
    {
      // W's own interval (r's uncertainty in it) and the joint region (footprint_fit.h)
      j["wear_coefficient_low"] = f.w_low, j["wear_coefficient_high"] = f.w_high;
      j["log_wear_coefficient_standard_error"] = f.sd_log_w, j["wear_coefficient_degrees_of_freedom"] = f.w_dof;
      j["log_wear_coefficient_candidate_sensitivity"] = f.w_candidate_sensitivity;
      io::Json &region = j["joint_region"];
      region["level"]  = f.joint_level; // (r, W) inside when Q <= level (footprint_fit.h):
      // Q = (a / s_a)^2 + ((b - dlnw_dlnr a) / s_w)^2, a = ln(r / r^), b = ln(W / W^), s_a by a's side
      region["scale_log_r_below"] = std::log(f.r / f.r_low) / z95;
      region["scale_log_r_above"] = std::log(f.r_high / f.r) / z95;
      region["scale_log_w"]       = f.joint_sd_w;
      std::vector<std::array<double, 2>> outline_points = joint_region_outline(f);
      outline_points.push_back(outline_points.front()); // (a closed outline)
      std::ofstream outline(out->file("footprint_region.csv"));
      outline << "smoothing_radius,wear_coefficient\n";
      for (const auto &p : outline_points)
        {
          region["outline"].push_back(io::Json(std::vector<double>{p[0], p[1]}));
          outline << io::format_number(p[0], 8) << ',' << io::format_number(p[1], 8) << '\n';
        }
      return outline_points;
    }

    void Calibration::plot_footprint(const FootprintFit &f, const std::vector<std::array<double, 2>> &outline_points) const
    {
      std::vector<std::size_t> by_r(series.size());
      for (std::size_t i = 0; i < by_r.size(); ++i)
        by_r[i] = i;
      std::sort(by_r.begin(), by_r.end(), [&](auto a, auto b) { return series[a].smoothing_radius < series[b].smoothing_radius; });
      std::ofstream candidates(out->file("footprint_candidates.csv"));
      candidates << "run,smoothing_radius,wear_coefficient,rss\n";
      double w_min = f.w, w_max = f.w, r_min = f.r, r_max = f.r;
      for (const auto &p : outline_points)
        r_min = std::min(r_min, p[0]), r_max = std::max(r_max, p[0]), w_min = std::min(w_min, p[1]),
        w_max = std::max(w_max, p[1]);
      for (const std::size_t i : by_r)
        {
          const double r = series[i].smoothing_radius, w = results[i].archard_coefficient > 0
                                                              ? results[i].archard_coefficient : results[i].scale;
          candidates << runs[i] << ',' << io::format_number(r, 8) << ',' << io::format_number(w, 8) << ','
                << io::format_number(results[i].rms_residual * results[i].rms_residual * double(ms.size()), 8) << '\n';
          w_min = std::min(w_min, w), w_max = std::max(w_max, w), r_min = std::min(r_min, r), r_max = std::max(r_max, r);
        }
      candidates.close();
      std::ofstream gp(out->file("footprint.gp"));
      gp << "set terminal pngcairo size 800,600\nset output 'footprint.png'\nset datafile separator ','\nset grid\n"
            "set key left top\nset logscale x\nset format y '%.2g'\n"
         << "set xrange [" << io::format_number(1000 * r_min / 1.2, 6) << ':' << io::format_number(1000 * r_max * 1.2, 6)
         << "]\nset yrange [" << io::format_number(w_min / 1.2, 6) << ':' << io::format_number(w_max * 1.3, 6)
         << "]\nset xtics (";
      for (std::size_t k = 0; k < by_r.size(); ++k) // (the candidates' footprints)
        gp << (k ? ", " : "") << io::format_number(1000 * series[by_r[k]].smoothing_radius, 3);
      gp << ")\nset xlabel 'footprint, Lifetime/Smoothing radius [mm]'\nset ylabel 'W [1/Pa]'\n"
            "set title 'W and the footprint: each candidate fitted its W; the joint 95 % region'\n"
            "plot 'footprint_region.csv' skip 1 using ($1*1000):2 with lines lw 2 title 'joint 95 % region', "
            "'footprint_candidates.csv' skip 1 using ($2*1000):3 with linespoints pt 7 title 'candidates (W fitted at "
            "each footprint)', '-' using 1:2 with points pt 2 ps 2 lw 2 title 'fit'\n"
         << io::format_number(1000 * f.r, 8) << ',' << io::format_number(f.w, 8) << "\ne\n";
      gp.close();
      io::run_gnuplot_for(out->root(), "footprint.gp", {"footprint.png"});
    }

    void Calibration::write_results()
    {
      json["measurements"] = table;
      json.write(out->file("calibration.json"));
      md.close();
      std::ofstream gp(out->file("calibration.gp"));
      gp << "set terminal pngcairo size 800,700\nset output 'calibration.png'\nset datafile separator ','\nset grid\n"
            "set key left top\nset xlabel 'measured depth [mm]'\nset ylabel 'predicted depth at the fitted W [mm]'\n"
            "set size ratio -1\nplot x with lines dt 2 lc rgb 'black' title 'equal'";
      for (const auto &dir : runs)
        gp << ", 'residuals.csv' using (strcol(1) eq '" << dir << "' ? $6*1000 : 1/0):($7*1000) with points pt 7 title '"
           << dir << "'";
      gp << '\n';
      gp.close();
      io::run_gnuplot(out->root(), "calibration.gp");
      std::printf("Output in %s\n", output.c_str());
    }
  } // namespace

  int run_calibrate_command(const std::vector<std::string> &args) { return Calibration(args).run(); }
} // namespace abrade::field
