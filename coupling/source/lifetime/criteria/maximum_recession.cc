// End of life: the largest recession of the followed points (Lifetime/Recession points), how far
// the surface point that was there on the design has moved (end_of_life_criterion.h).
#include <abrade/common/format_number.h>
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <deal.II/base/bounding_box.h>

#include <algorithm>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class MaximumRecession : public EndOfLifeCriterion
    {
    public:
      std::string parameter() const override { return "Maximum recession"; }
      std::string name() const override { return "maximum recession"; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry(parameter(), "0", dealii::Patterns::Double(0),
                          "[m] End of life: the largest recession of the Recession points; 0: no limit. Range: >= 0.");
      }
      void parse_parameters(dealii::ParameterHandler &prm) override { maximum = prm.get_double(parameter()); }
      bool active() const override { return maximum > 0; }

      double limit(const PartNow &design, std::vector<std::string> &warnings) const override
      {
        const dealii::BoundingBox<3> box(design.part.design_surface().vertices);
        const double size = std::max({box.side_length(0), box.side_length(1), box.side_length(2)});
        if (maximum > size)
          warnings.push_back("Lifetime/Maximum recession " + io::format_number(maximum) + " m is more than the "
                             "part's largest extent (" + io::format_number(size) + " m): no edge recedes that far, "
                             "and a life to it is an extrapolation beyond the part (a length in millimetres?)");
        return maximum;
      }

      double value(const PartNow &now) const override
      {
        const auto r = now.part.recession_at(now.followed_points);
        return *std::max_element(r.begin(), r.end());
      }

      // at the followed point that has receded most after this update (a tip recedes faster
      // than its depth, by a factor the same for all beds)
      std::vector<double> bed_rates(const PartNow &now, const BedRates &beds) const override
      {
        std::vector<double> rates;
        for (const auto &bed : beds.followed)
          rates.push_back(bed[most_receded(now)]);
        return rates;
      }

      Places places(const PartNow &now, const BedRates &beds) const override
      {
        return {now.part.recession_at(now.followed_points), beds.followed};
      }

      std::vector<double> where(const PartNow &now, const std::vector<double> &, bool projected) const override
      {
        if (projected)
          return {};
        const auto &p = now.followed_points[most_receded(now)];
        return {p[0], p[1], p[2]};
      }
      void        mark_limit(TrajectoryMarks &m) const override { m.recession_limit = maximum; }
      bool        drawn_in_trajectory() const override { return true; }
      std::string section_label() const override { return "recession of the followed point (circled) "; }
      void        section_drawing(SectionMark &) const override {}

    private:
      static std::size_t most_receded(const PartNow &now)
      {
        const auto r = now.part.recession_at(now.followed_points);
        return std::size_t(std::max_element(r.begin(), r.end()) - r.begin());
      }
      double maximum = 0;
    };
  } // namespace

  ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumRecession);
} // namespace abrade::coupling::lifetime
