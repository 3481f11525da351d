// End of life: the plate's remaining thickness, as calipers read it across the plate at the
// gauge height, at the thinnest station (edge_gauge.h, end_of_life_criterion.h). Its quantity is
// the thickness lost, so that it grows: its limit is the design's thickness less the minimum.
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class MinimumPlateThickness : public EndOfLifeCriterion
    {
    public:
      std::string parameter() const override { return "Minimum plate thickness"; }
      std::string name() const override { return "minimum plate thickness"; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry(parameter(), "0", dealii::Patterns::Double(0),
                          "[m] End of life: the plate's remaining thickness, as calipers across it read it at "
                          "Gauge height above the design's edge, at the thinnest of the Gauge stations; 0: no "
                          "limit. Range: >= 0.");
      }
      void parse_parameters(dealii::ParameterHandler &prm) override
      {
        minimum = prm.get_double(parameter());
      }
      bool active() const override { return minimum > 0; }

      double limit(const PartNow &design, std::vector<std::string> &) const override
      {
        if (!active())
          return 0;
        if (!(minimum < design.design_thickness))
          throw CriterionRefused(parameter(),
                                 io::format_number(minimum) + " m is not less than the design's plate thickness at "
                                 "the gauge height (" + io::format_number(design.design_thickness) + " m at " +
                                 io::format_number(design.gauge_height) + " m above the edge)");
        return design.design_thickness - minimum;
      }

      double value(const PartNow &now) const override { return now.design_thickness - now.gauge.thinnest; }

      // the mean of the two faces' rates at the thinnest station's gauge height, before the move
      std::vector<double> bed_rates(const PartNow &now, const BedRates &beds) const override
      {
        std::vector<double> rates;
        for (const auto &bed : beds.faces)
          rates.push_back(bed[now.gauge.thinnest_station]);
        return rates;
      }

      Places places(const PartNow &now, const BedRates &beds) const override
      {
        Places p{std::vector<double>(now.sections.x.size()), beds.faces};
        for (std::size_t i = 0; i < p.values.size(); ++i)
          p.values[i] = now.design_thickness - now.sections.thickness[i];
        return p;
      }

      std::vector<double> where(const PartNow &now, const std::vector<double> &, bool projected) const override
      {
        if (projected)
          return {};
        const std::size_t k = now.gauge.thinnest_station;
        return {now.sections.x[k], 0.5 * (now.sections.y_low[k] + now.sections.y_high[k]), now.gauge_z};
      }
      void        mark_limit(TrajectoryMarks &m) const override { m.plate_limit = minimum; }
      std::string section_label() const override { return "plate thickness lost "; }
      void        section_drawing(SectionMark &) const override {}

    private:
      double minimum = 0;
    };
  } // namespace

  ABRADE_REGISTER_END_OF_LIFE_CRITERION(MinimumPlateThickness);
} // namespace abrade::coupling::lifetime
