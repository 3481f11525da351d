// A poured heap of non-rotating frictional spheres (the seed's pellet model) stands at a finite
// angle of repose that does not change once the heap is at rest.
#include "dem_test_helpers.h"

#include <abrade/dem/generation.h>

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

TEST(AngleOfRepose, PouredHeapIsStableAndFinite)
{
  const Material grain = Material::from_shear_modulus("grain", 1e7, 0.25, 2500, false);
  Settings       s;
  s.threads = 2;
  Simulation sim(s);
  const int  mg = sim.add_material(grain), mw = sim.add_material(grain);
  sim.set_interaction(mg, mg, {0.5, 0.5, 0.0});
  sim.set_interaction(mg, mw, {0.5, 0.5, 0.0});
  sim.add_wall(floor_wall(mw, 2.0));
  FillRegion f;
  f.box_min = Vec3(-0.08, -0.08, 0.02), f.box_max = Vec3(0.08, 0.08, 0.6);
  f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.009, f.sizes.max = 0.011;
  f.count = 800, f.seed = 11;
  fill_region(sim, f);
  sim.setup();
  sim.run_phase("pour", 1.5);
  const double a1 = heap_angle(sim.particles());
  sim.run_phase("rest", 0.5);
  const double a2 = heap_angle(sim.particles());
  std::printf("angle of repose: %.1f deg after 1.5 s, %.1f deg after 2.0 s; kinetic energy %.3g J\n", a1, a2,
              sim.kinetic_energy());
  EXPECT_GT(a1, 10);
  EXPECT_LT(a1, 60);
  EXPECT_NEAR(a2, a1, 1.0);
  EXPECT_LT(sim.kinetic_energy(), 1e-3);
}
