// End of life: the edge's recession as a height gauge reads it along the whole edge, at its
// worst station (edge_gauge.h, end_of_life_criterion.h).
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <cmath>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class MaximumEdgeRecession : public EndOfLifeCriterion
    {
    public:
      std::string parameter() const override { return "Maximum edge recession"; }
      std::string name() const override { return "maximum edge recession"; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry(parameter(), "0", dealii::Patterns::Double(0),
                          "[m] End of life: the edge's recession as a height gauge reads it along the whole "
                          "edge -- at Gauge stations stations from end to end, corners included, the rise of "
                          "the part's lowest point in the cross-section above the design's -- at its worst "
                          "station; 0: no limit. Unlike Maximum recession it needs no points and misses no "
                          "corner. Range: >= 0.");
      }
      void parse_parameters(dealii::ParameterHandler &prm) override
      {
        maximum = prm.get_double(parameter());
      }
      bool   active() const override { return maximum > 0; }
      double limit(const PartNow &, std::vector<std::string> &) const override { return maximum; }

      double value(const PartNow &now) const override { return now.gauge.recession; }

      // where the worst station's edge was gauged before the move (a gauge's point moves as
      // the triangle under it does)
      std::vector<double> bed_rates(const PartNow &now, const BedRates &beds) const override
      {
        std::vector<double> rates;
        for (const auto &bed : beds.edge)
          rates.push_back(bed[now.gauge.recession_station]);
        return rates;
      }

      // every station, as the gauge reads it (edge_gauge.cc): a section cut away entirely has
      // receded to the design's top
      Places places(const PartNow &now, const BedRates &beds) const override
      {
        const EdgeSections &worn = now.sections, &design = now.design_at_sections;
        Places              p{std::vector<double>(worn.x.size()), beds.edge};
        for (std::size_t i = 0; i < worn.x.size(); ++i)
          p.values[i] = (std::isfinite(worn.height[i]) ? worn.height[i] : design.top[i]) - design.height[i];
        return p;
      }

      std::vector<double> where(const PartNow &now, const std::vector<double> &, bool projected) const override
      {
        if (projected)
          return {};
        const auto &p = now.sections.lowest[now.gauge.recession_station];
        return {p[0], p[1], p[2]};
      }
      void        mark_limit(TrajectoryMarks &m) const override { m.edge_limit = maximum; }
      bool        drawn_in_trajectory() const override { return true; }
      std::string section_label() const override
      {
        return "edge recession (a height gauge, between the dashed lines) ";
      }
      void section_drawing(SectionMark &mark) const override { mark.lowest_points = true; }

    private:
      double maximum = 0;
    };
  } // namespace

  ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumEdgeRecession);
} // namespace abrade::coupling::lifetime
