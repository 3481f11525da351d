// End of life: the largest wear depth, the distance of the worn surface below the design
// surface, as `abrade compare` measures a scan (end_of_life_criterion.h).
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <algorithm>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class MaximumDepth : public EndOfLifeCriterion
    {
    public:
      std::string parameter() const override { return "Maximum depth"; }
      std::string name() const override { return "maximum depth"; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry(parameter(), "0.012", dealii::Patterns::Double(0),
                          "[m] End of life: the largest wear depth, the distance of the worn surface below the "
                          "design surface (as abrade compare measures a scan; not the vertex displacement, which "
                          "is 2.9-3x larger at a chisel's tip and corners); 0: no limit. It cannot exceed half the "
                          "local plate thickness (a worn-back edge is measured by Maximum recession). Range: >= 0.");
      }
      void parse_parameters(dealii::ParameterHandler &prm) override { maximum = prm.get_double(parameter()); }
      bool active() const override { return maximum > 0; }

      double limit(const PartNow &design, std::vector<std::string> &warnings) const override
      {
        const double thickness = design.part.thickness();
        // a limit the part cannot reach is "reached" only by an extrapolation far beyond anything
        // the run followed (1 m on a 30 mm knife gave 5.5e8 t without a word)
        if (maximum > thickness)
          warnings.push_back("Lifetime/Maximum depth " + io::format_number(maximum) + " m is more than the part's "
                             "plate thickness (" + io::format_number(thickness) + " m): no depth below the design "
                             "reaches it, and a life to it is an extrapolation beyond the part (a length in "
                             "millimetres?)");
        else if (maximum >= 0.5 * thickness)
          warnings.push_back("Maximum depth " + io::format_number(maximum) + " m is at least half the plate "
                             "thickness (" + io::format_number(thickness) + " m): the wear depth below the design "
                             "is the distance to the nearest design surface and cannot exceed that; the edge's "
                             "recession is Maximum recession (of the Recession points)");
        return maximum;
      }

      double value(const PartNow &now) const override
      {
        const auto &depth = now.part.wear_depth();
        return depth.empty() ? 0.0 : *std::max_element(depth.begin(), depth.end());
      }

      // at the vertex that is deepest after this update
      std::vector<double> bed_rates(const PartNow &, const BedRates &beds) const override
      {
        const Rates &r = *beds.rates;
        std::size_t  deepest = 0;
        double       most    = -1;
        for (std::size_t v = 0; v < r.mean.size(); ++v)
          if (beds.depth_before[v] + beds.cycles * r.mean[v] > most)
            most = beds.depth_before[v] + beds.cycles * r.mean[v], deepest = v;
        std::vector<double> rates;
        for (const auto &bed : r.seed)
          rates.push_back(bed[deepest]);
        return rates;
      }

      // at the points the design's vertices moved to
      Places places(const PartNow &now, const BedRates &beds) const override
      {
        return {now.part.at_followed_points(now.part.wear_depth(), now.part.design_surface().vertices),
                beds.design_points};
      }

      double projected(const PartNow &, const BedRates &beds, double) const override
      {
        double deepest = 0;
        for (std::size_t v = 0; v < beds.rates->mean.size(); ++v)
          deepest = std::max(deepest, beds.depth_before[v] + beds.cycles * beds.rates->mean[v]);
        return deepest;
      }

      std::vector<double> where(const PartNow &, const std::vector<double> &deepest, bool) const override
      {
        return deepest;
      }
      void        mark_limit(TrajectoryMarks &m) const override { m.depth_limit = maximum; }
      bool        drawn_in_trajectory() const override { return true; }
      std::string section_label() const override { return "depth below the design "; }

    private:
      double maximum = 0;
    };
  } // namespace

  ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumDepth);
} // namespace abrade::coupling::lifetime
