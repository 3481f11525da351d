// Chung & Ooi (2011) tests 3 and 4 (shared/reference/verification.md).
//  3: normal impact with damping: the rebound restitution equals the input one exactly with the
//     calibrated damping; with EDEM's documented formula it differs, by an amount we measure and
//     bound (docs/physics.md reports it).
//  4: oblique impact with friction: above 32.5 deg the sphere slides throughout and rigid-body
//     theory is exact for the tangential restitution and the rebound spin.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

#include <cstdio>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material alumina{"aluminium oxide", 380e9, 0.23, 4000, true};
  const Material cast_iron{"cast iron", 100e9, 0.25, 7000, true};
  constexpr double R = 0.0025, V = 3.9;

  struct Rebound
  {
    Vec3 velocity, spin;
  };

  Rebound impact(const Material &mat, double restitution, double friction, double angle_deg,
                 DampingModel damping, double spin = 0)
  {
    const double m = sphere_mass(R, mat.density);
    const HertzImpact a(m, R, e_star(mat, mat), V);
    Settings s = quiet_settings(a.contact_time / 200);
    s.damping  = damping;
    Simulation sim(s);
    const int ms = sim.add_material(mat), mw = sim.add_material(mat);
    sim.set_interaction(ms, mw, {restitution, friction, 0.0});
    sim.add_wall(floor_wall(mw, 0.1));
    auto &P = sim.particles();
    P.add(0, 0, 0, R + 1e-7, R, mat.density, ms);
    const double th = angle_deg * M_PI / 180;
    P.vx[0] = V * std::sin(th), P.vz[0] = -V * std::cos(th);
    P.wy[0] = spin;
    sim.setup();
    bool touched = false;
    for (int k = 0; k < 100000; ++k)
      {
        sim.step();
        const double overlap = R - sim.particles().z[0];
        touched |= overlap > 0;
        if (touched && overlap < 0)
          break;
      }
    const auto &Q = sim.particles();
    return {Vec3(Q.vx[0], Q.vy[0], Q.vz[0]), Vec3(Q.wx[0], Q.wy[0], Q.wz[0])};
  }
} // namespace

TEST(ChungOoi, Test3CalibratedDampingReproducesRestitution)
{
  for (const Material &mat : {alumina, cast_iron})
    for (double e : {0.2, 0.4, 0.6, 0.8, 1.0})
      {
        const Rebound r = impact(mat, e, 0.0, 0.0, DampingModel::calibrated);
        EXPECT_NEAR(r.velocity[2] / V, e, 2e-3) << mat.name << " e = " << e;
      }
}

TEST(ChungOoi, Test3EdemDampingErrorIsMeasured)
{
  // EDEM's beta formula comes from a linear spring. With the Hertz damping S_n-scaled as EDEM
  // does it (c ~ delta^1/4) the rebound restitution still matches the input: the dimensionless
  // contact ODE gives |e_out - e| < 2e-6; at dt = t_c/200 the time integration adds ~1e-3.
  // Print the measured values and bound the error.
  double worst = 0;
  for (double e : {0.2, 0.4, 0.6, 0.8, 1.0})
    {
      const Rebound r     = impact(alumina, e, 0.0, 0.0, DampingModel::edem);
      const double  e_out = r.velocity[2] / V;
      std::printf("EDEM damping: input e %.1f -> rebound e %.4f\n", e, e_out);
      worst = std::max(worst, std::abs(e_out - e));
    }
  EXPECT_LT(worst, 2e-3);
  for (double e : {0.2, 0.5, 0.9})
    EXPECT_NEAR(hertz_restitution(-2 * std::sqrt(5.0 / 6.0) * edem_beta(e)), e, 1e-5);
}

TEST(ChungOoi, Test4ObliqueImpactMatchesRigidBodyTheoryWhenSliding)
{
  const double mu = 0.092, e = 0.98;
  struct Expected
  {
    double angle, et, spin;
  };
  // published: 40 deg: e_t 0.783, spin -544 rad/s; 60: 0.895, -355; 80: 0.968, -123
  for (const Expected x : {Expected{40, 0.783, 544}, Expected{60, 0.895, 355}, Expected{80, 0.968, 123}})
    {
      const double  th = x.angle * M_PI / 180;
      const Rebound r  = impact(alumina, e, mu, x.angle, DampingModel::calibrated);
      const double  et = r.velocity[0] / (V * std::sin(th));
      const double  et_theory   = 1 - mu * (1 + e) / std::tan(th);
      const double  spin_theory = 2.5 * mu * (1 + e) * V * std::cos(th) / R;
      SCOPED_TRACE(x.angle);
      EXPECT_NEAR(et, et_theory, 2e-3);
      EXPECT_NEAR(std::abs(r.spin[1]) / spin_theory, 1, 5e-3);
      EXPECT_NEAR(et, x.et, 2e-3);
      EXPECT_NEAR(std::abs(r.spin[1]) / x.spin, 1, 5e-3);
      // sliding in +x on a floor below spins the sphere about +y
      EXPECT_GT(r.spin[1], 0);
    }
}

TEST(ChungOoi, Test6NormalImpactOfASpinningSphere)
{
  // Chung & Ooi test 6 in its sliding regime: a sphere spinning fast about y hits the plane
  // normally (at a shared edge of the plane's two triangles); the contact point slides
  // throughout, so friction changes the spin by -2.5 mu (1+e) V / R and gives the centre a
  // tangential speed mu (1+e) V against the contact point's sliding direction.
  const double mu = 0.092, e = 0.98, spin = 2000;
  const Rebound r = impact(alumina, e, mu, 0.0, DampingModel::calibrated, spin);
  EXPECT_NEAR(r.spin[1], spin - 2.5 * mu * (1 + e) * V / R, 5e-3 * 2.5 * mu * (1 + e) * V / R);
  // the contact point (bottom) moves at -spin R in x, so friction pushes the sphere towards +x
  EXPECT_NEAR(r.velocity[0], mu * (1 + e) * V, 5e-3 * mu * (1 + e) * V);
  EXPECT_NEAR(r.velocity[2] / V, e, 2e-3);
}
