// Finnie's erosion as LIGGGHTS' `wear finnie` implements it (Finnie 1960): per contact and step
// 2 k |v| |F| f(gamma) dt / A, with v the particle centre's velocity relative to the wall, gamma
// its angle to the triangle's plane, f = cos^2(gamma) / 3 for tan(gamma) > 1/3 and
// sin(2 gamma) - 3 sin^2(gamma) otherwise, A the triangle's area; no wear while the particle
// moves away from the wall. Checked against LIGGGHTS itself (tests/unit/test_finnie_liggghts.cc).
#include "plugin.h"

#include <algorithm>

namespace abrade::dem::wear_laws
{
  class Finnie : public WearLaw
  {
  public:
    std::string name() const override { return "finnie"; }
    std::string section() const override { return "Finnie"; }
    std::string documentation() const override
    {
      return "Finnie impact wear as LIGGGHTS' `wear finnie`: 2 k |v| |F| f(gamma) dt / A per contact and step "
             "(field finnie_wear [m], per triangle area).";
    }
    std::vector<WearField> fields() const override
    {
      return {{"finnie_wear", "m", "2 k |v| |F| f(gamma) dt / A summed over contacts and steps", false, true}};
    }
    void declare_parameters(ParameterSection &p) const override
    {
      p.declare_number("Coefficient", 1, 0, unbounded,
                       "[-] k_finnie of the Finnie law (LIGGGHTS' peratomtypepair value). Range: >= 0.");
    }
    void parse_parameters(const ParameterSection &p, const WearContext &) override { k = p.number("Coefficient"); }
    double      coefficient() const override { return k; }
    std::string coefficient_name() const override { return "Coefficient"; }

    void record(const Simulation &sim, const ContactLog &log, WearDeposit &deposit) const override
    {
      const double dt = sim.dt();
      deposit.for_each_contact(log, [&](const WallContactRecord &r) {
        const double *v  = r.centre_velocity;
        const double  vm = length(v);
        // the contact point lies at -normal from the centre: only approaching particles wear
        const double approach = -(v[0] * r.normal[0] + v[1] * r.normal[1] + v[2] * r.normal[2]);
        if (!(vm > 1e-7 && approach >= 0))
          return;
        const Vec3   n     = sim.wall(r.wall).current_normal(r.triangle);
        const double vn    = std::abs(v[0] * n[0] + v[1] * n[1] + v[2] * n[2]);
        const double sin_g = std::min(1.0, vn / vm);
        const double cos_g = std::min(1.0, std::sqrt(std::max(0.0, vm * vm - vn * vn)) / vm);
        const double fg    = (cos_g < 1e-3 || 3 * sin_g > cos_g) ? cos_g * cos_g / 3 : 2 * sin_g * cos_g - 3 * sin_g * sin_g;
        const double fmag  = std::sqrt(r.normal_force * r.normal_force + r.tangential_force[0] * r.tangential_force[0] +
                                      r.tangential_force[1] * r.tangential_force[1] +
                                      r.tangential_force[2] * r.tangential_force[2]);
        deposit.add(r, 0, 2 * k * vm * fmag * fg * dt);
      });
    }

  private:
    double k = 1;
  };

  ABRADE_REGISTER_WEAR_LAW(Finnie);
} // namespace abrade::dem::wear_laws
