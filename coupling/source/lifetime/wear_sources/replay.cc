// Lifetime/Wear source = replay: the unfiltered wear another lifetime run of the case stored
// (its wear/ directory), carried onto this run's surface and scaled to this case's W
// (stored_wear.h; wear_source.h): the same life at another footprint, or W, without a DEM run.
// With Replay/DEM from, the DEM's own cycles from those tonnes on: the part as the replay wore
// it, then the wear with the geometry's feedback (the replay leaves it out).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/list_items.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/coupling/lifetime/wear_calibration.h>
#include <abrade/coupling/lifetime/wear_source.h>

#include <algorithm>
#include <filesystem>
#include <set>

namespace abrade::coupling::lifetime
{
  namespace
  {
    /// The stored wear for the cycles before @p from tonnes, the DEM's from there on.
    class ReplayThenDem : public WearSource
    {
    public:
      ReplayThenDem(std::unique_ptr<WearSource> replay, std::unique_ptr<WearSource> dem, double from)
        : replay(std::move(replay)), dem(std::move(dem)), from(from)
      {}

      CycleWear cycle(const fem::SolidSurface &surface, double tonnes, const std::vector<int> &bed_seeds) override
      {
        dem_now     = tonnes >= from;
        CycleWear w = (dem_now ? dem : replay)->cycle(surface, tonnes, bed_seeds);
        if (!dem_now)
          replayed.insert(w.bed_seeds.begin(), w.bed_seeds.end());
        else // (a stored run of the same seeds has had the DEM's beds of a later update in it)
          {
            std::vector<std::string> twice;
            for (int seed : bed_seeds)
              if (replayed.count(seed))
                twice.push_back(std::to_string(seed));
            if (!twice.empty()) // (a note: the set-up's, not a fault of the DEM's cycle)
              w.notes.push_back("the beds of seeds " + io::list_text(twice) + " were replayed before (a stored "
                                "update's): the life's interval counts them twice (too narrow)");
          }
        return w;
      }
      std::vector<std::string> phases() const override { return replay->phases(); }
      double                   wear_coefficient() const override { return dem->wear_coefficient(); }
      bool                     removes_volume() const override { return replay->removes_volume(); }
      /// (the last cycle's: the loop counts the DEM's warnings, not a replay's)
      std::string name() const override { return (dem_now ? dem : replay)->name(); }

    private:
      std::unique_ptr<WearSource> replay, dem;
      double                      from;
      bool                        dem_now = false;
      std::set<int>               replayed; ///< the beds of the replayed cycles
    };

    class ReplaySource : public WearSourceChoice
    {
    public:
      std::string name() const override { return "replay"; }
      std::string documentation() const override
      {
        return "the unfiltered wear another lifetime run of this case stored (its wear/ directory, Replay/"
               "Run), carried onto this run's surface: the same life at another Smoothing radius (a candidate "
               "footprint for abrade calibrate) or W without a DEM run (docs/field.md)";
      }
      std::string section() const override { return "Replay"; }
      bool        from_particles() const override { return true; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Run", "", dealii::Patterns::Anything(),
                          "[directory, ...] Wear source = replay: the output directory of the lifetime run whose "
                          "stored wear (wear/update_*.wear) is replayed (relative to this file; give an absolute path on the command line). Its beds are "
                          "the replay's; beyond the tonnes it reached its last update's wear is used (warned). "
                          "Several directories (comma-separated; a directory whose name holds a comma cannot be "
                          "one of them): runs of this case on the same part, their beds "
                          "joined update by update as one run of all of them stores them, as long as their parts "
                          "are the same (e.g. one-update runs of one bed each, Lifetime/Cycles per update and "
                          "Maximum updates = 1, made apart; a grab's tonnes per cycle the beds' mean payload). "
                          "The wear is scaled by this case's W over the stored run's.");
        prm.declare_entry("DEM from", "0", dealii::Patterns::Double(0),
                          "[t] Wear source = replay: every cycle from this many tonnes handled on is the DEM's "
                          "(this case's beds, settled in the run as Wear source = dem settles them, on the part as "
                          "the replay wore it; under mpirun the ranks shared out among the beds, as Lifetime/DEM/"
                          "Ranks per bed = 0 does), "
                          "the cycles before it the stored wear's: the geometry's feedback from a worn state on, "
                          "at the cost of the DEM's cycles from there only (docs/field.md). 0: the stored wear "
                          "throughout. Range: [0, inf).");
      }

      void parse_parameters(ParameterFile &file) override
      {
        runs.clear();
        for (const auto &given : io::list_items(file.handler().get("Run"), ','))
          {
            runs.push_back(file.path_beside(given));
            if (std::count(runs.begin(), runs.end(), runs.back()) > 1)
              file.fail(path(), "Run", runs.back() + " is given twice: one run's beds twice are not more beds");
          }
        if (runs.empty())
          file.fail(path(), "Run", "Wear source = replay needs the directory of a lifetime run");
        dem_from = file.handler().get_double("DEM from");
      }

      std::unique_ptr<WearSource> make(const WearSourceSetUp &s) const override
      {
        std::error_code ec;
        for (const auto &r : runs)
          if (std::filesystem::equivalent(r, s.ctx.output.root(), ec))
            s.ctx.parameters.fail(path(), "Run", r + " is this run's own output directory: its stored "
                                  "wear would be overwritten by the replay's; give the replay another --output");
        std::unique_ptr<WearSource> source;
        try
          {
            source = make_replayed_wear_source(runs, s.design, s.mesh_size, s.dem_case.factor_at_tools(),
                                               s.tonnes_per_cycle == 0, s.seeds);
          }
        catch (const InputError &e)
          {
            s.ctx.parameters.fail(path(), "Run", e.what());
          }
        // scaled to this case's W where the stored run had another
        std::string  scaled;
        const double w_case = case_wear_coefficient(s.dem_case), w_stored = source->wear_coefficient();
        if (w_case > 0 && w_stored > 0 && w_case != w_stored)
          {
            source = make_calibrated_wear_source(std::move(source), w_case);
            scaled = ", scaled by this case's W over the stored run's, " + io::format_number(w_case, 4) + " / " +
                     io::format_number(w_stored, 4);
          }
        if (!(dem_from > 0))
          {
            s.ctx.log.line("wear replayed from " + io::list_text(runs) + " (its stored wear, no DEM" + scaled + ")");
            return source;
          }
        auto dem = make_dem_wear_source(s.dem_case, s.seeds, s.tonnes_per_cycle, 0, s.ctx);
        if (dem->phases() != source->phases())
          s.ctx.parameters.fail(path(), "DEM from", "the stored run's cycle has other phases than this case's: "
                                "the DEM cannot go on from its wear");
        s.ctx.log.line("wear replayed from " + io::list_text(runs) + " (its stored wear" + scaled + ") until " +
                       io::format_number(dem_from, 6) + " t, the DEM's cycles from there on (Replay/DEM from)");
        return std::make_unique<ReplayThenDem>(std::move(source), std::move(dem), dem_from);
      }
      std::string description() const override
      {
        return "the stored wear of " + io::list_text(runs) + (dem_from > 0 ? ", the DEM from " + io::format_number(dem_from, 6) + " t" : "");
      }
      // (its stored wear, carried onto this run's surfaces: stored_wear.h)
      void add_results(io::Json &r) const override
      {
        r["replayed_run"] = io::list_text(runs);
        if (dem_from > 0)
          r["dem_from_tonnes"] = dem_from;
        if (runs.size() > 1)
          for (const auto &each : runs)
            r["replayed_runs"].push_back(each);
      }

    private:
      std::vector<std::string> runs; ///< Replay/Run, resolved
      double                   dem_from = 0; ///< Replay/DEM from [t] (0: never)
    };
  } // namespace

  ABRADE_REGISTER_WEAR_SOURCE(ReplaySource);
} // namespace abrade::coupling::lifetime
