// The rope grab's mechanism driving DEM walls (dem/rope_grab_driver.h): the walls ride on the
// mechanism's parts exactly, and the particles' loads reach it as a hand computes them (a
// resting weight: its force and its moment about the hinge), with the ropes carrying the lot.
#include <abrade/common/error.h>
#include <abrade/dem/rope_grab_driver.h>

#include "dem_test_helpers.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material steel = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, false);
  const Material heavy = Material::from_shear_modulus("heavy", 1e8, 0.25, 7800, false);
  const Vec3     hinge(0, 0, 1.75);

  // The coarse CI grab's mechanism (cases/grab/grab_coarse_rope.prm).
  RopeGrabRig coarse_rig(const std::vector<std::string> &phases)
  {
    RopeGrabRig r;
    auto       &d            = r.design;
    d.upper_pin_offset       = 0.45;
    d.tie_rod_length         = 0.7;
    d.shell_pin              = {0.42, 0.3};
    d.closed_angle           = 56.4 * M_PI / 180;
    d.falls                  = 4;
    d.lower_head_mass        = 150;
    d.upper_head_mass        = 50;
    d.shell_mass             = 150;
    d.shell_centre           = {0.33, 0.05};
    d.shell_inertia          = 5;
    d.closing_rope_stiffness = 1e6;
    d.holding_rope_stiffness = 1e6;
    d.closing_rope_damping = d.holding_rope_damping = 2 * 0.5 * std::sqrt(1e6 * 500.0);
    d.winch_acceleration                            = 4;
    r.hinge                                         = hinge;
    r.phases                                        = phases;
    r.walls = {{"right", RopeGrab::Part::right_shell}, {"left", RopeGrab::Part::left_shell},
               {"head", RopeGrab::Part::lower_head}};
    return r;
  }

  Wall plate_wall(const std::string &name, int material, const Vec3 &centre, double size)
  {
    Wall w;
    w.name     = name;
    w.material = material;
    w.mesh     = primitives::plate(centre, 2, size, size, size / 4);
    return w;
  }
} // namespace

// Plates on the shells and the lower head, no particles: closing on the winch, each plate's
// vertices are where the mechanism's state puts them (the hinge moved by z - z0, a shell turned
// by +-angle about it).
TEST(RopeGrabDriver, WallsRideOnTheMechanismsParts)
{
  Simulation sim(quiet_settings(1e-4, true));
  const int  m = sim.add_material(steel);
  sim.add_wall(plate_wall("right", m, hinge + Vec3(0.3, 0, -0.3), 0.2));
  sim.add_wall(plate_wall("left", m, hinge + Vec3(-0.3, 0, -0.3), 0.2));
  sim.add_wall(plate_wall("head", m, hinge + Vec3(0, 0, 0.1), 0.2));
  const std::vector<TriangleMesh> reference = {sim.wall(0).mesh, sim.wall(1).mesh, sim.wall(2).mesh};
  RopeGrabRig rig = coarse_rig({"closing"});
  rig.closing["closing"] = {1.0, 1e5}; // hauls in
  rig.holding["closing"] = {0, 0};     // slack
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  sim.run_phase("closing", 0.6);

  // the walls move with the velocities the mechanism set in the step before: they are one
  // drift behind its state
  const auto &q     = driver->state();
  const double z    = q.z - sim.dt() * q.z_rate, angle = q.angle - sim.dt() * q.angle_rate;
  EXPECT_GT(angle, 0.3) << "the shells closed";
  const Vec3 moved = hinge + Vec3(0, 0, z - hinge.z());
  for (int w = 0; w < 3; ++w)
    {
      const Eigen::Matrix3d turn = Eigen::AngleAxisd(w == 0 ? angle : w == 1 ? -angle : 0.0, Vec3::UnitY()).toRotationMatrix();
      for (std::size_t v = 0; v < reference[w].vertices.size(); ++v)
        {
          const Vec3 expected = moved + turn * (reference[w].vertices[v] - hinge);
          const Vec3 now(&sim.wall(w).current[3 * v]);
          EXPECT_NEAR((now - expected).norm(), 0, 1e-9) << sim.wall(w).name << " vertex " << v;
        }
    }
  // a wall's velocity is its part's
  EXPECT_DOUBLE_EQ(sim.wall(0).angular_velocity.y(), q.angle_rate);
  EXPECT_DOUBLE_EQ(sim.wall(1).angular_velocity.y(), -q.angle_rate);
  EXPECT_DOUBLE_EQ(sim.wall(2).velocity.z(), q.z_rate);
}

// A heavy ball resting on a plate of the right shell, x from the hinge, while the grab hangs
// open on its holding ropes: the mechanism gets the ball's weight w as the vertical load and
// x w as the closing moment about the hinge, and the ropes carry the grab and the ball.
TEST(RopeGrabDriver, ARestingWeightReachesTheMechanismAsAHandComputesIt)
{
  Settings s = quiet_settings(2e-5, true);
  Simulation sim(s);
  const int  mw = sim.add_material(steel), mp = sim.add_material(heavy);
  sim.set_interaction(mp, mw, {0.1, 0.5, 0.0});
  const double x = 0.8, plate = hinge.z() - 0.3, r = 0.05;
  sim.add_wall(plate_wall("right", mw, Vec3(x, 0, plate), 0.3));
  sim.add_wall(plate_wall("left", mw, Vec3(-x, 0, plate), 0.3));
  sim.particles().add(0, x, 0, plate + r, r, heavy.density, mp);
  const double w = 9.81 * heavy.density * 4.0 / 3.0 * M_PI * r * r * r;

  RopeGrabRig rig = coarse_rig({"hold"});
  rig.walls.pop_back(); // no head plate
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  double          tension = 0;
  long            n = 0;
  sim.run_phase("hold", 0.6, [&](const Simulation &sim) {
    if (sim.time() < 0.4)
      return;
    mean += driver->particle_loads();
    // (the closing rope, on its brake, takes a share of the ball once the grab sinks by its stretch)
    tension += driver->mechanism().holding_tension(driver->state(), Winch{}) +
               driver->mechanism().closing_tension(driver->state(), Winch{});
    ++n;
  });
  mean /= n;
  tension /= n;
  EXPECT_NEAR(mean[0], -w, 2e-3 * w);
  EXPECT_NEAR(mean[1], x * w, 2e-3 * x * w);
  const double grab = 9.81 * driver->mechanism().mass_matrix(0)(0, 0);
  EXPECT_NEAR(tension, grab + w, 2e-3 * w) << "the ropes carry the grab and the ball";
  EXPECT_NEAR(driver->state().angle, 0, 1e-12) << "hanging open on its stop";
}

TEST(RopeGrabDriver, RefusesAWallWithAMotionOfItsOwnAndGravityAcross)
{
  Simulation sim(quiet_settings(1e-4, true));
  const int  m = sim.add_material(steel);
  Wall       right = plate_wall("right", m, Vec3(0.3, 0, 1.4), 0.2);
  right.motion.kind = WallMotion::Kind::prescribed;
  sim.add_wall(right);
  sim.add_wall(plate_wall("left", m, Vec3(-0.3, 0, 1.4), 0.2));
  RopeGrabRig rig = coarse_rig({"closing"});
  rig.walls.pop_back();
  EXPECT_THROW(RopeGrabDriver(rig, sim), abrade::InputError);
  rig.walls.emplace_back("nowhere", RopeGrab::Part::upper_head);
  Settings across = quiet_settings(1e-4, true);
  across.gravity  = Vec3(1, 0, -9.81);
  Simulation tilted(across);
  EXPECT_THROW(RopeGrabDriver(rig, tilted), abrade::InputError);
}
