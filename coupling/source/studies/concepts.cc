// `abrade concepts`: see concepts.h.
//
// Per run (concept, seed): the knives' wear volume per phase (the runs' Output/Wear field; walls/KNIFE_wear.csv, averaged
// over the knives: the grab's two knives are replicates) and the payload (payload.csv: the most
// mass above Simulation/Payload height at the end of a phase). Per concept: mean and standard
// deviation over the seeds of the wear per phase and in total, the payload, and the wear per
// tonne (per seed, then averaged). Every concept runs on the same beds (common random numbers),
// so a change against the baseline is taken pair by pair: per bed the ratio concept / baseline,
// their geometric mean, and the 95 % t-interval of the mean log ratio over the beds (n - 1
// degrees of freedom); a change is significant when its interval excludes 1. The bed-to-bed
// scatter that both share cancels in the ratio (independent comparisons of the means did not
// rank the concepts: their intervals overlapped). With lifetime runs every concept's lifetime
// draws the same beds in every update (the same Lifetime/Seeds), and the lives' ratio is paired
// the same way: through each update's beds at the place that ends life and the life's
// elasticity to the update (life_beds.csv; lifetime/paired_life.h).
#include <abrade/common/error.h>
#include <abrade/common/input_file.h>
#include <abrade/common/external.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/json.h>
#include <abrade/common/output_directory.h>
#include <abrade/coupling/dem_run/seed_bed_file.h>
#include <abrade/coupling/studies/child_runs.h>
#include <abrade/coupling/studies/concepts.h>
#include <abrade/coupling/studies/paired_change.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/simulation_parameters.h>
#include <abrade/coupling/studies/study_lives.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    std::string label_of(const std::string &file)
    {
      return std::filesystem::path(file).stem().string();
    }

    struct Sample
    {
      std::string                   field;       ///< Output/Wear field ("archard_volume")
      std::vector<std::string>      phases;      ///< in the order of the cycle
      std::map<std::string, double> wear;        ///< per phase and "total" [m^3 per cycle]
      double                        payload = 0; ///< [t per cycle]
    };

    Sample reduce(const std::string &dir, const std::vector<std::string> &knives)
    {
      Sample s;
      for (const auto &k : knives)
        {
          s.field = io::summary_string(dir + "/summary.json", "wear_field").value_or("archard_volume");
          const CsvTable t   = read_csv_table(dir + "/walls/" + k + "_wear.csv");
          const int      vol = t.column(s.field);
          for (const auto &row : t.rows)
            {
              if (k == knives.front() && row[0] != "total")
                s.phases.push_back(row[0]);
              s.wear[row[0]] += std::stod(row[vol]) / knives.size();
            }
        }
      const CsvTable p = read_csv_table(dir + "/payload.csv");
      const int      m = p.column("mass_above_payload_height");
      for (const auto &row : p.rows)
        s.payload = std::max(s.payload, std::stod(row[m]) / 1000);
      return s;
    }

    struct Stat
    {
      double mean = 0, std = 0, se = 0;
    };

    Stat stat(const std::vector<double> &v)
    {
      Stat s;
      for (double x : v)
        s.mean += x / v.size();
      for (double x : v)
        s.std += v.size() > 1 ? (x - s.mean) * (x - s.mean) / (v.size() - 1) : 0.0;
      s.std = std::sqrt(s.std);
      s.se  = s.std / std::sqrt(double(v.size()));
      return s;
    }

    using Change = PairedChange;
  } // namespace

  namespace
  {
    /// A concept's wear, payload and wear per tonne over its beds.
    struct Summary
    {
      std::map<std::string, Stat> wear;
      Stat                        payload, per_tonne;
      std::vector<double>         total_of_bed, payload_of_bed, per_tonne_of_bed; // per bed, for the pairs
    };

    /// `abrade concepts`: every concept's cycles on the same beds (and, asked for, its life),
    /// reduced to its wear and payload, and their changes against the baseline pair by pair.
    class ConceptStudy
    {
    public:
      ConceptStudy(const ConceptOptions &o, const std::string &abrade) : o(o), abrade(abrade) {}

      int run()
      {
        check_and_claim();
        run_cycles();
        if (o.lifetime_updates > 0)
          run_lifetimes();
        reduce_runs();
        write_tables();
        plot_wear();
        for (const char *plot : {"wear.gp", "lifetime.gp"})
          if (std::filesystem::exists(out->file(plot)))
            io::run_gnuplot(root, plot, o.quiet);
        if (!o.quiet)
          {
            std::ifstream table(out->file("concepts.md"));
            std::cout << table.rdbuf() << "Output in " << root << std::endl;
          }
        return 0;
      }

    private:
      /// The files checked and named (their labels), the output directory claimed.
      void check_and_claim();
      /// The cycles: the baseline first (its runs settle the beds), then the others.
      void run_cycles();
      /// Each concept's knife life on the same beds, and lifetime.gp.
      void run_lifetimes();
      /// Each run's wear and payload, each concept's Summary.
      void reduce_runs();
      /// concepts.csv and concepts.md: a row per concept.
      void write_tables();
      /// Concept @p k's changes against the baseline, pair by pair on the same beds.
      struct Changes
      {
        Change wear, payload, per_tonne, life_change;
      };
      Changes changes_of(std::size_t k);
      void    write_csv_head(std::ostream &csv) const;
      void    write_csv_row(std::ostream &csv, std::size_t k, const Changes &c);
      void    write_md_head(std::ostream &md) const;
      void    write_md_row(std::ostream &md, std::size_t k, const Changes &c);
      /// The change of concept @p k's life against the baseline's, paired on the beds both drew
      /// (study_lives.h).
      Change life_change_of(std::size_t k);
      /// The bar chart of the wear per phase, the total's spread over the beds as error bars.
      void plot_wear();

      const ConceptOptions                &o;
      const std::string                   &abrade;
      std::vector<std::string>             labels;
      std::unique_ptr<io::OutputDirectory> out;
      std::string                          root;
      std::map<std::string, std::string>   life;       // label -> predicted tonnes (text)
      std::map<std::string, StudyLife>     life_value; // label -> its life, interval and beds
      std::vector<std::string>             phases;
      std::string                          wear_field; ///< the runs' Output/Wear field, as its columns name it
      std::vector<Summary>                 sum;
    };

    void ConceptStudy::check_and_claim()
    {
      if (o.files.size() < 2)
        throw InputError("command line", "concepts needs at least two parameter files (the first is the baseline)");
      if (o.output.empty())
        throw InputError("command line", "concepts needs --output DIR");
      refuse_study_owned_sets(o.sets, "--set", o.lifetime_updates > 0);
      for (const auto &f : o.files)
        {
          io::require_input_file(f);
          labels.push_back(label_of(f));
          if (std::count(labels.begin(), labels.end(), labels.back()) > 1)
            throw InputError(f, "two concepts named '" + labels.back() + "' (the file names name them)");
        }
      // the payload is compared: a case without a payload height (or with one that is not a
      // number) would fail only after its runs, on a missing payload.csv
      for (const auto &f : o.files)
        {
          ParameterFile file(f, o.sets);
          if (!read_payload_height(file))
            file.fail({"Simulation"}, "Payload height",
                      "concepts compares the payload as well as the wear: set the height above which the grab's "
                      "load is counted");
        }
      out = std::make_unique<io::OutputDirectory>(o.output);
      out->claim();
      root = std::filesystem::absolute(o.output).string();
      out->subdirectory("beds"), out->subdirectory("runs");
    }

    void ConceptStudy::run_cycles()
    {
      auto child = [&](std::size_t k, int seed) {
        std::vector<std::string> sets = o.sets;
        for (std::string &set : study_cycle_sets(seed, root + "/" + seed_bed_file(seed)))
          sets.push_back(std::move(set));
        const std::string dir = root + "/runs/" + labels[k] + "-seed" + std::to_string(seed);
        return ChildRun{dir, run_command(abrade, std::filesystem::absolute(o.files[k]).string(), dir, sets)};
      };
      std::vector<ChildRun> baseline, others;
      for (int seed : o.seeds)
        {
          baseline.push_back(child(0, seed));
          for (std::size_t k = 1; k < o.files.size(); ++k)
            others.push_back(child(k, seed));
        }
      if (!o.quiet)
        std::cout << "concepts: " << o.files.size() << " concepts x " << o.seeds.size() << " seeds, output in " << root
                  << std::endl;
      run_children(baseline, o.jobs, "concepts (baseline, settles the beds)");
      run_children(others, o.jobs, "concepts");
    }

    void ConceptStudy::run_lifetimes()
    {
      std::vector<ChildRun> runs;
      for (std::size_t k = 0; k < o.files.size(); ++k)
        {
          const std::string dir = root + "/lifetime/" + labels[k];
          std::filesystem::create_directories(dir + "/beds");
          for (int s : o.seeds) // the same beds
            std::filesystem::copy_file(root + "/" + seed_bed_file(s), dir + "/" + seed_bed_file(s),
                                       std::filesystem::copy_options::overwrite_existing);
          const auto sets = lifetime_run_sets(o.sets, o.lifetime_updates, o.seeds);
          runs.push_back({dir, run_command(abrade, std::filesystem::absolute(o.files[k]).string(), dir, sets)});
        }
      run_children(runs, o.jobs, "concepts (lifetime)");
      for (const auto &l : labels)
        {
          life_value[l] = read_study_life(root + "/lifetime/" + l);
          char text[32] = "-";
          if (life_value[l].tonnes > 0)
            std::snprintf(text, sizeof text, "%.3g", life_value[l].tonnes);
          life[l] = text;
        }
      std::ofstream gp(out->file("lifetime.gp"));
      gp << "set terminal pngcairo size 900,600 noenhanced\nset output 'lifetime.png'\nset datafile separator ','\nset grid\n"
            "set key left top\nset xlabel 'handled material [t]'\nset ylabel 'largest wear depth [mm]'\nplot ";
      for (std::size_t k = 0; k < labels.size(); ++k)
        gp << (k ? ", " : "") << "'lifetime/" << labels[k] << "/trajectory.csv' using (column('tonnes')):(column('max_depth')*1000) with linespoints title '"
           << labels[k] << "'";
      gp << '\n';
    }

    void ConceptStudy::reduce_runs()
    {
      std::vector<std::vector<Sample>> samples(o.files.size());
      for (std::size_t k = 0; k < o.files.size(); ++k)
        for (int seed : o.seeds)
          samples[k].push_back(reduce(root + "/runs/" + labels[k] + "-seed" + std::to_string(seed), o.knives));
      phases = samples[0][0].phases;
      wear_field = samples[0][0].field;
      sum.resize(o.files.size());
      for (std::size_t k = 0; k < o.files.size(); ++k)
        {
          std::vector<double> pay, per_t;
          for (const auto &s : samples[k])
            pay.push_back(s.payload), per_t.push_back(s.payload > 0 ? s.wear.at("total") / s.payload : 0.0);
          for (const auto &p : phases)
            {
              std::vector<double> w;
              for (const auto &s : samples[k])
                w.push_back(s.wear.count(p) ? s.wear.at(p) : 0.0);
              sum[k].wear[p] = stat(w);
            }
          std::vector<double> tot;
          for (const auto &s : samples[k])
            tot.push_back(s.wear.at("total"));
          sum[k].wear["total"] = stat(tot);
          sum[k].payload       = stat(pay);
          sum[k].per_tonne     = stat(per_t);
          sum[k].total_of_bed = tot, sum[k].payload_of_bed = pay, sum[k].per_tonne_of_bed = per_t;
        }
    }

    Change ConceptStudy::life_change_of(std::size_t k)
    {
      Change c = life_change(life_value[labels[k]], life_value[labels[0]]);
      c.significant = c.significant && k > 0;
      return c;
    }

    namespace
    {
      /// "mean +- std" of @p s, scaled by @p scale.
      std::string plus_minus(const Stat &s, double scale)
      {
        char buf[128];
        std::snprintf(buf, sizeof buf, "%.3g +- %.2g", scale * s.mean, scale * s.std);
        return buf;
      }

      /// A change in per cent with its interval and * where significant (a change without an
      /// interval, one bed: said so).
      std::string percent(const Change &c)
      {
        char buf[128];
        if (!c.interval)
          std::snprintf(buf, sizeof buf, "%+.1f %% (no interval: one bed)", 100 * (c.ratio - 1));
        else
          std::snprintf(buf, sizeof buf, "%+.1f %% [%+.1f, %+.1f]%s", 100 * (c.ratio - 1), 100 * (c.low - 1),
                        100 * (c.high - 1), c.significant ? " *" : "");
        return buf;
      }

      /// A change's CSV columns: per cent, half the interval, its ends, significant (one bed:
      /// the interval's cells empty).
      std::string change_columns(const Change &c)
      {
        std::ostringstream text;
        text.precision(8);
        text << ',' << 100 * (c.ratio - 1);
        if (c.interval)
          text << ',' << 50 * (c.high - c.low) << ',' << 100 * (c.low - 1) << ',' << 100 * (c.high - 1);
        else
          text << ",,,";
        text << ',' << (c.significant ? 1 : 0);
        return text.str();
      }
    } // namespace

    ConceptStudy::Changes ConceptStudy::changes_of(std::size_t k)
    {
      return {paired_change(sum[k].total_of_bed, sum[0].total_of_bed),
              paired_change(sum[k].payload_of_bed, sum[0].payload_of_bed),
              paired_change(sum[k].per_tonne_of_bed, sum[0].per_tonne_of_bed), life_change_of(k)};
    }

    void ConceptStudy::write_csv_head(std::ostream &csv) const
    {
      csv << "concept";
      for (const auto &p : phases)
        csv << ",wear_" << p << ",wear_" << p << "_std";
      csv << ",wear_total,wear_total_std,payload,payload_std,wear_per_tonne,wear_per_tonne_std,"
             "change_wear_total_percent,change_wear_total_uncertainty,change_wear_total_low_percent,"
             "change_wear_total_high_percent,change_wear_total_significant,"
             "change_payload_percent,change_payload_uncertainty,change_payload_low_percent,change_payload_high_percent,"
             "change_payload_significant,change_wear_per_tonne_percent,change_wear_per_tonne_uncertainty,"
             "change_wear_per_tonne_low_percent,change_wear_per_tonne_high_percent,change_wear_per_tonne_significant,"
             "predicted_life_tonnes,predicted_life_low,predicted_life_high,change_life_percent,change_life_uncertainty,change_life_low_percent,"
             "change_life_high_percent,change_life_significant\n";
    }

    void ConceptStudy::write_csv_row(std::ostream &csv, std::size_t k, const Changes &c)
    {
      csv << labels[k];
      for (const auto &p : phases)
        csv << ',' << sum[k].wear[p].mean << ',' << sum[k].wear[p].std;
      csv << ',' << sum[k].wear["total"].mean << ',' << sum[k].wear["total"].std << ',' << sum[k].payload.mean << ','
          << sum[k].payload.std << ',' << sum[k].per_tonne.mean << ',' << sum[k].per_tonne.std << change_columns(c.wear)
          << change_columns(c.payload) << change_columns(c.per_tonne) << ',' << (life.count(labels[k]) ? life[labels[k]] : "");
      if (life_value.count(labels[k]))
        csv << ',' << life_value[labels[k]].low << ',' << life_value[labels[k]].high << change_columns(c.life_change) << '\n';
      else
        csv << ",,,,,,,\n";
    }

    void ConceptStudy::write_md_head(std::ostream &md) const
    {
      md << "# Knife concepts (" << o.seeds.size() << " beds each; baseline: " << labels[0] << ")\n\n"
         << "Knife wear per cycle (" << wear_field << ", mean of the knives) in mm^3, payload in kg per cycle, mean +- "
            "standard deviation over the beds. Changes against the baseline pair by pair on the same beds: the "
            "geometric mean of the per-bed ratios and its 95 % interval [low, high]; * marks a significant change "
            "(the interval excludes no change). The predicted life: its 95 % interval in parentheses, its change against the "
            "baseline paired the same way, through every update's beds at the place that ends life (docs/lifetime.md, "
            "\"Two lives on the same beds\").\n\n"
         << "| concept |";
      for (const auto &p : phases)
        md << " wear " << p << " |";
      md << " wear total | payload [kg] | wear per tonne [mm^3/t] | change in wear | change in payload | change in wear per tonne |"
         << (o.lifetime_updates > 0 ? " predicted life [t] |" : "") << "\n|---|";
      for (std::size_t p = 0; p < phases.size() + 6 + (o.lifetime_updates > 0); ++p)
        md << "---|";
      md << '\n';
    }

    void ConceptStudy::write_md_row(std::ostream &md, std::size_t k, const Changes &c)
    {
      md << "| " << labels[k] << " |";
      for (const auto &p : phases)
        md << ' ' << plus_minus(sum[k].wear[p], 1e9) << " |";
      md << ' ' << plus_minus(sum[k].wear["total"], 1e9) << " | " << plus_minus(sum[k].payload, 1e3) << " | "
         << plus_minus(sum[k].per_tonne, 1e9) << " | " << (k ? percent(c.wear) : "baseline") << " | "
         << (k ? percent(c.payload) : "baseline") << " | " << (k ? percent(c.per_tonne) : "baseline") << " |";
      if (o.lifetime_updates > 0)
        {
          const auto &v = life_value[labels[k]];
          md << ' ' << life[labels[k]];
          if (v.low > 0)
            {
              char buf[128];
              std::snprintf(buf, sizeof buf, " (%.3g ... %.3g)", v.low, v.high);
              md << buf;
            }
          md << (k ? "; " + percent(c.life_change) : std::string()) << " |";
        }
      md << '\n';
    }

    void ConceptStudy::write_tables()
    {
      std::ofstream csv(out->file("concepts.csv"));
      csv.precision(8);
      write_csv_head(csv);
      std::ofstream md(out->file("concepts.md"));
      write_md_head(md);
      for (std::size_t k = 0; k < o.files.size(); ++k)
        {
          const Changes c = changes_of(k);
          write_csv_row(csv, k, c);
          write_md_row(md, k, c);
        }
      csv.close(), md.close();
    }

    void ConceptStudy::plot_wear()
    {
      // (the second plot reads the header line as a row: its first concept is row 1)
      std::ofstream dat(out->file("wear.dat"));
      dat << "concept";
      for (const auto &p : phases)
        dat << ' ' << p;
      dat << " total total_std\n";
      for (std::size_t k = 0; k < labels.size(); ++k)
        {
          dat << labels[k];
          for (const auto &p : phases)
            dat << ' ' << 1e9 * sum[k].wear[p].mean;
          dat << ' ' << 1e9 * sum[k].wear["total"].mean << ' ' << 1e9 * sum[k].wear["total"].std << '\n';
        }
      std::ofstream gp(out->file("wear.gp"));
      gp << "set terminal pngcairo size 900,600 noenhanced\nset output 'wear.png'\nset style data histograms\n"
            "set style histogram rowstacked\nset style fill solid 0.8 border -1\nset boxwidth 0.6\nset grid y\n"
            "set ylabel 'knife wear per cycle [mm^3]'\nset key outside\nset yrange [0:*]\nplot for [c=2:"
         << phases.size() + 1 << "] 'wear.dat' using c:xtic(1) title columnhead, '' using ($0-1):"
         << phases.size() + 2 << ":" << phases.size() + 3
         << " with yerrorbars lc rgb 'black' pt 7 ps 0.6 title 'total, +- std over the beds'\n";
    }
  } // namespace

  int run_concepts(const ConceptOptions &o, const std::string &abrade) { return ConceptStudy(o, abrade).run(); }
} // namespace abrade::coupling
