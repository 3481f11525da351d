// Lifetime/Wear source = replay: the unfiltered wear another lifetime run of the case stored
// (its wear/ directory), carried onto this run's surface and scaled to this case's W
// (stored_wear.h; wear_source.h): the same life at another footprint, or W, without a DEM run.
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/coupling/lifetime/wear_calibration.h>
#include <abrade/coupling/lifetime/wear_source.h>

#include <filesystem>

namespace abrade::coupling::lifetime
{
  namespace
  {
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
                          "[directory] Wear source = replay: the output directory of the lifetime run whose "
                          "stored wear (wear/update_*.wear) is replayed (relative to this file; give an absolute path on the command line). Its beds are "
                          "the replay's; beyond the tonnes it reached its last update's wear is used (warned). "
                          "The wear is scaled by this case's W over the stored run's.");
      }

      void parse_parameters(ParameterFile &file) override
      {
        const std::string given = file.handler().get("Run");
        if (given.empty())
          file.fail(path(), "Run", "Wear source = replay needs the directory of a lifetime run");
        run = file.path_beside(given);
      }

      std::unique_ptr<WearSource> make(const WearSourceSetUp &s) const override
      {
        std::error_code ec;
        if (std::filesystem::equivalent(run, s.ctx.output.root(), ec))
          s.ctx.parameters.fail(path(), "Run", run + " is this run's own output directory: its stored "
                                "wear would be overwritten by the replay's; give the replay another --output");
        std::unique_ptr<WearSource> source;
        try
          {
            source = make_replayed_wear_source(run, s.design, s.mesh_size, s.dem_case.factor_at_tools());
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
        s.ctx.log.line("wear replayed from " + run + " (its stored wear, no DEM" + scaled + ")");
        return source;
      }
      std::string description() const override { return "the stored wear of " + run; }
      // (its stored wear, carried onto this run's surfaces: stored_wear.h)
      void add_results(io::Json &r) const override { r["replayed_run"] = run; }

    private:
      std::string run; ///< Replay/Run, resolved
    };
  } // namespace

  ABRADE_REGISTER_WEAR_SOURCE(ReplaySource);
} // namespace abrade::coupling::lifetime
