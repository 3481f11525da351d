// Archard's sliding wear as EDEM implements it: each contact removes Q = W max(F_n, 0) |v_t| dt
// per step, with v_t the sliding velocity of the contact point and W = K / H the wear
// coefficient over the hardness (Archard 1953; EDEM's "Archard wear" model). The default wear
// law of a knife.
#include "plugin.h"

#include <algorithm>

namespace abrade::dem::wear_laws
{
  class Archard : public WearLaw
  {
  public:
    std::string name() const override { return "archard"; }
    std::string section() const override { return "Archard"; }
    std::string documentation() const override
    {
      return "Archard sliding wear as in EDEM: worn volume W max(F_n, 0) |v_t| dt per contact and step "
             "(field archard_volume [m^3]; archard_depth = volume / triangle area).";
    }
    std::vector<WearField> fields() const override
    {
      return {{"archard_volume", "m^3", "W max(F_n, 0) |v_t| dt summed over contacts and steps", true}};
    }
    void declare_parameters(ParameterSection &p) const override
    {
      p.declare_number("Coefficient", 2e-14, 0, unbounded,
                       "[1/Pa] W = K / H of this wall against the particles. Default: K = 1e-4 (dimensionless "
                       "wear coefficient of iron ore on steel, within the 1e-5..1e-3 of the literature) over "
                       "H = 5e9 Pa (a wear-resistant steel, ~500 HB): an order of magnitude only, to be "
                       "calibrated against measured wear (abrade calibrate). The thesis' SFC study uses W = 1 "
                       "(relative values). Range: >= 0.");
    }
    void parse_parameters(const ParameterSection &p, const WearContext &) override { w = p.number("Coefficient"); }
    double      coefficient() const override { return w; }
    std::string coefficient_name() const override { return "Coefficient"; }

    void record(const Simulation &sim, const ContactLog &log, WearDeposit &deposit) const override
    {
      const double dt = sim.dt();
      deposit.for_each_contact(log, [&](const WallContactRecord &r) {
        deposit.add(r, 0, w * std::max(r.normal_force, 0.0) * length(r.tangential_velocity) * dt);
      });
    }

  private:
    double w = 2e-14;
  };

  ABRADE_REGISTER_WEAR_LAW(Archard);
} // namespace abrade::dem::wear_laws
