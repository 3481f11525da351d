// End of life: the mass worn off the whole part (end_of_life_criterion.h). One quantity of the
// whole part: no places, no place on the part where it ends.
#include <abrade/coupling/lifetime/end_of_life_criterion.h>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class MaximumWornMass : public EndOfLifeCriterion
    {
    public:
      std::string parameter() const override { return "Maximum worn mass"; }
      std::string name() const override { return "maximum worn mass"; }

      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry(parameter(), "0", dealii::Patterns::Double(0),
                          "[kg] End of life: the mass worn off the part; 0: no limit. Range: >= 0.");
      }
      void parse_parameters(dealii::ParameterHandler &prm) override { maximum = prm.get_double(parameter()); }
      bool   active() const override { return maximum > 0; }
      double limit(const PartNow &, std::vector<std::string> &) const override { return maximum; }

      double value(const PartNow &now) const override
      {
        return (now.design_volume - now.part.volume()) * now.density;
      }
      // each bed's worn volume per cycle (its relative scatter is the mass's)
      std::vector<double> bed_rates(const PartNow &, const BedRates &beds) const override
      {
        return beds.rates->seed_volume;
      }
      double projected(const PartNow &now, const BedRates &beds, double before) const override
      {
        return before + beds.cycles * beds.rates->wear_volume * now.density;
      }
      std::vector<double> where(const PartNow &, const std::vector<double> &, bool) const override { return {}; }
      std::string whole_part_note() const override { return "the whole part's worn mass ends the life; "; }

    private:
      double maximum = 0;
    };
  } // namespace

  ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumWornMass);
} // namespace abrade::coupling::lifetime
