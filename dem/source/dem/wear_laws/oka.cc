// Oka's erosion law (Oka, Okamura and Yoshida 2005, "Practical estimation of erosion damage
// caused by solid particle impact, Part 1", Wear 259, 95-101): an impact of a particle of mass m,
// diameter D and speed V at the angle alpha to the surface removes the volume
//
//   dV = m E90 (V / V_ref)^k2 (D / D_ref)^k3 (sin alpha)^n1 (1 + Hv (1 - sin alpha))^n2
//
// with E90 the volume removed per unit particle mass at normal incidence at the reference speed
// and size, Hv the wall's Vickers hardness [GPa] and n1, n2, k2, k3 the law's exponents.
//
// An impact is counted once, at the first step of a contact (when its history begins), with the
// particle centre's velocity relative to the wall and its angle to the contact's tangent plane
// (sin alpha = |v . n| / |v|), while the particle approaches. Coarse-grained particles
// (Particles/Coarse graining/Factor f) erode as the f^3 real particles they stand for: their
// mass, each with the real diameter D = 2 r / f.
#include "plugin.h"

#include <algorithm>

namespace abrade::dem::wear_laws
{
  class Oka : public WearLaw
  {
  public:
    std::string name() const override { return "oka"; }
    std::string section() const override { return "Oka"; }
    std::string documentation() const override
    {
      return "Oka erosion (Oka et al. 2005): worn volume m E90 (V/V_ref)^k2 (D/D_ref)^k3 (sin a)^n1 "
             "(1 + Hv (1 - sin a))^n2 per impact (field oka_volume [m^3]; oka_depth = volume / triangle area).";
    }
    std::vector<WearField> fields() const override
    {
      return {{"oka_volume", "m^3", "volume eroded by impacts (Oka's law) summed over contacts", true}};
    }
    void declare_parameters(ParameterSection &p) const override
    {
      p.declare_number("Coefficient", 1e-8, 0, unbounded,
                       "[m^3/kg] E90: volume eroded per kg of impacting particles at normal incidence, at the "
                       "reference speed and diameter (about 1e-8 for sand on steel at 104 m/s: an order of "
                       "magnitude, to be calibrated). Range: >= 0.");
      p.declare_number("Hardness", 1.8, 0, 1000, "[GPa] Vickers hardness Hv of the wall. Range: [0, 1000].");
      p.declare_number("n1", 0.77, 0, 100,
                       "[-] Exponent of sin(alpha) (Oka et al. 2005 for SiO2 on a steel of Hv 1.8 GPa: "
                       "0.71 Hv^0.14). Range: [0, 100].");
      p.declare_number("n2", 1.38, 0, 100,
                       "[-] Exponent of 1 + Hv (1 - sin alpha) (SiO2 on steel: 2.4 Hv^-0.94). Range: [0, 100].");
      p.declare_number("Velocity exponent", 2.35, 0, 100,
                       "[-] k2, the exponent of V / V_ref (2.3 Hv^0.038). Range: [0, 100].");
      p.declare_number("Size exponent", 0.19, 0, 100, "[-] k3, the exponent of D / D_ref. Range: [0, 100].");
      p.declare_number("Reference velocity", 104, 1e-12, unbounded,
                       "[m/s] V_ref of the law's fit. Range: > 0.");
      p.declare_number("Reference diameter", 326e-6, 1e-12, unbounded,
                       "[m] D_ref of the law's fit (real particles: coarse-grained ones count with their real "
                       "diameter). Range: > 0.");
    }
    void parse_parameters(const ParameterSection &p, const WearContext &context) override
    {
      e90 = p.number("Coefficient"), hv = p.number("Hardness"), n1 = p.number("n1"), n2 = p.number("n2");
      k2 = p.number("Velocity exponent"), k3 = p.number("Size exponent");
      v_ref = p.number("Reference velocity"), d_ref = p.number("Reference diameter");
      coarse_graining = context.coarse_graining;
    }
    bool        uses_particle_size() const override { return true; }
    double      coefficient() const override { return e90; }
    std::string coefficient_name() const override { return "Coefficient"; }

    /// The volume one impact removes (speed @p v, sin of the angle to the surface @p sin_a).
    double volume(double mass, double diameter, double v, double sin_a) const
    {
      return mass * e90 * std::pow(v / v_ref, k2) * std::pow(diameter / d_ref, k3) * std::pow(sin_a, n1) *
             std::pow(1 + hv * (1 - sin_a), n2);
    }

    void record(const Simulation &sim, const ContactLog &log, WearDeposit &deposit) const override
    {
      const ParticleStore &P = sim.particles();
      deposit.for_each_contact(log, [&](const WallContactRecord &r) {
        if (!r.began)
          return;
        const double *v  = r.centre_velocity;
        const double  vm = length(v);
        const double  vn = v[0] * r.normal[0] + v[1] * r.normal[1] + v[2] * r.normal[2];
        if (!(vm > 0 && vn < 0)) // (the normal points from the wall to the particle)
          return;
        const double sin_a = std::min(1.0, -vn / vm);
        deposit.add(r, 0, volume(P.mass[r.particle], 2 * P.radius[r.particle] / coarse_graining, vm, sin_a));
      });
    }

  private:
    double e90 = 1e-8, hv = 1.8, n1 = 0.77, n2 = 1.38, k2 = 2.35, k3 = 0.19, v_ref = 104, d_ref = 326e-6;
    double coarse_graining = 1;
  };

  ABRADE_REGISTER_WEAR_LAW(Oka);
} // namespace abrade::dem::wear_laws
