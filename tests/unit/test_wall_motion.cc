// Wall motion: prescribed translation per phase, rotation about a hinge, and a rigid body with a
// free degree of freedom that comes to rest on a particle (its weight balances the contact).
#include <abrade/common/error.h>

#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material pellet = Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, false);
  const Material steel  = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, false);
} // namespace

TEST(WallMotion, PrescribedTranslationAndHingeRotation)
{
  Simulation sim(quiet_settings(1e-4));
  const int  m = sim.add_material(steel);
  sim.add_material(pellet);
  Wall knife;
  knife.name = "knife", knife.material = m;
  knife.mesh = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  knife.motion.kind   = WallMotion::Kind::prescribed;
  knife.motion.centre = Vec3(0, 0, 1); // hinge 1 m above the edge
  knife.motion.phases["penetration"].velocity         = Vec3(0, 0, -1.5);
  knife.motion.phases["travel"].velocity              = Vec3(1.5, 0, 0);
  knife.motion.phases["closing"].angular_velocity     = Vec3(0, 0.5, 0);
  sim.add_wall(knife);
  sim.setup();
  const Vec3 edge0 = knife.mesh.vertices[0];
  sim.run_phase("penetration", 0.2);
  sim.run_phase("travel", 0.4);
  const Wall &w = sim.wall(0);
  EXPECT_NEAR(w.translation[2], -1.5 * 0.2, 1e-12);
  EXPECT_NEAR(w.translation[0], 1.5 * 0.4, 1e-12);
  EXPECT_NEAR(w.current[2] - edge0[2], -0.3, 1e-12);
  sim.run_phase("rest", 0.1); // not in the table: at rest
  EXPECT_NEAR(w.translation[0], 0.6, 1e-12);

  // rotate 0.5 rad/s about +y through the (moved) hinge for 1 s
  const Vec3 hinge = w.current_centre();
  const Vec3 p0(w.current[0], w.current[1], w.current[2]);
  sim.run_phase("closing", 1.0);
  const Vec3 p1(w.current[0], w.current[1], w.current[2]);
  const Vec3 expected = hinge + Eigen::AngleAxisd(0.5, Vec3::UnitY()) * (p0 - hinge);
  EXPECT_NEAR((p1 - expected).norm(), 0, 1e-10);
  // velocity of a material point: omega x r
  EXPECT_NEAR((w.velocity_at(p1) - Vec3(0, 0.5, 0).cross(p1 - hinge)).norm(), 0, 1e-12);
}

TEST(WallMotion, RigidBodyRestsOnAParticleUnderItsWeight)
{
  Settings s = quiet_settings(5e-5, true);
  Simulation sim(s);
  const int  mp = sim.add_material(pellet), mw = sim.add_material(steel);
  sim.set_interaction(mp, mw, {0.1, 0.5, 0.0});
  sim.add_wall(floor_wall(mw, 0.5));
  const double R = 0.0275, M = 20;
  Wall lid;
  lid.name = "lid", lid.material = mw;
  lid.mesh = primitives::plate(Vec3(0, 0, 2 * R + 0.001), 2, 0.2, 0.2, 0);
  lid.motion.kind    = WallMotion::Kind::rigid_body;
  lid.motion.mass    = M;
  lid.motion.centre  = Vec3(0, 0, 2 * R + 0.001);
  lid.motion.free[2] = true; // only vertical translation
  sim.add_wall(lid);
  sim.particles().add(0, 0.01, 0.013, R, R, pellet.density, mp);
  sim.setup();
  sim.run_phase("settle", 3.0);
  const double m = sim.particles().mass[0];
  EXPECT_NEAR(sim.wall(1).force[2] / (M * 9.81), 1, 1e-3);             // the particle carries the lid
  EXPECT_NEAR(sim.wall(0).force[2] / (-(M + m) * 9.81), 1, 1e-3);       // the floor carries both
  EXPECT_NEAR(sim.wall(1).velocity[2], 0, 1e-4);
  EXPECT_NEAR(sim.wall(1).translation[0], 0, 0);                       // x is not free
  // overlap under the lid follows Hertz for its weight
  const double e_s  = e_star(pellet, steel);
  const double gap  = sim.wall(1).current_centre()[2] - sim.particles().z[0];
  const double load = 4.0 / 3.0 * e_s * std::sqrt(R) * std::pow(R - gap, 1.5);
  EXPECT_NEAR(load / (M * 9.81), 1, 2e-3);
}

// Two walls of one body (a grab's two shells): a lid made of two halves, each on a particle of
// its own, one half heavier than the other. As one body their weights add and they come to rest
// together; the two particles carry the whole body between them, the halves' own weights do
// not matter. A wall free only in some phases follows its table in the others.
TEST(WallMotion, WallsOfOneBodyMoveTogetherAndFreePhases)
{
  Settings   s = quiet_settings(5e-5, true);
  Simulation sim(s);
  const int  mp = sim.add_material(pellet), mw = sim.add_material(steel);
  sim.set_interaction(mp, mw, {0.1, 0.5, 0.0});
  sim.add_wall(floor_wall(mw, 0.5));
  const double R = 0.0275, z = 2 * R + 0.001;
  for (const auto &[name, x, mass] : {std::tuple{"left", -0.1, 30.0}, std::tuple{"right", 0.1, 10.0}})
    {
      Wall half;
      half.name = name, half.material = mw;
      half.mesh = primitives::plate(Vec3(x, 0, z), 2, 0.18, 0.18, 0);
      half.motion.kind    = WallMotion::Kind::rigid_body;
      half.motion.body    = "lid";
      half.motion.mass    = mass;
      half.motion.centre  = Vec3(0, 0, z);
      half.motion.free[2] = true;
      half.motion.free_phases = {"settle"};
      half.motion.phases["lift"].velocity = Vec3(0, 0, 0.1);
      sim.add_wall(half);
    }
  sim.particles().add(0, -0.1, 0, R, R, pellet.density, mp);
  sim.particles().add(1, 0.1, 0, R, R, pellet.density, mp);
  sim.setup();
  sim.run_phase("settle", 3.0);
  const double total = (sim.wall(1).force[2] + sim.wall(2).force[2]) / (40 * 9.81);
  EXPECT_NEAR(total, 1, 1e-3);                                                    // the body's weight
  EXPECT_NEAR(sim.wall(1).translation[2], sim.wall(2).translation[2], 1e-12);     // one body
  EXPECT_NEAR(sim.wall(1).force[2], sim.wall(2).force[2], 2e-3 * 40 * 9.81);       // shared equally
  // in "lift" the table holds: 0.1 m/s up for 0.5 s, whatever the loads
  const double z0 = sim.wall(1).translation[2];
  sim.run_phase("lift", 0.5);
  EXPECT_NEAR(sim.wall(1).translation[2] - z0, 0.05, 1e-9);
  EXPECT_NEAR(sim.wall(2).translation[2] - z0, 0.05, 1e-9);

  // walls of one body must agree on how they move
  Wall odd;
  odd.name = "odd", odd.material = mw;
  odd.mesh = primitives::plate(Vec3(0, 0, 1), 2, 0.1, 0.1, 0);
  odd.motion.kind   = WallMotion::Kind::rigid_body;
  odd.motion.body   = "lid";
  odd.motion.mass   = 1;
  odd.motion.centre = Vec3(0, 0, 1);
  EXPECT_THROW(sim.add_wall(odd), abrade::InputError);
}

// The clamshell shell: closed, two mirrored shells hold sector x R^2 x width (their side plates
// are circular sectors), and opening turns the lip about the hinge.
TEST(Primitives, ClamshellShell)
{
  const double R = 0.4, W = 0.6, sector = M_PI / 2;
  const auto   shell = primitives::clamshell_shell(R, W, sector, 0, 1, 0.02);
  double       side_area = 0;
  for (std::size_t t = 0; t < shell.n_triangles(); ++t)
    if (std::abs(std::abs(shell.normal(t)[1]) - 1) < 1e-9)
      side_area += shell.area(t);
  // two sector plates, inscribed polygons: the arc is approximated by chords of <= 2 cm
  EXPECT_NEAR(side_area / (2 * 0.5 * sector * R * R), 1, 2e-3);
  Vec3 lo, hi;
  shell.bounding_box(lo, hi);
  EXPECT_NEAR(lo[2], -R, 1e-12);   // the lip straight down
  EXPECT_NEAR(hi[0], R, 1e-12);    // the back at the hinge's height, +x side
  EXPECT_NEAR(lo[0], 0, 1e-12);
  const auto open = primitives::clamshell_shell(R, W, sector, M_PI / 3, -1, 0.02);
  open.bounding_box(lo, hi);
  EXPECT_NEAR(hi[0], 0, 1e-12);                          // the -x side
  EXPECT_NEAR(lo[2], -R * std::cos(M_PI / 3), 1e-12);    // the lip 60 degrees up
}
