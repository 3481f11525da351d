// A new wall motion is one file and one registration line (wall_motion_model.h): this test is
// that file. Its toy motion oscillates the wall along x, x(t) = A sin(2 pi t / P) from the start
// of every phase, with its own parameters (Wall NAME/Motion/Oscillating/Amplitude and Period).
// Registered here, outside the library, it must be a choice of Motion/Type, have its parameters
// declared and read, and move a wall as it says, without a change anywhere else.
//
// The truth: the wall's displacement after t is A sin(w t), w = 2 pi / P; the engine takes the
// velocity at each step's middle, whose sum of v(t) = A w cos(w t) is the integral plus
// (dt^2 / 24) (v'(0) - v'(t)) = (w dt)^2 / 24 A sin(w t) (the midpoint rule's error, to dt^4): so
// A sin(w t) (1 + (w dt)^2 / 24), 5.1e-10 m above A at a quarter period (velocities taken at the
// steps' starts would be A w dt / 2 = 7.9e-6 m off; the sums' round-off over a period stays below 1e-13 m).
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/dem/wall_motion_model.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
  using namespace abrade::dem;

  class Oscillating : public WallMotionModel
  {
  public:
    std::string      name() const override { return "oscillating"; }
    std::string      documentation() const override { return "x = Amplitude sin(2 pi t / Period) in every phase"; }
    WallMotion::Kind kind() const override { return WallMotion::Kind::prescribed; }
    std::string      section() const override { return "Oscillating"; }
    void             declare_parameters(ParameterSection &p) const override
    {
      p.declare_number("Amplitude", 0.01, 0, 1, "[m] The largest displacement along x. Range: [0, 1].");
      p.declare_number("Period", 0.1, 1e-6, 1e3, "[s] The time of one oscillation. Range: [1e-6, 1e3].");
    }
    void parse_parameters(const ParameterSection &p, const MotionContext &, WallMotion &) override
    {
      amplitude = p.number("Amplitude");
      period    = p.number("Period");
    }
    PhaseVelocity velocity(const WallMotion &, const std::string &, double t) const override
    {
      const double omega = 2 * M_PI / period;
      PhaseVelocity v;
      v.velocity = Vec3(amplitude * omega * std::cos(omega * t), 0, 0);
      return v;
    }
    bool time_dependent() const override { return true; }

  private:
    double amplitude = 0, period = 1;
  };
} // namespace

ABRADE_REGISTER_WALL_MOTION(Oscillating);

// a choice of Motion/Type beside the library's own, in the order of the names
TEST(ToyWallMotion, IsRegisteredWithTheBuiltInOnes)
{
  EXPECT_EQ(wall_motion_names(), (std::vector<std::string>{"fixed", "oscillating", "prescribed", "rigid body"}));
}

// a wall of the default case given it: its parameters read from its own subsection, and it
// moves the wall by its formula
TEST(ToyWallMotion, MovesAWallOfACaseAsItSays)
{
  abrade::coupling::ParameterFile params("", {"Wall knife/Motion/Type=oscillating",
                                              "Wall knife/Motion/Oscillating/Amplitude=0.02",
                                              "Wall knife/Motion/Oscillating/Period=0.08"});
  const abrade::coupling::DemCase c = abrade::coupling::read_dem_case(params);
  const Wall *knife = nullptr;
  for (const auto &w : c.walls)
    if (w.wall.name == "knife")
      knife = &w.wall;
  ASSERT_NE(knife, nullptr);
  ASSERT_TRUE(knife->motion.model);
  EXPECT_EQ(knife->motion.model->name(), "oscillating");
  EXPECT_EQ(knife->motion.kind, WallMotion::Kind::prescribed);

  // A sin(w t) (1 + (w dt)^2 / 24), the midpoint sum of the velocity (above)
  const double dt           = 1e-5, omega = 2 * M_PI / 0.08;
  auto         midpoint_sum = [&](double t) {
    return 0.02 * std::sin(omega * t) * (1 + omega * omega * dt * dt / 24);
  };
  Wall w = *knife;
  w.initialise();
  w.set_phase("travel");
  for (int step = 1; step <= 8000; ++step) // one period
    {
      w.advance(dt);
      if (step == 2000 || step == 4000 || step == 8000)
        {
          EXPECT_NEAR(w.translation[0], midpoint_sum(step * dt), 1e-13) << "step " << step;
        }
    }
  // after the move the wall has the velocity of the step's end (the contacts' velocity)
  EXPECT_NEAR(w.velocity[0], 0.02 * omega * std::cos(omega * 8000 * dt), 1e-14);
  EXPECT_NEAR(w.translation[1], 0, 1e-15);
  EXPECT_NEAR(w.translation[2], 0, 1e-15);
  // every phase starts the oscillation afresh
  w.set_phase("penetration");
  w.advance(dt);
  EXPECT_NEAR(w.translation[0], midpoint_sum(8000 * dt) + midpoint_sum(dt), 1e-13);
}

// a bad value of its parameter is an input error naming its entry
TEST(ToyWallMotion, ItsParametersAreChecked)
{
  EXPECT_ANY_THROW(abrade::coupling::ParameterFile("", {"Wall knife/Motion/Type=oscillating",
                                                        "Wall knife/Motion/Oscillating/Period=0"}));
}

// The built-in rigid body reads its own entries through the same section (rigid_body.cc), and
// another motion's entries set on a wall are refused, not ignored.
namespace
{
  /// The message of the InputError read_dem_case throws for @p sets on the default case.
  std::string refusal(const std::vector<std::string> &sets)
  {
    try
      {
        abrade::coupling::ParameterFile params("", sets);
        abrade::coupling::read_dem_case(params);
      }
    catch (const std::exception &e)
      {
        return e.what();
      }
    return "";
  }
} // namespace

TEST(RigidBodyMotion, ReadsItsEntries)
{
  abrade::coupling::ParameterFile params("", {"Wall container/Motion/Type=rigid body",
                                              "Wall container/Motion/Mass=5", "Wall container/Motion/Inertia=1, 2, 3",
                                              "Wall container/Motion/Free degrees of freedom=tz, rx",
                                              "Wall container/Motion/Gravity=false", "Wall container/Motion/Body=b",
                                              "Wall container/Motion/Free in phases=travel"});
  const abrade::coupling::DemCase c = abrade::coupling::read_dem_case(params);
  const WallMotion               &m = c.walls.front().wall.motion;
  EXPECT_EQ(c.walls.front().wall.name, "container");
  EXPECT_EQ(m.kind, WallMotion::Kind::rigid_body);
  EXPECT_EQ(m.model->name(), "rigid body");
  EXPECT_EQ(m.mass, 5);
  EXPECT_EQ(m.inertia, Vec3(1, 2, 3));
  EXPECT_EQ(m.free, (std::array<bool, 6>{false, false, true, true, false, false}));
  EXPECT_FALSE(m.gravity);
  EXPECT_EQ(m.body, "b");
  EXPECT_EQ(m.free_phases, (std::set<std::string>{"travel"}));
}

TEST(RigidBodyMotion, RefusesWhatItCannotBe)
{
  EXPECT_NE(refusal({"Wall container/Motion/Type=rigid body"}).find("needs a positive mass"), std::string::npos);
  EXPECT_NE(refusal({"Wall container/Motion/Type=rigid body", "Wall container/Motion/Mass=5",
                     "Wall container/Motion/Free in phases=bogus"})
              .find("'bogus' is not a phase"),
            std::string::npos);
  // a Body on a prescribed wall would leave it out of the body without a word: a wall has its
  // own motion's entries only; another's at its defaults is a no-op, left out
  const std::string body = refusal({"Wall knife/Motion/Body=grab"});
  EXPECT_NE(body.find("'Body' is an entry of Motion/Type = rigid body, and wall knife's Motion/Type is prescribed"),
            std::string::npos)
    << body;
  EXPECT_EQ(refusal({"Wall knife/Motion/Inertia=0,0,0.0", "Wall knife/Motion/Gravity=true"}), ""); // (the defaults)
}

// The velocity table (Motion/Velocities, Angular velocities) is the prescribed and rigid-body
// motions' own: a fixed wall has none, and a velocity given it is refused (it was ignored
// without a word when every wall had the table); at its default (empty) it is a no-op.
TEST(VelocityTable, IsTheEntryOfTheMotionsThatFollowIt)
{
  const std::string fixed = refusal({"Wall container/Motion/Velocities=travel: 1, 0, 0"});
  EXPECT_NE(fixed.find("'Velocities' is an entry of Motion/Type = prescribed, and wall container's Motion/Type is "
                       "fixed"),
            std::string::npos)
    << fixed;
  EXPECT_NE(refusal({"Wall container/Motion/Angular velocities=travel: 0, 0, 1"}).find("'Angular velocities' is an "
                                                                                         "entry of Motion/Type"),
            std::string::npos);
  EXPECT_EQ(refusal({"Wall container/Motion/Velocities=", "Wall container/Motion/Angular velocities="}), "");

  // read by the motions that take it: per phase, the phases not listed at rest
  abrade::coupling::ParameterFile params(
    "", {"Wall knife/Motion/Velocities=travel: 1, 2, 3", "Wall knife/Motion/Angular velocities=penetration: 0, 0, 4",
         "Wall container/Motion/Type=rigid body", "Wall container/Motion/Mass=5",
         "Wall container/Motion/Velocities=settle: 0, 0, -1"});
  const abrade::coupling::DemCase c = abrade::coupling::read_dem_case(params);
  const WallMotion               &container = c.walls[0].wall.motion, &knife = c.walls[1].wall.motion;
  EXPECT_EQ(knife.phases.at("travel").velocity, Vec3(1, 2, 3));
  EXPECT_EQ(knife.phases.at("travel").angular_velocity, Vec3::Zero());
  EXPECT_EQ(knife.phases.at("penetration").velocity, Vec3::Zero());
  EXPECT_EQ(knife.phases.at("penetration").angular_velocity, Vec3(0, 0, 4));
  EXPECT_EQ(container.phases.at("settle").velocity, Vec3(0, 0, -1));
  EXPECT_EQ(container.phases.count("travel"), 0u);

  EXPECT_NE(refusal({"Wall knife/Motion/Velocities=bogus: 1, 0, 0"}).find("unknown phase 'bogus'"), std::string::npos);
  EXPECT_NE(refusal({"Wall knife/Motion/Velocities=travel: 1, 0"}).find("phase 'travel': expected three finite numbers"),
            std::string::npos);
  EXPECT_NE(refusal({"Wall knife/Motion/Velocities=travel 1, 0, 0"}).find("expected 'phase: x, y, z'"),
            std::string::npos);
}

// The default case's knife moves without a Velocities line (its wall's own default).
TEST(VelocityTable, TheKnifesDefaultMovesIt)
{
  abrade::coupling::ParameterFile params("", {});
  const abrade::coupling::DemCase c = abrade::coupling::read_dem_case(params);
  EXPECT_EQ(c.walls[1].wall.name, "knife");
  EXPECT_EQ(c.walls[1].wall.motion.phases.at("travel").velocity, Vec3(1.5, 0, 0));
  EXPECT_EQ(c.walls[1].wall.motion.phases.at("penetration").velocity, Vec3(0, 0, -1.5));
}
