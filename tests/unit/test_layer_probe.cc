// The contact-layer probe counts the particles whose centre lies within its thickness of the
// wall's surface (in the wall's moving frame) and averages their velocity along its axis.
#include "dem_test_helpers.h"

#include <abrade/dem/layer_probe.h>

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

TEST(LayerProbe, CountsTheLayerAndAveragesItsVelocity)
{
  Simulation sim(quiet_settings(1e-5));
  const int  mp = sim.add_material(Material::from_shear_modulus("p", 1e8, 0.25, 3700, false));
  const int  mw = sim.add_material(Material::from_shear_modulus("s", 7e10, 0.3, 7800, false));
  sim.set_interaction(mp, mw, {0.6, 0.0, 0.0});
  Wall knife;
  knife.name = "knife", knife.material = mw;
  knife.mesh = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  knife.mesh.refine(0.05);
  knife.motion.kind                      = WallMotion::Kind::prescribed;
  knife.motion.phases["travel"].velocity = Vec3(1.5, 0, 0);
  sim.add_wall(knife);
  auto &P = sim.particles();
  const double r = 0.01;
  // beside the side face (y = +0.015): centre 0.012 from it (in the layer), 0.05 (not)
  P.add(0, 0.0, 0.015 + 0.012, 0.25, r, 3700, mp);
  P.add(1, 0.1, 0.015 + 0.012, 0.30, r, 3700, mp);
  P.add(2, 0.0, 0.015 + 0.05, 0.25, r, 3700, mp);
  P.add(3, 0.5, 0.0, 0.25, r, 3700, mp); // ahead of the knife's end, 0.3 m away
  for (int i : {0, 1})
    P.vx[i] = 1.0;
  P.vx[2] = 5.0, P.vx[3] = 7.0;
  sim.setup();
  auto probe = std::make_shared<LayerProbe>(sim, 0, 0.015, Vec3(2, 0, 0), 1);
  sim.add_hook(probe);
  sim.run_phase("travel", 1e-5);
  ASSERT_EQ(probe->samples().size(), 1u);
  const auto &s = probe->samples()[0];
  EXPECT_EQ(s.count, 2);
  EXPECT_NEAR(s.mean_velocity, 1.0, 1e-12);
  EXPECT_NEAR(s.wall_velocity, 1.5, 1e-12);
  EXPECT_EQ(s.phase, "travel");
  // the knife moves on at 1.5 m/s for 0.2 s in all
  sim.run_phase("travel", 0.2 - 1e-5);
  EXPECT_NEAR(sim.wall(0).translation[0], 0.3, 1e-9);
}
