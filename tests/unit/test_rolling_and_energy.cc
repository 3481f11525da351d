// Rolling resistance (EDEM constant directional torque): a sphere rolling on a plane decelerates
// at (5/7) mu_r g, and a sphere at rest under a large load stops spinning instead of chattering.
// And an e = 1 sphere bouncing on a plane under gravity keeps its energy.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

TEST(RollingFriction, RollingSphereDeceleratesAtFiveSeventhsMuRG)
{
  const Material glass{"glass", 48e9, 0.2, 2800, true};
  const double   R = 0.01, mu_r = 0.1, g = 9.81;
  Simulation     sim(quiet_settings(2e-6, true));
  const int      ms = sim.add_material(glass), mw = sim.add_material(glass);
  sim.set_interaction(ms, mw, {0.5, 0.5, mu_r});
  sim.add_wall(floor_wall(mw, 2.0));
  auto &P = sim.particles();
  P.add(0, -0.5, 0, R, R, glass.density, ms);
  sim.setup();
  sim.run_phase("rest", 0.02); // let the normal contact settle
  P.vx[0] = 1.0, P.wy[0] = 1.0 / R, P.vz[0] = 0;
  sim.run_phase("roll", 0.05);
  const double v1 = P.vx[0], t1 = sim.time();
  sim.run_phase("roll", 0.2);
  const double v2 = P.vx[0], t2 = sim.time();
  const double decel = (v1 - v2) / (t2 - t1);
  EXPECT_NEAR(decel / (5.0 / 7.0 * mu_r * g), 1, 1e-2);
  // still rolling without slip
  EXPECT_NEAR(P.wy[0] * R / P.vx[0], 1, 1e-3);
}

// A pellet pressed onto a plate with 3.2 kN (as pellets jammed under a knife are), at the case
// time step (0.2 x Rayleigh), with a small spin: the rolling resistance stops the spin and keeps
// it stopped. Applied as the torque -mu_r |F_n| R w/|w|, it would flip the spin by
// h mu_r |F_n| R / I = 0.26 rad/s every half step (7 mm/s of sliding at the contact point,
// which the wear laws count): this test fails with that form.
TEST(RollingFriction, PressedSphereAtRestStopsSpinningWithoutChatter)
{
  const Material pellet = Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, true);
  const Material steel  = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, true);
  const double   R = 0.0275, mu_r = 0.05;
  Settings       s = quiet_settings(1.146e-4);
  s.gravity        = Vec3(0, 0, -1000); // m g = 3.2 kN
  Simulation sim(s);
  const int  ms = sim.add_material(pellet), mw = sim.add_material(steel);
  sim.set_interaction(ms, mw, {0.6, 0.4, mu_r});
  sim.add_wall(floor_wall(mw, 0.5));
  auto &P = sim.particles();
  P.add(0, 0, 0, R * 0.99, R, pellet.density, ms);
  sim.setup();
  sim.run_phase("settle", 0.05); // damped onto the plate
  P.vx[0] = P.vy[0] = P.vz[0] = 0;
  P.wy[0]          = 0.01;
  double largest   = 0;
  for (int k = 0; k < 2000; ++k)
    {
      sim.step();
      largest = std::max(largest, std::abs(P.wx[0]) + std::abs(P.wy[0]) + std::abs(P.wz[0]));
    }
  EXPECT_LE(largest, 0.01 + 1e-12);
  EXPECT_LT(std::abs(P.wy[0]), 1e-9);
  EXPECT_LT(std::abs(P.vx[0]), 1e-6); // nothing rolls
}

TEST(EnergyConservation, ElasticBouncingSphereKeepsItsHeight)
{
  const Material glass{"glass", 48e9, 0.2, 2800, false};
  const double   R = 0.01, h0 = 0.05;
  Simulation     sim(quiet_settings(1e-6, true));
  const int      ms = sim.add_material(glass), mw = sim.add_material(glass);
  sim.set_interaction(ms, mw, {1.0, 0.0, 0.0});
  sim.add_wall(floor_wall(mw, 0.5));
  auto &P = sim.particles();
  P.add(0, 0, 0, R + h0, R, glass.density, ms);
  sim.setup();
  // the apex of each of five flights after a bounce must return to the drop height
  std::vector<double> apexes;
  double              apex = 0;
  bool                flying = true;
  while (apexes.size() < 5)
    {
      sim.step();
      const bool now_flying = P.z[0] > R;
      apex                  = std::max(apex, P.z[0]);
      if (flying && !now_flying)
        apex = 0; // landed
      if (!flying && now_flying)
        apex = P.z[0]; // took off
      if (now_flying && P.vz[0] < 0 && P.vz[0] + 9.81 * sim.dt() >= 0)
        apexes.push_back(apex); // passed the apex this step
      flying = now_flying;
    }
  for (double a : apexes)
    EXPECT_NEAR((a - R) / h0, 1, 1e-3);
  const double energy = sim.kinetic_energy() + P.mass[0] * 9.81 * (P.z[0] - R);
  EXPECT_NEAR(energy / (P.mass[0] * 9.81 * h0), 1, 1e-3);
}
