// A poured heap of non-rotating frictional spheres (the thesis' pellet model, docs/physics.md) stands at a finite
// angle of repose that does not change once the heap is at rest.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

TEST(AngleOfRepose, PouredHeapIsStableAndFinite)
{
  const Material grain = Material::from_shear_modulus("grain", 1e7, 0.25, 2500, false);
  Settings       s;
  s.threads          = 2;
  const PouredHeap h = pour_heap(s, grain, {0.5, 0.5, 0.0});
  std::printf("angle of repose: %.1f deg after 1.5 s, %.1f deg after 2.0 s; kinetic energy %.3g J\n", h.after_pour,
              h.after_rest, h.kinetic_energy);
  EXPECT_GT(h.after_pour, 10);
  EXPECT_LT(h.after_pour, 60);
  EXPECT_NEAR(h.after_rest, h.after_pour, 1.0);
  EXPECT_LT(h.kinetic_energy, 1e-3);
}
