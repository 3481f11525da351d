// Rolling resistance (EDEM constant directional torque): a sphere rolling on a plane decelerates
// at (5/7) mu_r g. And an e = 1 sphere bouncing on a plane under gravity keeps its energy.
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
