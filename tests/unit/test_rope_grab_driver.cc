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
               {"head", RopeGrab::Part::lower_head}, {"top", RopeGrab::Part::upper_head}};
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

  /// A steel plate on each part of coarse_rig's walls: the shells (right, left) and the heads
  /// (head, top).
  void add_part_plates(Simulation &sim)
  {
    const int m = sim.add_material(steel);
    sim.add_wall(plate_wall("right", m, hinge + Vec3(0.3, 0, -0.3), 0.2));
    sim.add_wall(plate_wall("left", m, hinge + Vec3(-0.3, 0, -0.3), 0.2));
    sim.add_wall(plate_wall("head", m, hinge + Vec3(0, 0, 0.1), 0.2));
    sim.add_wall(plate_wall("top", m, hinge + Vec3(0, 0, 1.2), 0.2));
  }
} // namespace

// Plates on the shells and the heads, no particles: closing on the winch, held still a while
// (a phase the mechanism does not move in), closing again. Each plate's vertices are where the
// mechanism's state puts them: the hinge moved by z - z0, a shell turned by +-angle about it,
// the upper head moved by z - z0 plus the head distance's change.
TEST(RopeGrabDriver, WallsRideOnTheMechanismsParts)
{
  Simulation sim(quiet_settings(1e-4, true));
  add_part_plates(sim);
  std::vector<TriangleMesh> reference;
  for (int w = 0; w < 4; ++w)
    reference.push_back(sim.wall(w).mesh);
  RopeGrabRig rig = coarse_rig({"closing"});
  rig.closing["closing"] = {1.0, 1e5}; // hauls in
  rig.holding["closing"] = {0, 0};     // slack
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  const RopeGrab &grab = driver->mechanism();

  const auto check_pose = [&](double z, double angle, const std::string &when) {
    const Vec3 moved = hinge + Vec3(0, 0, z - hinge.z());
    for (int w = 0; w < 4; ++w)
      {
        const double turned = w == 0 ? angle : w == 1 ? -angle : 0.0;
        const Vec3   lift   = w == 3 ? Vec3(0, 0, grab.head_distance(angle) - grab.head_distance(0)) : Vec3::Zero();
        const Eigen::Matrix3d turn = Eigen::AngleAxisd(turned, Vec3::UnitY()).toRotationMatrix();
        for (std::size_t v = 0; v < reference[w].vertices.size(); ++v)
          {
            const Vec3 expected = moved + lift + turn * (reference[w].vertices[v] - hinge);
            const Vec3 now(&sim.wall(w).current[3 * v]);
            EXPECT_NEAR((now - expected).norm(), 0, 1e-9) << when << ": " << sim.wall(w).name << " vertex " << v;
          }
      }
  };
  sim.run_phase("closing", 0.3);
  // the walls move with the velocities the mechanism set in the step before: they are one
  // drift behind its state
  const auto &q = driver->state();
  EXPECT_GT(q.angle, 0.2) << "the shells closed";
  check_pose(q.z - sim.dt() * q.z_rate, q.angle - sim.dt() * q.angle_rate, "closing");
  EXPECT_DOUBLE_EQ(sim.wall(0).angular_velocity.y(), q.angle_rate);
  EXPECT_DOUBLE_EQ(sim.wall(1).angular_velocity.y(), -q.angle_rate);
  EXPECT_DOUBLE_EQ(sim.wall(2).velocity.z(), q.z_rate);

  // held still: the mechanism takes the walls' pose and stays there
  sim.run_phase("hold", 0.05);
  check_pose(q.z, q.angle, "held");
  EXPECT_EQ(q.z_rate, 0);
  sim.run_phase("closing", 0.3);
  EXPECT_GT(q.angle, 0.5);
  check_pose(q.z - sim.dt() * q.z_rate, q.angle - sim.dt() * q.angle_rate, "closing again");
}

// The trolley carries the grab along x: every wall is where the mechanism's state puts it,
// moved by the trolley's travel too; the travel is the ramp's, worked by hand (to one step's
// drift); a held phase stops the trolley with the walls; the closing angle and the hinge's
// height evolve as without the trolley (the frame's acceleration does no work on them).
TEST(RopeGrabDriver, TheTrolleyCarriesTheWholeGrab)
{
  const auto run = [](bool travel, std::vector<Vec3> &vertices) {
    Simulation sim(quiet_settings(1e-4, true));
    add_part_plates(sim);
    RopeGrabRig rig = coarse_rig({"travel"});
    rig.closing["travel"] = {1.0, 1e5}; // closing while it travels
    rig.holding["travel"] = {0, 0};
    if (travel)
      rig.trolley["travel"] = 0.5;
    rig.trolley_acceleration = 2;
    auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
    sim.add_driver(driver);
    sim.setup();
    sim.run_phase("travel", 0.3);
    const double dt = sim.dt();
    // ramp 0.25 s at 2 m/s^2, then 0.05 s at 0.5 m/s: a t1^2 / 2 + v (t - t1)
    if (travel)
      {
        EXPECT_NEAR(driver->trolley_position(), 2 * 0.25 * 0.25 / 2 + 0.5 * 0.05, 0.5 * dt * 1.01);
        EXPECT_DOUBLE_EQ(driver->trolley_speed(), 0.5);
        EXPECT_NEAR(driver->phases().back().second.trolley_end, driver->trolley_position(), 1e-15);
      }
    const double x = driver->trolley_position() - dt * driver->trolley_speed(); // (the walls: one drift behind)
    for (int w = 0; w < 4; ++w)
      EXPECT_DOUBLE_EQ(sim.wall(w).velocity.x(), driver->trolley_speed());
    sim.run_phase("hold", 0.05);
    EXPECT_EQ(driver->trolley_speed(), 0);
    EXPECT_NEAR(driver->trolley_position(), x, 1e-15) << "held: the trolley is where its walls are";
    vertices.clear();
    for (int w = 0; w < 4; ++w)
      for (std::size_t v = 0; v < sim.wall(w).mesh.vertices.size(); ++v)
        vertices.emplace_back(Vec3(&sim.wall(w).current[3 * v]) - Vec3(x, 0, 0));
    return std::make_pair(driver->state(), x);
  };
  std::vector<Vec3> carried, still;
  const auto [with, x] = run(true, carried);
  const auto [without, zero] = run(false, still);
  EXPECT_GT(x, 0.08);
  EXPECT_EQ(zero, 0);
  EXPECT_GT(with.angle, 0.2) << "the shells closed while travelling";
  EXPECT_DOUBLE_EQ(with.angle, without.angle);
  EXPECT_DOUBLE_EQ(with.z, without.z);
  ASSERT_EQ(carried.size(), still.size());
  for (std::size_t v = 0; v < carried.size(); ++v)
    EXPECT_NEAR((carried[v] - still[v]).norm(), 0, 1e-9) << "vertex " << v << ": moved by the trolley's travel only";
}

// The trolley over several phases: back along -x after a hold, then braking in a phase that
// gives it no speed, each phase's travel worked by hand (to one step's drift) and starting where
// the one before ended; with Trolley acceleration 0 it takes each speed at once.
TEST(RopeGrabDriver, TheTrolleyRampsAndBrakesPhaseByPhase)
{
  const auto travel = [](double acceleration, const std::vector<std::pair<std::string, double>> &phases) {
    Simulation sim(quiet_settings(1e-4, true));
    add_part_plates(sim);
    RopeGrabRig rig = coarse_rig({"travel", "back", "brake"});
    rig.trolley["travel"]    = 0.5;
    rig.trolley["back"]      = -0.25;
    rig.trolley_acceleration = acceleration;
    auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
    sim.add_driver(driver);
    sim.setup();
    std::vector<std::pair<double, double>> ends; // (position, speed) after each phase
    for (const auto &[phase, duration] : phases)
      {
        sim.run_phase(phase, duration);
        ends.emplace_back(driver->trolley_position(), driver->trolley_speed());
        for (int w = 0; w < 4; ++w)
          EXPECT_DOUBLE_EQ(sim.wall(w).velocity.x(), driver->trolley_speed()) << phase;
      }
    const auto &records = driver->phases();
    for (std::size_t k = 1; k < records.size(); ++k)
      EXPECT_EQ(records[k].second.trolley_start, records[k - 1].second.trolley_end) << records[k].first;
    return std::make_pair(ends, sim.dt());
  };
  {
    const auto [ends, dt] = travel(2, {{"travel", 0.3}, {"hold", 0.05}, {"back", 0.2}, {"brake", 0.1}});
    const double x_travel = 2 * 0.25 * 0.25 / 2 + 0.5 * 0.05;        // ramp 0.25 s, then 0.05 s at 0.5
    const double x_back   = -(0.25 * 0.25 / (2 * 2) + 0.25 * 0.075); // ramp 0.125 s, then 0.075 s at -0.25
    const double x_brake  = -(0.25 * 0.1 - 2 * 0.1 * 0.1 / 2);       // braking at 2 m/s^2 for 0.1 s
    EXPECT_NEAR(ends[0].first, x_travel, 0.5 * dt * 1.01);
    EXPECT_EQ(ends[1].second, 0) << "held";
    EXPECT_NEAR(ends[2].first - ends[1].first, x_back, 0.5 * dt * 1.01);
    EXPECT_DOUBLE_EQ(ends[2].second, -0.25);
    EXPECT_NEAR(ends[3].second, -0.25 + 2 * 0.1, 2 * dt * 1.01);
    EXPECT_NEAR(ends[3].first - ends[2].first, x_brake, 0.5 * dt * 1.01);
  }
  {
    const auto [ends, dt] = travel(0, {{"travel", 0.2}, {"brake", 0.1}});
    EXPECT_NEAR(ends[0].first, 0.5 * 0.2, 0.5 * dt * 1.01) << "at once";
    EXPECT_EQ(ends[1].second, 0);
    EXPECT_NEAR(ends[1].first, ends[0].first, 1e-15) << "stopped at once";
  }
}

// The hinge's height recorded when the lips close is the mechanism's at the first step that
// ends at the closing stop; a phase that begins closed records none.
TEST(RopeGrabDriver, RecordsTheHingeWhereTheLipsClose)
{
  Simulation sim(quiet_settings(1e-4, true));
  add_part_plates(sim);
  RopeGrabRig rig = coarse_rig({"closing", "closed"});
  rig.closing["closing"] = {2.0, 1e5};
  rig.holding["closing"] = {0, 0};
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  double first = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k < 400 && std::isnan(first); ++k)
    sim.run_phase("closing", 0.01, [&](const Simulation &) {
      if (std::isnan(first) && driver->state().angle >= rig.design.closed_angle)
        first = driver->state().z;
    });
  ASSERT_FALSE(std::isnan(first)) << "the shells did not close";
  EXPECT_EQ(driver->phases().back().second.hinge_when_closed, first);
  sim.run_phase("closed", 0.01);
  EXPECT_TRUE(std::isnan(driver->phases().back().second.hinge_when_closed)) << "began closed";
}

// A ball resting on the upper head's plate: its weight w reaches the mechanism as (-w, -w d')
// (the upper head rises by d' for a unit turn of the shells).
TEST(RopeGrabDriver, AWeightOnTheUpperHeadLoadsItThroughTheLinkage)
{
  Simulation sim(quiet_settings(2e-5, true));
  const int  mw = sim.add_material(steel), mp = sim.add_material(heavy);
  sim.set_interaction(mp, mw, {0.1, 0.5, 0.0});
  const double r = 0.05, top = hinge.z() + 1.0;
  sim.add_wall(plate_wall("right", mw, Vec3(0.5, 0, hinge.z() - 0.3), 0.2));
  sim.add_wall(plate_wall("left", mw, Vec3(-0.5, 0, hinge.z() - 0.3), 0.2));
  sim.add_wall(plate_wall("top", mw, Vec3(0, 0, top), 0.3));
  sim.particles().add(0, 0.05, 0, top + r, r, heavy.density, mp);
  const double w = 9.81 * heavy.density * 4.0 / 3.0 * M_PI * r * r * r;
  RopeGrabRig  rig = coarse_rig({"hold"});
  rig.walls        = {{"right", RopeGrab::Part::right_shell}, {"left", RopeGrab::Part::left_shell},
               {"top", RopeGrab::Part::upper_head}};
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  long            n    = 0;
  sim.run_phase("hold", 0.5, [&](const Simulation &sim) {
    if (sim.time() > 0.3)
      mean += driver->particle_loads(), ++n;
  });
  mean /= n;
  // d' by differences of the linkage's head distance
  const double h = 1e-6, slope = (driver->mechanism().head_distance(h) - driver->mechanism().head_distance(-h)) / (2 * h);
  EXPECT_EQ(driver->state().angle, 0) << "hanging open on its stop";
  EXPECT_NEAR(mean[0], -w, 2e-3 * w);
  EXPECT_NEAR(mean[1], -w * slope, 2e-3 * w * std::abs(slope));
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
  rig.walls = {{"right", RopeGrab::Part::right_shell}, {"left", RopeGrab::Part::left_shell}};
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

// The coarse grab's shells (0.4 m radius, open 60 degrees) lowered on the holding ropes onto a
// floor of heavy balls in a box, then left standing with both ropes slack: it stands on its
// lips, its hinge 0.4 cos 60 deg = 0.2 m above the balls' surface under the lips (less the
// contacts' overlaps, under a millimetre), open on its stop, at rest, the floor carrying its
// whole weight.
TEST(RopeGrabDriver, AFreeGrabStandsOnItsLipsOnARigidFloor)
{
  Settings settings = quiet_settings(0, true);
  settings.threads  = 2;
  Simulation   sim(settings);
  const int    mw = sim.add_material(steel), mb = sim.add_material(heavy);
  sim.set_interaction(mb, mw, {0.2, 0.5, 0.0});
  sim.set_interaction(mb, mb, {0.2, 0.5, 0.0});
  const double r = 0.02, top = 2 * r;
  const Vec3   lo(-0.6, -0.36, 0), hi(0.6, 0.36, 0.5);
  Wall         box;
  box.name     = "floor";
  box.material = mw;
  box.mesh     = primitives::box_container(lo, hi);
  sim.add_wall(box);
  long id = 0;
  for (double x = lo.x() + r; x < hi.x() - r + 1e-9; x += 2 * r)
    for (double y = lo.y() + r; y < hi.y() - r + 1e-9; y += 2 * r)
      sim.particles().add(id++, x, y, r, r, heavy.density, mb);
  const Vec3 start(0, 0, top + 0.2 + 0.03); // lips 30 mm above the balls
  for (const int side : {1, -1})
    {
      Wall shell;
      shell.name     = side > 0 ? "right" : "left";
      shell.material = mw;
      shell.mesh     = primitives::clamshell_shell(0.4, 0.6, M_PI / 2, M_PI / 3, side, 0.04);
      shell.mesh.translate(start);
      sim.add_wall(shell);
    }
  RopeGrabRig rig = coarse_rig({"lowering", "standing"});
  rig.hinge       = start;
  rig.walls       = {{"right", RopeGrab::Part::right_shell}, {"left", RopeGrab::Part::left_shell}};
  rig.holding["lowering"] = {-0.2, std::numeric_limits<double>::infinity()};
  rig.closing["lowering"] = rig.closing["standing"] = rig.holding["standing"] = {0, 0}; // slack
  auto driver = std::make_shared<RopeGrabDriver>(rig, sim);
  sim.add_driver(driver);
  sim.setup();
  sim.settle(1e-7, 0.3);
  sim.run_phase("lowering", 0.25);
  sim.run_phase("standing", 0.5);
  double floor_load = 0;
  long   n          = 0;
  sim.run_phase("standing", 0.1, [&](const Simulation &s) {
    floor_load += -s.wall(0).force.z(), ++n;
  });
  const auto  &q      = driver->state();
  const double weight = 9.81 * driver->mechanism().mass_matrix(0)(0, 0);
  // the lips (x = +-0.4 sin 60 deg) rest on the column of balls nearest below them, on their
  // surface there; two Hertz contacts in series (lip on ball, ball on floor, about 160 N each)
  // overlap by about 0.2 mm each: 0.43 mm measured, against the centimetres a wrong lip height
  // or a grab that splays would give
  const double lip = 0.4 * std::sin(M_PI / 3);
  const double column = lo.x() + r + 2 * r * std::round((lip - lo.x() - r) / (2 * r));
  const double surface = r + std::sqrt(r * r - (lip - column) * (lip - column));
  EXPECT_LT(q.z, surface + 0.2) << "stands on its lips (0.2 m below the hinge) on the balls";
  EXPECT_GT(q.z, surface + 0.2 - 1e-3) << "sank into the floor";
  EXPECT_EQ(q.angle, 0) << "open on its stop";
  EXPECT_NEAR(q.z_rate, 0, 1e-3);
  EXPECT_EQ(driver->mechanism().holding_tension(q, Winch{0, 0}), 0);
  EXPECT_NEAR(floor_load / n, weight + sim.particles().size() * 9.81 * heavy.density * 4.0 / 3.0 * M_PI * r * r * r,
              2e-3 * weight)
    << "the floor carries the grab and the balls";
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
  rig.walls = {{"right", RopeGrab::Part::right_shell}, {"left", RopeGrab::Part::left_shell}};
  EXPECT_THROW(RopeGrabDriver(rig, sim), abrade::InputError);
  rig.walls.emplace_back("nowhere", RopeGrab::Part::upper_head);
  Settings across = quiet_settings(1e-4, true);
  across.gravity  = Vec3(1, 0, -9.81);
  Simulation tilted(across);
  EXPECT_THROW(RopeGrabDriver(rig, tilted), abrade::InputError);
}
