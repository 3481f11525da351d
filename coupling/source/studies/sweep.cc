// `abrade sweep`: a parametric study (a parameter varied, several beds per value, averages over
// them) as one command; several varied parameters make a grid (the coarse-graining study: particle
// size x knife friction, docs/coarse-graining.md).
//
// 1. Make the settled bed of every seed and combination of varied particle parameters (one run
//    each, the first such combination), in parallel.
// 2. Run every other (combination, seed) from those beds, in parallel, one thread per run.
// 3. Reduce: per run, from walls/WALL_wear.csv, WALL_forces.csv, WALL_layer.csv and
//    WALL_wear_profile.csv: the total and per-phase wear (of Output/Wear field) and per metre of the wall's
//    path in each phase; the share of the wear below --edge-height (the edge), also of each
//    phase's wear where the profile has the phases' columns, and on each face
//    direction; the peak wear depth after the surface filter (over the particle radius and over
//    a fixed length); the mean force magnitude per phase, the peak force in the first phase and
//    the mean force over the second half of the last (steady state); the contact layer's
//    velocity and slip over the second half of the last phase; the mean number of particles
//    touching the wall per phase. Then mean and standard deviation over the seeds per
//    combination -> study.csv, study.md.
// 4. Plots (gnuplot, PNG): every metric against the first varied parameter (one line per
//    combination of the others, error bars: the seeds' standard deviation), the wear by height
//    above the edge, force and layer velocity against time (each averaged over the seeds); the
//    final wear-coloured wall surface of every run.
#include <abrade/common/csv_writer.h>
#include <abrade/common/json.h>
#include <abrade/common/list_items.h>
#include <abrade/common/error.h>
#include <abrade/common/external.h>
#include <abrade/common/output_directory.h>
#include <abrade/common/progress.h>
#include <abrade/coupling/dem_run/seed_bed_file.h>
#include <abrade/coupling/studies/child_runs.h>
#include <abrade/coupling/studies/paired_change.h>
#include <abrade/coupling/studies/study_lives.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameter_text.h>
#include <abrade/coupling/studies/sweep.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    struct RunMetrics
    {
      std::map<std::string, double> value; // metric name -> value
      std::vector<double>           time, force, layer_time, layer_velocity;
      std::vector<double>           height_share; // wear share per height band
      double                        band = 0;
    };

    double number(const std::string &text) { return std::stod(text); }

    /// The wall's wear per phase (Output/Wear field's column) and per metre it travelled.
    void add_wear(RunMetrics &m, const std::string &dir, const std::string &wall, const std::string &field)
    {
      const CsvTable wear = read_csv_table(dir + "/walls/" + wall + "_wear.csv");
      const int      vol = wear.column(field), path = wear.column("path_length");
      for (const auto &r : wear.rows)
        {
          m.value["wear_" + r[0]] = number(r[vol]);
          if (r[0] != "total" && number(r[path]) > 0) // (a wall at rest in a phase has no wear per metre)
            m.value["wear_per_m_" + r[0]] = number(r[vol]) / number(r[path]);
        }
    }

    /// The force on the wall: its magnitude over time, per phase the mean, the first phase's
    /// peak and the last one's steady mean, over its second half. Returns when that half
    /// begins [s].
    double add_forces(RunMetrics &m, const std::string &dir, const std::string &wall,
                      const std::vector<std::string> &phases)
    {
      const CsvTable f = read_csv_table(dir + "/walls/" + wall + "_forces.csv");
      const int      t = f.column("time"), fx = f.column("fx"), fy = f.column("fy"), fz = f.column("fz");
      double         t_last_start = 1e300, t_end = 0;
      for (const auto &r : f.rows)
        if (r[0] == phases.back())
          t_last_start = std::min(t_last_start, number(r[t])), t_end = std::max(t_end, number(r[t]));
      std::map<std::string, double> force_sum;
      std::map<std::string, int>    rows;
      double                        peak = 0, steady = 0;
      int                           n_steady = 0;
      for (const auto &r : f.rows)
        {
          const double time = number(r[t]);
          const double mag  = std::sqrt(std::pow(number(r[fx]), 2) + std::pow(number(r[fy]), 2) + std::pow(number(r[fz]), 2));
          m.time.push_back(time), m.force.push_back(mag);
          force_sum[r[0]] += mag, ++rows[r[0]];
          if (r[0] == phases.front())
            peak = std::max(peak, mag);
          if (r[0] == phases.back() && time >= 0.5 * (t_last_start + t_end))
            steady += mag, ++n_steady;
        }
      for (const auto &p : phases)
        m.value["mean_force_" + p] = rows[p] ? force_sum[p] / rows[p] : 0.0;
      m.value["peak_force_" + phases.front()]  = peak;
      m.value["steady_force_" + phases.back()] = n_steady ? steady / n_steady : 0.0;
      return 0.5 * (t_last_start + t_end);
    }

    /// The wall's layer probe, where it has one: the layer's velocity and slip over the last
    /// phase's second half (from @p steady_from [s]), the contacts per phase.
    void add_layer(RunMetrics &m, const std::string &dir, const std::string &wall,
                   const std::vector<std::string> &phases, double steady_from)
    {
      const std::string layer_file = dir + "/walls/" + wall + "_layer.csv";
      if (!std::filesystem::exists(layer_file))
        return;
      const CsvTable l  = read_csv_table(layer_file);
      const int      lt = l.column("time"), lv = l.column("mean_velocity"), lw = l.column("wall_velocity"),
                lc = l.column("contacts");
      double sum_v = 0, sum_slip = 0;
      int    n     = 0;
      std::map<std::string, double> contacts;
      std::map<std::string, int>    samples;
      for (const auto &r : l.rows)
        {
          m.layer_time.push_back(number(r[lt]));
          m.layer_velocity.push_back(number(r[lv]));
          contacts[r[0]] += number(r[lc]), ++samples[r[0]];
          if (r[0] == phases.back() && number(r[lt]) >= steady_from)
            sum_v += number(r[lv]), sum_slip += number(r[lw]) - number(r[lv]), ++n;
        }
      m.value["layer_velocity_" + phases.back()] = n ? sum_v / n : 0.0;
      m.value["layer_slip_" + phases.back()]     = n ? sum_slip / n : 0.0;
      for (const auto &p : phases)
        m.value["contacts_" + p] = samples[p] ? contacts[p] / samples[p] : 0.0;
    }

    /// The wear profile, where the run wrote one: the share per height band and below the edge
    /// height (a band it cuts in proportion), per face, and the filtered peaks; per phase, where
    /// the profile has the phases' columns, the share of that phase's wear below the edge height.
    void add_profile(RunMetrics &m, const std::string &dir, const std::string &wall, const std::string &field,
                     double edge_height, const std::vector<std::string> &phases)
    {
      const std::string profile_file = dir + "/walls/" + wall + "_wear_profile.csv";
      if (!std::filesystem::exists(profile_file))
        return;
      const CsvTable pr    = read_csv_table(profile_file);
      const int      label = pr.column("label"), lo = pr.column("lower"), hi = pr.column("upper"),
                v = pr.column(field), area = pr.column("area");
      // the part of a height row's band below the edge height
      const auto below_edge = [&](const std::vector<std::string> &r) {
        const double a = number(r[lo]), b = number(r[hi]);
        return std::clamp((edge_height - a) / (b - a), 0.0, 1.0);
      };
      const double total = m.value["wear_total"];
      double       edge  = 0;
      for (const auto &r : pr.rows)
        {
          const double share = total > 0 ? number(r[v]) / total : 0.0;
          if (r[0] == "height")
            {
              m.height_share.push_back(share), m.band = number(r[hi]) - number(r[lo]);
              edge += share * below_edge(r);
            }
          else if (r[0] == "face" && number(r[area]) > 0)
            m.value["share_face_" + r[label]] = share;
          else if (r[0] == "filtered_peak")
            m.value["peak_depth_filter_" + r[label]] = number(r[v]);
        }
      m.value["edge_share"] = edge;
      for (const auto &p : phases)
        if (const int column = pr.find(field + "_" + p); column >= 0)
          {
            double below = 0, all = 0;
            for (const auto &r : pr.rows)
              if (r[0] == "height")
                below += number(r[column]) * below_edge(r), all += number(r[column]);
            m.value["edge_share_" + p] = all > 0 ? below / all : 0.0;
          }
    }

    /// The metrics of one finished run (see the file comment).
    RunMetrics reduce_run(const std::string &dir, const std::string &wall, const std::vector<std::string> &phases,
                          double edge_height)
    {
      RunMetrics m;
      // the run's wear field (Output/Wear field; Archard's volume by default)
      const std::string field = io::summary_string(dir + "/summary.json", "wear_field").value_or("archard_volume");
      add_wear(m, dir, wall, field);
      const double steady_from = add_forces(m, dir, wall, phases);
      add_layer(m, dir, wall, phases, steady_from);
      add_profile(m, dir, wall, field, edge_height, phases);
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

    /// A value as a file-name part.
    std::string label(const std::string &v)
    {
      std::string l;
      for (char c : v)
        if (c == '+')
          l += "plus";
        else
          l += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
      return l;
    }
  } // namespace

  void parse_vary(const std::string &text, SweepOptions &o)
  {
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
      throw InputError("--vary '" + text + "'", "expected \"Section/Key=v1,v2,...\"");
    SweepOptions::Vary vary;
    vary.key    = io::trimmed(text.substr(0, eq));
    vary.values = io::list_items(text.substr(eq + 1), ',');
    if (vary.values.empty())
      throw InputError("--vary '" + text + "'", "no values given");
    o.varies.push_back(vary);
  }

  namespace
  {
    /// One sweep (the file comment): its run() reads as the algorithm.
    class Sweep
    {
    public:
      Sweep(const SweepOptions &options, const std::string &abrade)
        : o(checked(options)), abrade(abrade), out(o.output)
      {}

      int run()
      {
        out.claim();
        root = std::filesystem::absolute(o.output).string();
        make_grid();
        check_every_combination();
        for (const char *d : {"plots", "surfaces", "beds", "runs"})
          out.subdirectory(d);
        plan_runs();
        run_the_runs();
        if (o.lifetime_updates > 0)
          run_the_lives();
        reduce();
        write_tables();
        write_plots();
        io::run_gnuplot(root + "/plots", "plots.gp", o.quiet);
        copy_final_surfaces();
        if (!o.quiet)
          {
            std::ifstream in(out.file("study.md"));
            std::cout << in.rdbuf() << "files: " << root << "/study.csv, study.md, plots/*.png, surfaces/*.vtp" << std::endl;
          }
        return 0;
      }

    private:
      /// A run: its combination of varied values, directory, bed file and seed.
      struct Run
      {
        std::size_t combo;
        std::string dir, bed;
        int         seed;
      };

      const SweepOptions        &o;
      const std::string          abrade;
      io::OutputDirectory        out;
      std::string                root; ///< the output directory, absolute
      /// the grid: every combination of the varied values, the first parameter varying slowest
      std::vector<std::vector<std::string>> combos;
      std::vector<Run>           first, rest; ///< the runs that settle a bed, and the others
      std::string                keys;        ///< "Key (3) x Key (2)"
      std::vector<StudyLife>     lives;       ///< each combination's life (--lifetime-updates)
      std::vector<PairedChange>  life_against_first;
      std::vector<std::string>   phases;
      std::vector<std::vector<RunMetrics>> by_combo;
      std::vector<PairedChange>  against_first; ///< each combination's total wear against the first's
      std::vector<std::string>   metrics;       ///< in the table's order (those every run has)
      std::vector<std::map<std::string, std::pair<double, double>>> stats; ///< mean and std per metric

      /// @p o, its options checked (before the output directory is made).
      static const SweepOptions &checked(const SweepOptions &o)
      {
        if (o.varies.empty())
          throw InputError("command line", "sweep needs --vary \"Section/Key=v1,v2,...\"");
        if (o.output.empty())
          throw InputError("command line", "sweep needs --output DIR");
        for (std::size_t a = 0; a < o.varies.size(); ++a)
          for (std::size_t b = 0; b < a; ++b)
            if (entry_as_now(o.varies[a].key) == entry_as_now(o.varies[b].key)) // (one entry, two spellings too)
              throw InputError("command line", "--vary '" + o.varies[a].key + "' is given twice" +
                                                 (o.varies[a].key == o.varies[b].key
                                                    ? std::string()
                                                    : " (as '" + o.varies[b].key + "')"));
        refuse_study_owned_sets(o.sets, "--set", o.lifetime_updates > 0);
        for (const auto &v : o.varies)
          refuse_study_owned_sets({v.key}, "--vary", o.lifetime_updates > 0);
        return o;
      }

      void make_grid()
      {
        for (const auto &v : o.varies)
          keys += (keys.empty() ? "" : " x ") + v.key + " (" + std::to_string(v.values.size()) + ")";
        combos.assign(1, {});
        for (const auto &v : o.varies)
          {
            std::vector<std::vector<std::string>> next;
            for (const auto &c : combos)
              for (const auto &x : v.values)
                next.push_back(c), next.back().push_back(x);
            combos = next;
          }
        {
          std::set<std::string> names; // the runs' directories: one per combination
          for (const auto &c : combos)
            if (!names.insert(combination_name(c)).second)
              throw InputError("command line", "--vary: the combination '" + combination_name(c) +
                                                 "' comes twice (a value repeated, or values that differ only in "
                                                 "characters a directory name cannot hold)");
        }
      }

      /// A combination's name (its runs' directories): its values, one value itself.
      static std::string combination_name(const std::vector<std::string> &c)
      {
        std::string n;
        for (const auto &x : c)
          n += (n.empty() ? "" : "_") + label(x);
        return n;
      }

      /// Every combination's parameters checked before any run starts.
      void check_every_combination() const
      {
        // (a misspelt key or a value out of its range would fail only after the first runs had
        // been launched, exit 3); the seeds differ only in Particles/Generation/Seed, whose values
        // the command line checked
        for (const auto &c : combos)
          {
            std::vector<std::string> sets = o.sets;
            for (std::size_t i = 0; i < o.varies.size(); ++i)
              sets.push_back(o.varies[i].key + "=" + c[i]);
            const int seed = o.seeds.empty() ? 1 : o.seeds.front();
            sets.push_back("Particles/Generation/Seed=" + std::to_string(seed));
            try
              {
                ParameterFile run(o.parameter_file, sets);
                const auto    walls = dealii::Utilities::split_string_list(run.handler().get("Walls"));
                if (std::find(walls.begin(), walls.end(), o.wall) == walls.end())
                  throw InputError("--wall " + o.wall, "no such wall in the case (its walls: " + run.handler().get("Walls") +
                                                         ")");
              }
            catch (const InputError &e)
              {
                throw InputError("sweep run " + combination_name(c) + "-seed" + std::to_string(seed), e.what());
              }
          }
      }

      /// A particle parameter changes the bed: one bed per seed and particle values, each
      /// value's label after the seed's bed's name ("beds/bed-seed3-0.01.bed").
      std::string bed_file(const std::vector<std::string> &c, int seed) const
      {
        std::string suffix;
        for (std::size_t i = 0; i < o.varies.size(); ++i)
          if (o.varies[i].key.rfind("Particles/", 0) == 0)
            suffix += "-" + label(c[i]);
        std::string file = seed_bed_file(seed);
        return file.insert(file.size() - std::string(".bed").size(), suffix);
      }

      void plan_runs()
      {
        std::set<std::string> beds;
        for (int seed : o.seeds)
          for (std::size_t k = 0; k < combos.size(); ++k)
            {
              const std::string bed = bed_file(combos[k], seed);
              Run r{k, root + "/runs/" + combination_name(combos[k]) + "-seed" + std::to_string(seed), root + "/" + bed, seed};
              (beds.insert(bed).second ? first : rest).push_back(r);
            }
      }

      ChildRun child_run(const Run &r) const
      {
        std::vector<std::string> sets = o.sets;
        for (std::size_t i = 0; i < o.varies.size(); ++i)
          sets.push_back(o.varies[i].key + "=" + combos[r.combo][i]);
        for (std::string &set : study_cycle_sets(r.seed, r.bed))
          sets.push_back(std::move(set));
        return ChildRun{r.dir, run_command(abrade, o.parameter_file, r.dir, sets)};
      }

      void run_the_runs()
      {
        std::vector<ChildRun> makes_beds, uses_beds;
        for (const auto &r : first)
          makes_beds.push_back(child_run(r));
        for (const auto &r : rest)
          uses_beds.push_back(child_run(r));
        if (!o.quiet)
          std::cout << "sweep: " << keys << " x " << o.seeds.size() << " seeds = " << first.size() + rest.size()
                    << " runs (" << first.size() << " settle their beds), output in " << root << std::endl;
        run_children(makes_beds, o.jobs, "sweep (first runs, which settle the beds)");
        run_children(uses_beds, o.jobs, "sweep");
      }

      /// Each combination's life, all on the same beds in every update.
      void run_the_lives()
      {
        lives.assign(combos.size(), {});
        life_against_first.assign(combos.size(), {});
        std::vector<ChildRun> runs;
        for (std::size_t c = 0; c < combos.size(); ++c)
          {
            std::vector<std::string> sets = o.sets;
            for (std::size_t i = 0; i < o.varies.size(); ++i)
              sets.push_back(o.varies[i].key + "=" + combos[c][i]);
            const std::string dir = root + "/lifetime/" + combination_name(combos[c]);
            runs.push_back({dir, run_command(abrade, o.parameter_file, dir,
                                             lifetime_run_sets(sets, o.lifetime_updates, o.seeds))});
          }
        std::filesystem::create_directories(root + "/lifetime");
        run_children(runs, o.jobs, "sweep (lifetime)");
        for (std::size_t c = 0; c < combos.size(); ++c)
          lives[c] = read_study_life(runs[c].dir);
        for (std::size_t c = 1; c < combos.size(); ++c)
          life_against_first[c] = life_change(lives[c], lives[0]);
      }

      void reduce()
      {
        {
          const CsvTable w = read_csv_table(first[0].dir + "/walls/" + o.wall + "_wear.csv");
          for (const auto &r : w.rows)
            if (r[0] != "total")
              phases.push_back(r[0]);
        }
        if (phases.empty())
          throw RunError("sweep: no phases in the runs' wear tables (is wear enabled for wall '" + o.wall + "'?)");
        by_combo.assign(combos.size(), {});
        std::vector<std::map<int, double>>   wear_of_seed(combos.size()); // for the pairs
        for (const auto &list : {first, rest})
          for (const auto &r : list)
            {
              by_combo[r.combo].push_back(reduce_run(r.dir, o.wall, phases, o.edge_height));
              wear_of_seed[r.combo][r.seed] = by_combo[r.combo].back().value.at("wear_total");
            }
        // each combination's total wear against the first's, pair by pair on the same seeds (the
        // same beds where no particle parameter varies: then the beds' scatter cancels)
        against_first.assign(combos.size(), {});
        for (std::size_t c = 0; c < combos.size(); ++c)
          {
            std::vector<double> a, b;
            for (int seed : o.seeds)
              a.push_back(wear_of_seed[c][seed]), b.push_back(wear_of_seed[0][seed]);
            against_first[c] = paired_change(a, b);
          }

        // the metrics, in the table's order (those every run has)
        metrics = {"wear_total"};
        for (const auto &p : phases)
          metrics.push_back("wear_" + p);
        for (const auto &p : phases)
          metrics.push_back("wear_per_m_" + p);
        metrics.push_back("edge_share");
        for (const auto &p : phases)
          metrics.push_back("edge_share_" + p);
        for (const std::string m : {"share_face_+x", "share_face_-x", "share_face_+y", "share_face_-y",
                                    "share_face_+z", "share_face_-z", "peak_depth_filter_radius", "peak_depth_filter_fixed"})
          metrics.push_back(m);
        for (const auto &p : phases)
          metrics.push_back("mean_force_" + p);
        metrics.push_back("peak_force_" + phases.front());
        metrics.push_back("steady_force_" + phases.back());
        metrics.push_back("layer_velocity_" + phases.back());
        metrics.push_back("layer_slip_" + phases.back());
        for (const auto &p : phases)
          metrics.push_back("contacts_" + p);
        metrics.erase(std::remove_if(metrics.begin(), metrics.end(),
                                     [&](const std::string &m) {
                                       for (const auto &runs : by_combo)
                                         for (const auto &r : runs)
                                           if (!r.value.count(m))
                                             return true;
                                       return false;
                                     }),
                      metrics.end());
      }

      /// What study.md's columns mean.
      std::string table_notes() const
      {
        std::ostringstream md;
        md << "\nWear is the volume of the runs' Output/Wear field (the Archard volume by default, its coefficient as in "
              "the parameter file); per metre: over the distance the wall's "
              "centroid moved in the phase. edge_share: the share of the total wear on triangles within "
           << o.edge_height
           << " m of the wall's lowest point, edge_share_PHASE the share of that phase's wear there; share_face_D: on the triangles whose normal is closest to direction D. "
              "peak_depth_filter_radius/fixed: the largest wear depth after the surface filter over the largest "
              "particle radius / over Output/Wear filter length. Forces in N (magnitude); steady-state and layer "
              "values are averages over the second half of phase '"
           << phases.back() << "'; the peak force is over phase '" << phases.front()
           << "'. Layer velocity in m/s along the probe axis; slip = wall velocity - layer velocity; contacts: "
              "contacts with the wall, a particle on two faces counting twice (mean over the probe's samples). "
              "wear_total / first: each combination's total wear against the first combination's, pair by pair on "
              "the same seeds (the same beds where no particle parameter varies), the geometric mean of the per-seed "
              "ratios with its 95 % t-interval; * marks a significant difference."
           << (o.lifetime_updates > 0
                 ? " life: tonnes to end of life of each combination's lifetime run (" + std::to_string(o.lifetime_updates) +
                     " updates, the seeds' beds in every update) with its 95 % interval; life / first: paired on "
                     "the beds both drew at the place that ends life (docs/lifetime.md, \"Two lives on the same beds\")."
                 : std::string())
           << "\n";
        return md.str();
      }

      /// study.csv and study.md: a row per combination of the varied values.
      void write_tables()
      {
        std::ofstream            csv(out.file("study.csv"));
        std::ofstream            md(out.file("study.md"));
        const std::vector<std::string> header = csv_header();
        for (std::size_t k = 0; k < header.size(); ++k)
          csv << (k ? "," : "") << header[k];
        csv << "\n";
        csv.precision(10);
        write_md_head(md);
        stats.assign(combos.size(), {});
        for (std::size_t c = 0; c < combos.size(); ++c)
          write_row(c, csv, md);
        md << table_notes();
        md.close();
        if (!csv)
          throw RunError("sweep: could not write " + out.file("study.csv"));
      }

      /// study.csv's columns: the varied keys, each metric's mean and spread, the paired ratio
      /// to the first combination, and the life's where lifetimes were run.
      std::vector<std::string> csv_header() const
      {
        std::vector<std::string> header;
        for (const auto &v : o.varies)
          header.push_back(v.key);
        for (const auto &m : metrics)
          header.push_back(m + "_mean"), header.push_back(m + "_std");
        for (const char *h : {"wear_total_ratio", "wear_total_ratio_low", "wear_total_ratio_high", "wear_total_ratio_significant"})
          header.push_back(h);
        if (o.lifetime_updates > 0)
          for (const char *h : {"life", "life_low", "life_high", "life_ratio", "life_ratio_low", "life_ratio_high",
                                "life_ratio_significant"})
            header.push_back(h);
        return header;
      }

      void write_md_head(std::ostream &md) const
      {
        md << "Sweep of " << keys << " (" << o.parameter_file << "), wall `" << o.wall
           << "`, mean +- standard deviation over seeds";
        for (int s : o.seeds)
          md << " " << s;
        md << ".\n\n|";
        for (const auto &v : o.varies)
          md << " " << v.key << " |";
        for (const auto &m : metrics)
          md << " " << m << " |";
        md << " wear_total / first (paired, 95 %) |" << (o.lifetime_updates > 0 ? " life [t] (95 %) | life / first (paired, 95 %) |" : "")
           << "\n|";
        for (std::size_t k = 0; k < o.varies.size() + metrics.size() + 1 + 2 * (o.lifetime_updates > 0); ++k)
          md << "---|";
        md << "\n";
      }

      /// A paired ratio in the table: with its interval and * where significant (one seed: said
      /// so).
      static std::string ratio_text(const PairedChange &q)
      {
        char buf[96];
        if (q.interval)
          std::snprintf(buf, sizeof buf, " %.4g [%.4g, %.4g]%s |", q.ratio, q.low, q.high, q.significant ? " *" : "");
        else
          std::snprintf(buf, sizeof buf, " %.4g (no interval: one seed) |", q.ratio);
        return buf;
      }

      /// A paired ratio's CSV cells: ratio, low, high, significant (one seed: the interval's cells
      /// empty).
      static std::string ratio_cells(const PairedChange &q)
      {
        std::ostringstream o;
        o.precision(10);
        o << "," << q.ratio;
        if (q.interval)
          o << "," << q.low << "," << q.high;
        else
          o << ",,";
        o << "," << (q.significant ? 1 : 0);
        return o.str();
      }

      /// Combination @p c's row: its values, each metric's mean and spread (kept in stats), its
      /// wear against the first's and its life.
      void write_row(std::size_t c, std::ostream &csv, std::ostream &md)
      {
        md << "|";
        for (std::size_t i = 0; i < combos[c].size(); ++i)
          md << " " << combos[c][i] << " |", csv << (i ? "," : "") << combos[c][i];
        for (const auto &m : metrics)
          {
            std::vector<double> xs;
            for (const auto &r : by_combo[c])
              xs.push_back(r.value.at(m));
            stats[c][m] = mean_std(xs);
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.4g +- %.2g", stats[c][m].first, stats[c][m].second);
            md << " " << buf << " |";
            csv << "," << stats[c][m].first << "," << stats[c][m].second;
          }
        const PairedChange &p = against_first[c];
        md << (c ? ratio_text(p) : std::string(" 1 (first) |"));
        csv << ratio_cells(p);
        if (o.lifetime_updates > 0)
          {
            const StudyLife    &l = lives[c];
            const PairedChange &q = life_against_first[c];
            csv << "," << l.tonnes << "," << l.low << "," << l.high << ratio_cells(q);
            char buf[96];
            std::snprintf(buf, sizeof buf, " %.3g (%.3g ... %.3g) |", l.tonnes, l.low, l.high);
            md << (l.tonnes > 0 ? std::string(buf) : std::string(" - |"));
            md << (c ? ratio_text(q) : std::string(" 1 (first) |"));
          }
        md << "\n", csv << "\n";
      }

      void write_plots()
      {
        // lines: one per combination of the parameters after the first
        std::map<std::string, std::vector<std::size_t>> lines;
        for (std::size_t c = 0; c < combos.size(); ++c)
          {
            std::string rest_name;
            for (std::size_t i = 1; i < combos[c].size(); ++i)
              rest_name += (rest_name.empty() ? "" : ", ") + o.varies[i].key + " = " + combos[c][i];
            lines[rest_name].push_back(c);
          }
        {
          std::ofstream gp(out.file("plots/plots.gp"));
          gp << "set terminal pngcairo size 900,600 noenhanced\nset grid\nset key below\n"
                "set offsets graph 0.05, graph 0.05, 0, 0\n";
          for (const auto &m : metrics)
            {
              const std::string file = label(m);
              std::ofstream     data(out.file("plots/" + file + ".dat"));
              for (const auto &[line, cs] : lines)
                {
                  data << "# " << line << "\n";
                  for (std::size_t c : cs)
                    data << combos[c][0] << " " << stats[c][m].first << " " << stats[c][m].second << "\n";
                  data << "\n\n";
                }
              gp << "set output '" << file << ".png'\nset xlabel '" << o.varies[0].key << "'\nset ylabel '" << m
                 << "'\nplot ";
              std::size_t k = 0;
              for (const auto &[line, cs] : lines)
                gp << (k ? ", " : "") << "'" << file << ".dat' index " << k << " using 1:2:3 with yerrorlines title '"
                   << (line.empty() ? "mean +- std over seeds" : line) << "'", ++k;
              gp << "\n";
            }
          // the wear by height above the edge, and force and layer velocity over time, per combination
          std::ofstream height(out.file("plots/wear_by_height.dat")), force(out.file("plots/force.dat")),
            layer(out.file("plots/layer.dat"));
          for (std::size_t c = 0; c < combos.size(); ++c)
            {
              std::vector<std::vector<double>> shares, forces, layers;
              for (const auto &r : by_combo[c])
                shares.push_back(r.height_share), forces.push_back(r.force), layers.push_back(r.layer_velocity);
              const auto h = average(shares), f = average(forces), l = average(layers);
              const auto &r0 = by_combo[c][0];
              height << "# " << combination_name(combos[c]) << "\n";
              for (std::size_t k = 0; k < h.size(); ++k)
                height << (k + 0.5) * r0.band << " " << h[k] << "\n";
              force << "# " << combination_name(combos[c]) << "\n";
              for (std::size_t k = 0; k < f.size(); ++k)
                force << r0.time[k] << " " << f[k] << "\n";
              layer << "# " << combination_name(combos[c]) << "\n";
              for (std::size_t k = 0; k < l.size(); ++k)
                layer << r0.layer_time[k] << " " << l[k] << "\n";
              height << "\n\n", force << "\n\n", layer << "\n\n";
            }
          auto per_combo = [&](const std::string &data, const std::string &using_) {
            for (std::size_t c = 0; c < combos.size(); ++c)
              {
                std::string title;
                for (std::size_t i = 0; i < combos[c].size(); ++i)
                  title += (i ? ", " : "") + combos[c][i];
                gp << (c ? ", " : "") << "'" << data << "' index " << c << " using " << using_ << " with lines title '"
                   << title << "'";
              }
            gp << "\n";
          };
          gp << "set output 'wear_by_height.png'\nset xlabel 'share of the wear on " << o.wall
             << "'\nset ylabel 'height above the lowest point [m]'\nset yrange [0:0.3]\nplot ";
          per_combo("wear_by_height.dat", "2:1");
          gp << "set autoscale y\nset output 'force.png'\nset xlabel 'time [s]'\nset ylabel '|F| on " << o.wall
             << " [N]'\nplot ";
          per_combo("force.dat", "1:2");
          gp << "set output 'layer_velocity.png'\nset ylabel 'contact-layer velocity along the axis [m/s]'\nplot ";
          per_combo("layer.dat", "1:2");
        }
      }

      /// The last snapshot of the wall of every run: the final wear state.
      void copy_final_surfaces() const
      {
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
                                           root + "/surfaces/" + o.wall + "_" + combination_name(combos[r.combo]) + "_seed" +
                                             std::to_string(r.seed) + ".vtp",
                                           std::filesystem::copy_options::overwrite_existing);
            }
      }
    };
  } // namespace

  int run_sweep(const SweepOptions &o, const std::string &abrade) { return Sweep(o, abrade).run(); }
} // namespace abrade::coupling
