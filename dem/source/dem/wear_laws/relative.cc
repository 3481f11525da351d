// Relative wear as EDEM's "Relative Wear" model reports it: the cumulative normal and tangential
// contact energies |F_n v_n| dt and |F_t . v_t| dt per contact and step, which rank the regions
// of a wall by how hard they are worked without a wear coefficient.
#include "plugin.h"

namespace abrade::dem::wear_laws
{
  class Relative : public WearLaw
  {
  public:
    std::string name() const override { return "relative"; }
    std::string section() const override { return "Relative"; }
    std::string documentation() const override
    {
      return "Relative wear (EDEM): cumulative normal energy |F_n v_n| dt and tangential energy |F_t . v_t| dt "
             "[J] (fields relative_normal_energy, relative_tangential_energy).";
    }
    std::vector<WearField> fields() const override
    {
      return {{"relative_normal_energy", "J", "|F_n v_n| dt summed over contacts and steps"},
              {"relative_tangential_energy", "J", "|F_t . v_t| dt summed over contacts and steps"}};
    }

    void record(const Simulation &sim, const ContactLog &log, WearDeposit &deposit) const override
    {
      const double dt = sim.dt();
      deposit.for_each_contact(log, [&](const WallContactRecord &r) {
        const double ftvt = r.tangential_force[0] * r.tangential_velocity[0] +
                            r.tangential_force[1] * r.tangential_velocity[1] +
                            r.tangential_force[2] * r.tangential_velocity[2];
        deposit.add(r, 0, std::abs(r.normal_force * r.normal_velocity) * dt);
        deposit.add(r, 1, std::abs(ftvt) * dt);
      });
    }
  };

  ABRADE_REGISTER_WEAR_LAW(Relative);
} // namespace abrade::dem::wear_laws
