// `abrade sweep`: the thesis' study design (a parameter varied, three beds per value, averages)
// as one command.
//
// 1. Make the settled bed of every seed (one run per seed, first value), in parallel.
// 2. Run every other (value, seed) pair from those beds, in parallel, one thread per run.
// 3. Reduce: per run, from walls/WALL_wear.csv, WALL_forces.csv and WALL_layer.csv, the total
//    and per-phase Archard wear, the peak force in the first phase, the mean force magnitude
//    over the second half of the last phase (steady state), and the contact layer's velocity
//    and slip over the second half of the last phase; then mean and standard deviation over
//    the seeds per value -> study.csv, study.md.
// 4. Plots (gnuplot, PNG): wear vs value, force vs time per value, layer velocity vs time per
//    value (each averaged over the seeds); the final wear-coloured wall surface of every run.
#include <abrade/common/csv_writer.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/child_runs.h>
#include <abrade/coupling/sweep.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    struct RunMetrics
    {
      std::map<std::string, double> value; // metric name -> value
      std::vector<double>           time, force, layer_time, layer_velocity;
    };

    /// The metrics of one finished run (see the file comment).
    RunMetrics reduce_run(const std::string &dir, const std::string &wall, const std::vector<std::string> &phases)
    {
      RunMetrics m;
      const std::string wear_file = dir + "/walls/" + wall + "_wear.csv";
      const CsvTable    wear      = read_csv_table(wear_file);
      const int         vol       = wear.column("archard_volume");
      for (const auto &r : wear.rows)
        m.value["wear_" + r[0]] = std::stod(r[vol]);

      const std::string force_file = dir + "/walls/" + wall + "_forces.csv";
      const CsvTable       f          = read_csv_table(force_file);
      const int         t = f.column("time"), fx = f.column("fx"),
              fy = f.column("fy"), fz = f.column("fz");
      double peak = 0, steady = 0, t_last_start = 1e300, t_end = 0;
      for (const auto &r : f.rows)
        if (r[0] == phases.back())
          t_last_start = std::min(t_last_start, std::stod(r[t])), t_end = std::max(t_end, std::stod(r[t]));
      int n_steady = 0;
      for (const auto &r : f.rows)
        {
          const double time = std::stod(r[t]);
          const double mag  = std::sqrt(std::pow(std::stod(r[fx]), 2) + std::pow(std::stod(r[fy]), 2) +
                                       std::pow(std::stod(r[fz]), 2));
          m.time.push_back(time), m.force.push_back(mag);
          if (r[0] == phases.front())
            peak = std::max(peak, mag);
          if (r[0] == phases.back() && time >= 0.5 * (t_last_start + t_end))
            steady += mag, ++n_steady;
        }
      m.value["peak_force_" + phases.front()] = peak;
      m.value["steady_force_" + phases.back()] = n_steady ? steady / n_steady : 0.0;

      const std::string layer_file = dir + "/walls/" + wall + "_layer.csv";
      if (std::filesystem::exists(layer_file))
        {
          const CsvTable l = read_csv_table(layer_file);
          const int   lt = l.column("time"), lv = l.column("mean_velocity"),
                    lw = l.column("wall_velocity");
          double sum_v = 0, sum_slip = 0;
          int    n     = 0;
          for (const auto &r : l.rows)
            {
              m.layer_time.push_back(std::stod(r[lt]));
              m.layer_velocity.push_back(std::stod(r[lv]));
              if (r[0] == phases.back() && std::stod(r[lt]) >= 0.5 * (t_last_start + t_end))
                sum_v += std::stod(r[lv]), sum_slip += std::stod(r[lw]) - std::stod(r[lv]), ++n;
            }
          m.value["layer_velocity_" + phases.back()] = n ? sum_v / n : 0.0;
          m.value["layer_slip_" + phases.back()]     = n ? sum_slip / n : 0.0;
        }
      return m;
    }

    std::pair<double, double> mean_std(const std::vector<double> &v)
    {
      double mean = 0;
      for (double x : v)
        mean += x;
      mean /= v.size();
      double var = 0;
      for (double x : v)
        var += (x - mean) * (x - mean);
      return {mean, v.size() > 1 ? std::sqrt(var / (v.size() - 1)) : 0.0};
    }

    /// Seed average of curves sampled at the same times (runs share dt and intervals).
    std::vector<double> average(const std::vector<std::vector<double>> &curves)
    {
      std::size_t n = curves.empty() ? 0 : curves[0].size();
      for (const auto &c : curves)
        n = std::min(n, c.size());
      std::vector<double> out(n, 0.0);
      for (const auto &c : curves)
        for (std::size_t k = 0; k < n; ++k)
          out[k] += c[k] / curves.size();
      return out;
    }
  } // namespace

  void parse_vary(const std::string &text, SweepOptions &o)
  {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
      throw InputError("--vary '" + text + "'", "expected \"Section/Key=v1,v2,...\"");
    o.key = text.substr(0, eq);
    o.values.clear();
    std::stringstream ss(text.substr(eq + 1));
    std::string       v;
    while (std::getline(ss, v, ','))
      {
        v.erase(0, v.find_first_not_of(' '));
        v.erase(v.find_last_not_of(' ') + 1);
        if (!v.empty())
          o.values.push_back(v);
      }
    if (o.values.empty())
      throw InputError("--vary '" + text + "'", "no values given");
  }

  int run_sweep(const SweepOptions &o, const std::string &abrade)
  {
    if (o.values.empty())
      throw InputError("command line", "sweep needs --vary \"Section/Key=v1,v2,...\"");
    if (o.output.empty())
      throw InputError("command line", "sweep needs --output DIR");
    const io::OutputDirectory out(o.output);
    const std::string         root = std::filesystem::absolute(o.output).string();
    out.subdirectory("plots");
    out.subdirectory("surfaces");
    const bool reuse_beds = o.key.rfind("Particles/", 0) != 0; // a particle parameter changes the bed
    out.subdirectory("beds");
    out.subdirectory("runs");

    struct Run
    {
      std::string value, dir;
      int         seed;
    };
    auto label = [](const std::string &v) {
      std::string l = v;
      for (char &c : l)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-')
          c = '_';
      return l;
    };
    std::vector<Run> first, rest;
    for (int seed : o.seeds)
      for (std::size_t k = 0; k < o.values.size(); ++k)
        {
          Run r{o.values[k], root + "/runs/" + label(o.values[k]) + "-seed" + std::to_string(seed), seed};
          (k == 0 || !reuse_beds ? first : rest).push_back(r);
        }

    auto child = [&](const Run &r) {
      std::vector<std::string> sets = o.sets;
      sets.push_back(o.key + "=" + r.value);
      sets.push_back("Particles/Generation/Seed=" + std::to_string(r.seed));
      sets.push_back("Particles/Settling/Bed file=" +
                     (reuse_beds ? root + "/beds/bed-seed" + std::to_string(r.seed) + ".bed" : std::string()));
      sets.push_back("Simulation/Threads=1");
      sets.push_back("Output/Write particles=false");
      sets.push_back("Output/Snapshot interval=0");
      return ChildRun{r.dir, run_command(abrade, o.parameter_file, r.dir, sets)};
    };
    std::vector<ChildRun> makes_beds, uses_beds;
    for (const auto &r : first)
      makes_beds.push_back(child(r));
    for (const auto &r : rest)
      uses_beds.push_back(child(r));
    if (!o.quiet)
      std::cout << "sweep: " << o.key << " over " << o.values.size() << " values x " << o.seeds.size()
                << " seeds = " << first.size() + rest.size() << " runs, output in " << root << std::endl;
    run_children(makes_beds, o.jobs, "sweep (first runs, which settle the beds)");
    run_children(uses_beds, o.jobs, "sweep");

    // --- reduce ---
    std::vector<std::string> phases;
    {
      const CsvTable w = read_csv_table(first[0].dir + "/walls/" + o.wall + "_wear.csv");
      for (const auto &r : w.rows)
        if (r[0] != "total")
          phases.push_back(r[0]);
    }
    if (phases.empty())
      throw RunError("sweep: no phases in the runs' wear tables (is wear enabled for wall '" + o.wall + "'?)");
    std::map<std::string, std::vector<RunMetrics>> by_value;
    for (const auto &list : {first, rest})
      for (const auto &r : list)
        by_value[r.value].push_back(reduce_run(r.dir, o.wall, phases));

    std::vector<std::string> metrics = {"wear_total"};
    for (const auto &p : phases)
      metrics.push_back("wear_" + p);
    metrics.push_back("peak_force_" + phases.front());
    metrics.push_back("steady_force_" + phases.back());
    if (by_value[o.values[0]][0].value.count("layer_velocity_" + phases.back()))
      {
        metrics.push_back("layer_velocity_" + phases.back());
        metrics.push_back("layer_slip_" + phases.back());
      }

    std::vector<std::string> header = {"value"};
    for (const auto &m : metrics)
      header.push_back(m + "_mean"), header.push_back(m + "_std");
    io::CsvWriter csv(out.file("study.csv"), header);
    std::ofstream md(out.file("study.md"));
    md << "Sweep of `" << o.key << "` (" << o.parameter_file << "), wall `" << o.wall << "`, mean +- standard deviation over seeds";
    for (int s : o.seeds)
      md << " " << s;
    md << ".\n\n| " << o.key;
    for (const auto &m : metrics)
      md << " | " << m;
    md << " |\n|---";
    for (std::size_t k = 0; k < metrics.size(); ++k)
      md << "|---";
    md << "|\n";
    for (const auto &v : o.values)
      {
        std::vector<double> row;
        md << "| " << v;
        for (const auto &m : metrics)
          {
            std::vector<double> xs;
            for (const auto &r : by_value[v])
              xs.push_back(r.value.at(m));
            const auto [mean, sd] = mean_std(xs);
            row.push_back(mean), row.push_back(sd);
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.4g +- %.2g", mean, sd);
            md << " | " << buf;
          }
        md << " |\n";
        csv.row(v, row);
      }
    md << "\nForces in N, velocities in m/s along the probe axis; slip = wall velocity - layer velocity; "
          "wear is the Archard volume (W as in the parameter file). Steady-state and layer values are "
          "averages over the second half of phase '" << phases.back() << "'; the peak force is over phase '"
       << phases.front() << "'.\n";
    md.close();

    // --- plots (gnuplot) and surfaces ---
    {
      std::ofstream wear_data(out.file("plots/wear.dat"));
      std::ofstream force_data(out.file("plots/force.dat"));
      std::ofstream layer_data(out.file("plots/layer.dat"));
      for (const auto &v : o.values)
        {
          std::vector<double> xs;
          std::vector<std::vector<double>> forces, layers;
          for (const auto &r : by_value[v])
            xs.push_back(r.value.at("wear_total")), forces.push_back(r.force), layers.push_back(r.layer_velocity);
          const auto [mean, sd] = mean_std(xs);
          wear_data << v << " " << mean << " " << sd << "\n";
          const auto f = average(forces), l = average(layers);
          force_data << "# " << v << "\n";
          for (std::size_t k = 0; k < f.size(); ++k)
            force_data << by_value[v][0].time[k] << " " << f[k] << "\n";
          force_data << "\n\n";
          layer_data << "# " << v << "\n";
          for (std::size_t k = 0; k < l.size(); ++k)
            layer_data << by_value[v][0].layer_time[k] << " " << l[k] << "\n";
          layer_data << "\n\n";
        }
      std::ofstream gp(out.file("plots/plots.gp"));
      gp << "set terminal pngcairo size 900,600\nset grid\nset key outside right\n";
      gp << "set output 'wear.png'\nset xlabel '" << o.key << "'\nset ylabel 'Archard wear volume'\n"
         << "plot 'wear.dat' using 1:2:3 with yerrorlines title 'mean +- std over seeds'\n";
      gp << "set output 'force.png'\nset xlabel 'time [s]'\nset ylabel '|F| on " << o.wall << " [N]'\nplot ";
      for (std::size_t k = 0; k < o.values.size(); ++k)
        gp << (k ? ", " : "") << "'force.dat' index " << k << " using 1:2 with lines title '" << o.values[k] << "'";
      gp << "\nset output 'layer_velocity.png'\nset ylabel 'contact-layer velocity along the axis [m/s]'\nplot ";
      for (std::size_t k = 0; k < o.values.size(); ++k)
        gp << (k ? ", " : "") << "'layer.dat' index " << k << " using 1:2 with lines title '" << o.values[k] << "'";
      gp << "\n";
    }
    io::run_gnuplot(root + "/plots", "plots.gp", o.quiet);
    for (const auto &list : {first, rest})
      for (const auto &r : list)
        {
          // the last snapshot of the wall: the final wear state
          std::string last;
          for (const auto &e : std::filesystem::directory_iterator(r.dir + "/walls"))
            {
              const std::string n = e.path().filename().string();
              if (n.rfind(o.wall + "_", 0) == 0 && e.path().extension() == ".vtp" && n > last)
                last = n;
            }
          if (!last.empty())
            std::filesystem::copy_file(r.dir + "/walls/" + last,
                                       root + "/surfaces/" + o.wall + "_" + label(r.value) + "_seed" +
                                         std::to_string(r.seed) + ".vtp",
                                       std::filesystem::copy_options::overwrite_existing);
        }
    if (!o.quiet)
      {
        std::ifstream in(out.file("study.md"));
        std::cout << in.rdbuf() << "files: " << root << "/study.csv, study.md, plots/*.png, surfaces/*.vtp" << std::endl;
      }
    return 0;
  }
} // namespace abrade::coupling
