// The geometry behind a multi-level bed's margin check (coupling/dem_run/fine_region_margin.h),
// against answers worked out by hand: the box a prescribed wall sweeps below a height, where a
// tilted face reaches farther at the height than any of its vertices below it (a vertex-only
// clip understates the reach by the face's tilt times its height there), and the bed's surface
// as the median column top, which a pellet standing on the heap does not move.
#include "dem_test_helpers.h"

#include <abrade/coupling/dem_run/fine_region_margin.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace abrade;

namespace
{
  /// A plate 0.2 m wide in x, rising from the line y = 0, z = 0 at @p tilt from the vertical
  /// towards +y, @p length long: two triangles.
  dem::Wall tilted_plate(double tilt, double length)
  {
    dem::Wall w;
    w.name = "plate";
    const double ty = length * std::sin(tilt), tz = length * std::cos(tilt);
    w.mesh.vertices  = {{-0.1, 0, 0}, {0.1, 0, 0}, {0.1, ty, tz}, {-0.1, ty, tz}};
    w.mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    return w;
  }
} // namespace

// The plate sinks 0.1 m, then travels 0.3 m along x; the bed's surface at z = 0.5 m. Below it
// the plate reaches y = (0.5 + 0.1) tan(20 deg) after sinking (where its face crosses the
// surface; its vertices below the surface all lie at y = 0), x from -0.1 to 0.4 m and z from
// -0.1 m up to the surface.
TEST(FineRegionMargin, ATiltedFaceSweepsToWhereItCrossesTheSurface)
{
  const double tilt = 20 * M_PI / 180;
  dem::Wall    w    = tilted_plate(tilt, 1.0);
  w.motion.kind     = dem::WallMotion::Kind::prescribed;
  w.motion.phases["sink"].velocity   = dem::Vec3(0, 0, -0.1);
  w.motion.phases["travel"].velocity = dem::Vec3(1.0, 0, 0);
  w.initialise();
  const std::vector<coupling::Phase> phases = {{"sink", 1.0}, {"travel", 0.3}};

  const auto box = coupling::swept_box(w, phases, 0.5, 50);
  ASSERT_TRUE(box);
  const auto &[lo, hi] = *box;
  EXPECT_NEAR(hi.y(), 0.6 * std::tan(tilt), 1e-9);
  EXPECT_NEAR(lo.y(), 0.0, 1e-9);
  EXPECT_NEAR(lo.x(), -0.1, 1e-9);
  EXPECT_NEAR(hi.x(), 0.4, 1e-9);
  EXPECT_NEAR(lo.z(), -0.1, 1e-9);
  EXPECT_NEAR(hi.z(), 0.5, 1e-9);

  // without a height the whole plate counts: its top edge at y = sin(20 deg)
  const auto whole = coupling::swept_box(w, phases);
  ASSERT_TRUE(whole);
  EXPECT_NEAR(whole->second.y(), std::sin(tilt), 1e-9);
  EXPECT_NEAR(whole->second.z(), std::cos(tilt), 1e-9);
}

// A wall that stays above the surface has no path in the bed; one whose motion follows the
// loads (a free rigid body) has no path known beforehand.
TEST(FineRegionMargin, APathAboveTheBedOrFollowingTheLoadsIsNotMeasured)
{
  dem::Wall w   = tilted_plate(0.3, 1.0);
  w.motion.kind = dem::WallMotion::Kind::fixed;
  w.initialise();
  const auto above = coupling::swept_box(w, {{"rest", 1.0}}, -0.01);
  ASSERT_TRUE(above);
  EXPECT_TRUE(std::isinf(above->first.z()) && above->first.z() > 0);

  w.motion.kind = dem::WallMotion::Kind::rigid_body;
  EXPECT_FALSE(coupling::swept_box(w, {{"rest", 1.0}}, 0.5));
}

// A flat layer of spheres (radius 0.01 m, centres at z = 0.2 m) over a 1 m x 1 m fill box, a fifth
// of it 0.05 m lower (x < 0.2 m), with one pellet above it (its centre 0.3 m above the layer's):
// the surface is the layer's top, 0.21 m; the highest top would say 0.51 m, the lowest 0.16 m,
// the mean 0.2005 m.
TEST(FineRegionMargin, TheBedsSurfaceIsTheMedianColumnTopNotTheHighestPellet)
{
  dem::Simulation sim(dem::testing::quiet_settings(1e-5));
  dem::Material   grain{"pellet", 1e7, 0.25, 3000};
  const int       m = sim.add_material(grain);
  sim.set_interaction(m, m, {});
  auto        &P = sim.particles();
  const double r = 0.01;
  long         id = 0;
  for (int i = 0; i < 50; ++i)
    for (int j = 0; j < 50; ++j)
      P.add(id++, (i + 0.5) * 2 * r, (j + 0.5) * 2 * r, i < 10 ? 0.15 : 0.2, r, grain.density, m);
  P.add(id++, 0.5, 0.5, 0.5, r, grain.density, m);
  sim.setup();

  dem::FillRegion fill;
  fill.box_min = dem::Vec3(0, 0, 0), fill.box_max = dem::Vec3(1, 1, 1);
  EXPECT_NEAR(coupling::bed_surface(sim, fill), 0.21, 1e-12);

  // an empty bed has no surface
  dem::Simulation empty(dem::testing::quiet_settings(1e-5));
  EXPECT_EQ(coupling::bed_surface(empty, fill), -std::numeric_limits<double>::max());
}
