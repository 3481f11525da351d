// Lifetime/Wear source = analytic: a known wear rate instead of the DEM, a function of the
// place and the tonnes (analytic_wear_source.cc; wear_source.h): verification of the loop, or
// rates measured elsewhere.
#include <abrade/coupling/lifetime/wear_source.h>

#include <stdexcept>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class AnalyticSource : public WearSourceChoice
    {
    public:
      std::string name() const override { return "analytic"; }
      std::string documentation() const override
      {
        return "the wear comes from the rate of subsection Analytic instead (verification of the loop, or wear "
               "rates measured elsewhere)";
      }
      std::string section() const override { return "Analytic"; }
      bool from_particles() const override { return false; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Wear rate", "1e-6", dealii::Patterns::Anything(),
                          "[m/t] Wear source = analytic: the depth worn off per tonne handled, along the "
                          "inward normal, as a function of the part's current coordinates x, y, z (the "
                          "part's own frame, see Recession points), of t, the tonnes handled so far, and of "
                          "zlow, the z of the part's lowest wearable point now, and zedge, the z of its lowest "
                          "wearable point within a longest triangle edge of the point along x (the edge "
                          "runs along x), e.g. '1e-6*exp(-z/0.01)', '1e-6*(1+t/5000)' or "
                          "'1e-6*(z < zedge + 0.003)' (a band on the edge line that follows each part of it up); "
                          "evaluated at the surface's vertices. muparser syntax.");
        prm.declare_entry("Wear is", "depth", dealii::Patterns::Selection("depth|volume"),
                          "Wear source = analytic: depth: the surface recedes by the rate x tonnes along its "
                          "normal (the offset surface, exact: verification of the motion); volume: the rate x "
                          "tonnes x each vertex's area is a volume removed, as the DEM's Archard volume is, "
                          "and every update's moved surface is corrected so that the part loses exactly it "
                          "(an offset surface loses less at convex edges).");
        prm.declare_entry("Seed scatter", "0", dealii::Patterns::Double(0, 1),
                          "[-] Wear source = analytic: each bed's rate is multiplied by a lognormal factor "
                          "of mean 1 and this relative standard deviation, drawn from the bed's seed (a fresh "
                          "one every update): a known bed-to-bed scatter (verification of the life's "
                          "interval). Range: [0, 1].");
      }

      void parse_parameters(ParameterFile &file) override
      {
        auto &prm    = file.handler();
        expression   = prm.get("Wear rate");
        scatter      = prm.get_double("Seed scatter");
        as_volume    = prm.get("Wear is") == "volume";
      }

      std::unique_ptr<WearSource> make(const WearSourceSetUp &s) const override
      {
        try
          {
            return make_analytic_wear_source(expression, s.tonnes_per_cycle, scatter, as_volume);
          }
        catch (const std::invalid_argument &e)
          {
            s.ctx.parameters.fail(path(), "Wear rate", e.what());
          }
      }
      std::vector<std::string> rate_entry() const override { return {"Lifetime", section(), "Wear rate"}; }
      std::string description() const override { return "the analytic rate " + expression; }

    private:
      std::string expression;
      double      scatter   = 0;
      bool        as_volume = false;
    };
  } // namespace

  ABRADE_REGISTER_WEAR_SOURCE(AnalyticSource);
} // namespace abrade::coupling::lifetime
