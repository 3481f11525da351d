// The rope grab's mechanism (dem/rope_grab.h) against answers found another way: its linkage
// against the triangle the tie rod closes (law of cosines), its reeving against counting the
// rope's parts, its statics (Lagrange's generalised loads) against free bodies in equilibrium
// (Newton, each body alone), its dynamics against free fall and against the energy the winch
// puts in.
#include <abrade/dem/rope_grab.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

using namespace abrade::dem;

namespace
{
  constexpr double g = 9.81;

  // A coarse grab's linkage, with numbers a hand can follow: at the open pose the tie rod spans
  // 0.2 m across and 0.48 m up (a 5-12-13 triangle of 0.52 m), so the head distance is
  // 0.1 + 0.48 = 0.58 m.
  RopeGrabDesign coarse_grab()
  {
    RopeGrabDesign d;
    d.upper_pin_offset       = 0.25;
    d.tie_rod_length         = 0.52;
    d.shell_pin              = {0.45, 0.10};
    d.closed_angle           = 0.9844;
    d.open_angle             = -0.1;
    d.falls                  = 4;
    d.lower_head_mass        = 120;
    d.upper_head_mass        = 80;
    d.shell_mass             = 150;
    d.shell_centre           = {0.22, -0.18};
    d.shell_inertia          = 4.0;
    d.closing_rope_stiffness = 2e5;
    d.holding_rope_stiffness = 4e5;
    d.winch_acceleration     = 3;
    return d;
  }

  double total_mass(const RopeGrabDesign &d) { return d.lower_head_mass + d.upper_head_mass + 2 * d.shell_mass; }

  /// The grab at rest, open at 3 m, hanging on its holding ropes, the closing rope just taut.
  RopeGrab::State hanging_open(const RopeGrab &grab)
  {
    RopeGrab::State s;
    s.z = 3;
    grab.tension_ropes(s, 0, total_mass(grab.design()) * g);
    return s;
  }
} // namespace

// The pin turned by hand: at 36.87 degrees (cos 0.8, sin 0.6) it is at
// (0.45 x 0.8 + 0.1 x 0.6, -0.45 x 0.6 + 0.1 x 0.8) = (0.42, -0.19); the rod spans
// 0.25 - 0.42 = -0.17 m across, so it rises sqrt(0.52^2 - 0.17^2) above the pin.
TEST(RopeGrab, HeadDistanceAtTwoPosesWorkedByHand)
{
  const RopeGrab grab(coarse_grab());
  EXPECT_NEAR(grab.head_distance(0.0), 0.58, 1e-12);
  const double angle = std::atan2(0.6, 0.8);
  EXPECT_NEAR(grab.shell_pin(angle).x(), 0.42, 1e-12);
  EXPECT_NEAR(grab.shell_pin(angle).y(), -0.19, 1e-12);
  EXPECT_NEAR(grab.head_distance(angle), -0.19 + std::sqrt(0.52 * 0.52 - 0.17 * 0.17), 1e-12);
  // closing the shells draws the heads together
  EXPECT_LT(grab.head_distance(angle), grab.head_distance(0.0));
}

// The inverse, by the triangle hinge - upper pin - shell pin: sides |HA|, |HP| = |p0|, l; the
// angle at the hinge from the law of cosines; the pin's polar angle is HA's minus it (the pin
// lies clockwise of HA, seen with x right and z up), and the shell has turned by the pin's
// open polar angle minus that.
TEST(RopeGrab, ShellAngleAtHeadDistanceAgainstTheLawOfCosines)
{
  const RopeGrabDesign design = coarse_grab();
  const RopeGrab       grab(design);
  for (const double distance : {0.55, 0.40, 0.25})
    {
      const double ha = std::hypot(design.upper_pin_offset, distance), hp = design.shell_pin.norm();
      const double at_hinge =
        std::acos((ha * ha + hp * hp - design.tie_rod_length * design.tie_rod_length) / (2 * ha * hp));
      const double pin_polar = std::atan2(distance, design.upper_pin_offset) - at_hinge;
      const double expected  = std::atan2(design.shell_pin.y(), design.shell_pin.x()) - pin_polar;
      EXPECT_NEAR(grab.angle_at_head_distance(distance), expected, 1e-9) << "head distance " << distance;
      // and the rod has its length there
      const Eigen::Vector2d pin = grab.shell_pin(expected);
      EXPECT_NEAR(std::hypot(design.upper_pin_offset - pin.x(), distance - pin.y()), design.tie_rod_length, 1e-12);
    }
  EXPECT_THROW(grab.angle_at_head_distance(0.9), std::domain_error);
}

// d' and d'' against central differences of d; the velocity terms against Lagrange's equations
// with M's derivative taken by differences.
TEST(RopeGrab, DerivativesAgainstDifferences)
{
  const RopeGrab grab(coarse_grab());
  const double   h = 1e-5;
  for (const double a : {-0.05, 0.2, 0.6, 0.95})
    {
      const double slope = (grab.head_distance(a + h) - grab.head_distance(a - h)) / (2 * h);
      const double curv  = (grab.head_distance(a + h) - 2 * grab.head_distance(a) + grab.head_distance(a - h)) / (h * h);
      EXPECT_NEAR(grab.head_distance_slope(a), slope, 1e-9);
      EXPECT_NEAR(grab.head_distance_curvature(a), curv, 1e-5);

      const Eigen::Matrix2d dm = (grab.mass_matrix(a + h) - grab.mass_matrix(a - h)) / (2 * h);
      const Eigen::Vector2d u(0.7, -1.3);
      // d/dt (M u) - 1/2 u^T dM/dq u at u' = 0: ( dM_za u_a^2, dM_aa u_a^2 - 1/2 dM_aa u_a^2 ) with u_z terms
      // cancelling in the second row
      const Eigen::Vector2d expected(dm(0, 1) * u[1] * u[1], 0.5 * dm(1, 1) * u[1] * u[1]);
      EXPECT_NEAR((grab.velocity_terms(a, u) - expected).norm(), 0, 1e-6 * expected.norm());
    }
}

// The reeving by counting parts: with the upper head held, the n falls between the heads
// shorten by n times the head distance's change and the line from the upper head to the crane
// stays; with the hinge held, the line lengthens by what the head rises (and the holding ropes).
TEST(RopeGrab, ClosingRopeLengthCountsTheFalls)
{
  const RopeGrabDesign design = coarse_grab();
  const RopeGrab       grab(design);
  const double         upper_head = 3.0; // the upper head's height, held
  const auto           parts      = [&](double z, double angle) {
    const double d = grab.head_distance(angle);
    return design.falls * d + (10.0 - (z + d)); // n falls + one line to a sheave at 10 m
  };
  const double a0 = 0.1, a1 = 0.8;
  const double z0 = upper_head - grab.head_distance(a0), z1 = upper_head - grab.head_distance(a1);
  const double change = grab.closing_rope_length(z1, a1) - grab.closing_rope_length(z0, a0);
  EXPECT_NEAR(change, parts(z1, a1) - parts(z0, a0), 1e-12);
  EXPECT_NEAR(change, design.falls * (grab.head_distance(a1) - grab.head_distance(a0)), 1e-12);
  // the holding ropes hang from the upper head: their length does not change when it is held
  EXPECT_NEAR(grab.holding_rope_length(z1, a1), grab.holding_rope_length(z0, a0), 1e-12);
}

// A grab held closed on a rigid block between its lips, hanging on its closing rope (holding
// ropes slack). Newton, body by body: the whole grab hangs on the one line to the crane, so
// T = m g. The upper head: T up, n T down from the falls, its weight, and two tie rods pushing
// it up along the rod direction e (from shell pin to upper pin) with compression C:
// C = ((n - 1) T + m_u g) / (2 e_z). The right shell about the hinge: the rod pushes its pin
// with -C e, its weight acts at its centre of mass, the block pushes its lip outwards with F;
// torques about +y (z F_x - x F_z) sum to zero, which gives F. Then Lagrange's generalised
// loads of the same forces must leave the mechanism at rest.
TEST(RopeGrab, HeldClosedOnABlockRopePullBalancesTheLipsThroughTheLinkage)
{
  const RopeGrabDesign design = coarse_grab();
  const RopeGrab       grab(design);
  for (const double angle : {0.7, 0.9})
    {
      RopeGrab::State s;
      s.z     = 2.0;
      s.angle = angle;
      const double m = total_mass(design), n = design.falls;
      const double t = m * g;
      grab.tension_ropes(s, t, 0);

      const Eigen::Vector2d pin = grab.shell_pin(angle);
      const Eigen::Vector2d upper(design.upper_pin_offset, grab.head_distance(angle));
      const Eigen::Vector2d e = (upper - pin) / design.tie_rod_length;
      const double          c = ((n - 1) * t + design.upper_head_mass * g) / (2 * e.y());
      const auto torque = [](const Eigen::Vector2d &r, const Eigen::Vector2d &f) { return r.y() * f.x() - r.x() * f.y(); };
      const Eigen::Vector2d lip(0.05, -0.42); // where the block touches the right lip
      const double rod     = torque(pin, -c * e);
      const double weight  = torque(grab.shell_centre(angle), Eigen::Vector2d(0, -design.shell_mass * g));
      const double f       = -(rod + weight) / lip.y();
      EXPECT_GT(f, 0) << "the block pushes the lips apart";

      const double lip_torque = torque(lip, Eigen::Vector2d(f, 0));
      // the left lip's force is the mirror image: (-f, 0) at (-x, z), torque -lip_torque
      const Eigen::Vector2d particles = grab.load(RopeGrab::Part::right_shell, 0, lip_torque, angle) +
                                        grab.load(RopeGrab::Part::left_shell, 0, -lip_torque, angle);
      const Winch closing{0, std::numeric_limits<double>::infinity()}, holding{0, 0};
      const Eigen::Vector2d a = grab.acceleration(s, particles, g, closing, holding);
      EXPECT_NEAR(a[0], 0, 1e-6 * g) << "at " << angle << " rad";
      EXPECT_NEAR(a[1], 0, 1e-6 * g) << "at " << angle << " rad";
      // and the balance is not trivial: a tenth more pull would close the shells on the block
      grab.tension_ropes(s, 1.1 * t, 0);
      EXPECT_GT(grab.acceleration(s, particles, g, closing, holding)[1], 1e-3);
    }
}

// With the ropes slack the grab falls freely: every body at g, the shells keep their angle.
TEST(RopeGrab, FallsFreelyWithSlackRopes)
{
  RopeGrab        grab(coarse_grab());
  RopeGrab::State s;
  s.z     = 5;
  s.angle = 0.3;
  grab.tension_ropes(s, 0, 0);
  s.closing_paid_out += 10;
  s.holding_paid_out += 10; // slack
  const Winch  still{0, std::numeric_limits<double>::infinity()};
  const double dt = 1e-4;
  for (int i = 0; i < 10000; ++i)
    grab.step(s, dt, Eigen::Vector2d::Zero(), g, still, still);
  // semi-implicit Euler: z_n = z_0 - g dt^2 n (n + 1) / 2
  EXPECT_NEAR(s.z, 5 - g * dt * dt * 10000.0 * 10001.0 / 2, 1e-9);
  EXPECT_NEAR(s.z_rate, -g * 1.0, 1e-9);
  EXPECT_NEAR(s.angle, 0.3, 1e-12);
}

// The energy of the integrated motion. The DEM's integration (semi-implicit Euler) is
// leapfrog's: positions at the steps, velocities between them; the kinetic energy at a step is
// that of the mean of the velocities either side of it.
double synchronised_energy(const RopeGrab &grab, const RopeGrab::State &before, const RopeGrab::State &after)
{
  RopeGrab::State at = before;
  at.z_rate          = 0.5 * (before.z_rate + after.z_rate);
  at.angle_rate      = 0.5 * (before.angle_rate + after.angle_rate);
  return grab.energy(at, g);
}

// A cycle in vacuum: the grab, open and hanging on its holding ropes, is lowered by both
// winches, then falls with the holding ropes slack while the closing winch hauls in and closes
// it onto its stop, then is hoisted at the closing winch's stall pull, a constant load of the
// particles' kind acting throughout. Energy: kinetic + gravity + the ropes' elastic energy
// changes by the work the winches do on the ropes and the load's, less the rope damping and the
// shells' impact on their stop, to 1e-4 of the winches' work.
TEST(RopeGrab, ACycleInVacuumConservesEnergyWithTheWinchesWork)
{
  for (const double damping : {0.0, 2e3})
    {
      RopeGrabDesign design       = coarse_grab();
      design.closing_rope_damping = damping;
      design.holding_rope_damping = damping;
      design.open_angle           = 0; // it starts on its opening stop
      RopeGrab        grab(design);
      RopeGrab::State s = hanging_open(grab);
      const double    m = total_mass(design);

      const double inf = std::numeric_limits<double>::infinity();
      const double dt  = 2e-5;
      struct Phase
      {
        double seconds;
        Winch  closing, holding;
      };
      const Phase cycle[] = {
        {0.5, {-0.5, inf}, {-0.5, inf}},   // lowering
        {1.0, {0.4, 3 * m * g}, {0, 0}},   // closing: holding ropes slack
        {1.0, {0.5, 1.5 * m * g}, {0, 0}}, // hoisting on the closing rope
      };
      // a constant load of the particles' kind (a vertical force and a closing moment)
      const Eigen::Vector2d particles(-300, 40);
      double          e0 = 0, e1 = 0, most_angle = 0, least_angle = 0, lowered_angle = 0;
      RopeGrab::Work  w0, w1;
      RopeGrab::State first_state, last_state;
      bool            first = true;
      for (const Phase &p : cycle)
        for (int i = 0; i < int(std::lround(p.seconds / dt)); ++i)
          {
            const RopeGrab::State before = s;
            const RopeGrab::Work  work   = grab.work();
            grab.step(s, dt, particles, g, p.closing, p.holding);
            e1 = synchronised_energy(grab, before, s);
            w1 = work;
            if (first)
              e0 = e1, w0 = w1, first_state = before, first = false;
            last_state = before;
            most_angle  = std::max(most_angle, s.angle);
            least_angle = std::min(least_angle, s.angle);
            if (&p == cycle)
              lowered_angle = s.angle;
          }
      const double winches = w1.winches - w0.winches, dissipated = w1.damping - w0.damping,
                   stops = w1.stops - w0.stops, loads = w1.loads - w0.loads;
      EXPECT_EQ(most_angle, design.closed_angle) << "the shells closed onto their stop";
      EXPECT_EQ(least_angle, design.open_angle) << "opened past its stop";
      EXPECT_EQ(lowered_angle, design.open_angle) << "lowered on its holding ropes, it hangs open on its stop";
      EXPECT_GT(std::abs(loads), 100.0);
      // the constant load's work, Q . (q_end - q_start), over the same steps as the ledger's
      EXPECT_NEAR(loads,
                  particles.dot(Eigen::Vector2d(last_state.z - first_state.z, last_state.angle - first_state.angle)),
                  1e-9 * std::abs(loads));
      EXPECT_GT(stops, 100.0);
      EXPECT_GT(std::abs(winches), 1000.0);
      EXPECT_NEAR(e1 - e0, winches - dissipated - stops + loads, 1e-4 * std::abs(winches))
        << "damping " << damping << ": winches " << winches << " J, damping " << dissipated << " J, stop "
        << stops << " J, loads " << loads << " J";
      if (damping > 0)
        EXPECT_GT(dissipated, 10.0);
      else
        EXPECT_EQ(dissipated, 0);
    }
}

// The shells arriving at their stop, nothing else acting: a plastic impact in the angle. The
// grab keeps its vertical momentum M_zz z' + M_za angle' and loses 1/2 M_eff angle'^2, with
// M_eff = M_aa - M_za^2 / M_zz (a collision of two bodies, here the angle and the rest).
TEST(RopeGrab, ShellsStopPlasticallyKeepingTheVerticalMomentum)
{
  const RopeGrabDesign design = coarse_grab();
  RopeGrab             grab(design);
  RopeGrab::State      s;
  s.z          = 2;
  s.angle      = design.closed_angle - 1e-3;
  s.angle_rate = 2.0;
  s.z_rate     = -0.3;
  s.closing_paid_out = s.holding_paid_out = 1e3; // slack
  const Eigen::Matrix2d m = grab.mass_matrix(design.closed_angle);
  const double          momentum = m(0, 0) * s.z_rate + m(0, 1) * s.angle_rate;
  const Winch           still{0, std::numeric_limits<double>::infinity()};
  for (int i = 0; i < 100; ++i)
    grab.step(s, 1e-5, Eigen::Vector2d::Zero(), 0.0, still, still);
  EXPECT_EQ(s.angle, design.closed_angle);
  EXPECT_EQ(s.angle_rate, 0);
  // the momentum and the energy at the stop's mass matrix (the 1 mrad before it changes M by
  // about 1e-3 of itself)
  EXPECT_NEAR(m(0, 0) * s.z_rate, momentum, 2e-3 * std::abs(momentum));
  const double before = 0.5 * (m(0, 0) * 0.09 - 2 * m(0, 1) * 0.3 * 2.0 + m(1, 1) * 4.0);
  const double lost   = 0.5 * (m(1, 1) - m(0, 1) * m(0, 1) / m(0, 0)) * 4.0;
  EXPECT_NEAR(grab.kinetic_energy(s), before - lost, 2e-3 * before);
  EXPECT_NEAR(grab.work().stops, lost, 2e-3 * lost);
}

// The kinetic energy against the bodies' own velocities, each found by differentiating its
// position along the motion numerically: the heads (on the axis), each shell's centre of mass
// (turned about the moving hinge) and its spin.
TEST(RopeGrab, KineticEnergyIsTheBodiesOwn)
{
  const RopeGrabDesign design = coarse_grab();
  const RopeGrab       grab(design);
  for (const double angle : {-0.05, 0.4, 0.9})
    {
      RopeGrab::State s;
      s.z          = 1.3;
      s.angle      = angle;
      s.z_rate     = -0.7;
      s.angle_rate = 1.9;
      const double h        = 1e-6;
      const auto   position = [&](double t) {
        const double z = s.z + t * s.z_rate, a = s.angle + t * s.angle_rate;
        const double c = std::cos(a), sn = std::sin(a);
        const Eigen::Vector2d shell(design.shell_centre.x() * c + design.shell_centre.y() * sn,
                                    -design.shell_centre.x() * sn + design.shell_centre.y() * c);
        // lower head, upper head, right shell's centre, left shell's centre (x mirrored)
        return std::array<Eigen::Vector2d, 4>{Eigen::Vector2d(0, z), Eigen::Vector2d(0, z + grab.head_distance(a)),
                                              Eigen::Vector2d(0, z) + shell,
                                              Eigen::Vector2d(-shell.x(), z + shell.y())};
      };
      const auto   ahead = position(h), behind = position(-h);
      const double masses[] = {design.lower_head_mass, design.upper_head_mass, design.shell_mass, design.shell_mass};
      double       energy   = 2 * 0.5 * design.shell_inertia * s.angle_rate * s.angle_rate; // the shells' spin
      for (int b = 0; b < 4; ++b)
        energy += 0.5 * masses[b] * ((ahead[b] - behind[b]) / (2 * h)).squaredNorm();
      EXPECT_NEAR(grab.kinetic_energy(s), energy, 1e-7 * energy) << "at " << angle << " rad";
    }
}

// Hanging still on one rope, the grab bobs on it as a damped oscillator of its whole mass: on
// the holding ropes open on the opening stop, on the closing rope closed on the closing stop
// (the shells pressed onto the stop, the angle fixed: the rope's length changes by -dz). The
// amplitude falls by exp(-2 pi zeta / sqrt(1 - zeta^2)) each period 2 pi / (omega sqrt(1 -
// zeta^2)), omega^2 = k / m, zeta = c / (2 sqrt(k m)).
TEST(RopeGrab, BobsOnItsRopeAsADampedOscillator)
{
  for (const bool closing : {false, true})
    {
      RopeGrabDesign design = coarse_grab();
      const double   k = closing ? design.closing_rope_stiffness : design.holding_rope_stiffness;
      const double   m = total_mass(design), zeta = 0.05;
      (closing ? design.closing_rope_damping : design.holding_rope_damping) = 2 * zeta * std::sqrt(k * m);
      RopeGrab        grab(design);
      RopeGrab::State s;
      s.z     = 2;
      s.angle = closing ? design.closed_angle : design.open_angle;
      // 1 % more stretch than the weight's: it starts 0.01 m g / k below its rest
      grab.tension_ropes(s, closing ? 1.01 * m * g : 0, closing ? 0 : 1.01 * m * g);
      const Winch brake{0, std::numeric_limits<double>::infinity()}, slack{0, 0};
      const double dt = 1e-6, omega = std::sqrt(k / m), damped = omega * std::sqrt(1 - zeta * zeta);
      const double rest = s.z + 0.01 * m * g / k;
      std::vector<double> peaks; // |z - rest| at the turning points
      double              previous_rate = 0;
      for (int i = 0; i < int(2.5 * 2 * M_PI / damped / dt); ++i)
        {
          grab.step(s, dt, Eigen::Vector2d::Zero(), g, closing ? brake : slack, closing ? slack : brake);
          if (i > 0 && (s.z_rate > 0) != (previous_rate > 0))
            peaks.push_back(std::abs(s.z - rest));
          previous_rate = s.z_rate;
          ASSERT_EQ(s.angle, closing ? design.closed_angle : design.open_angle) << "left its stop";
        }
      ASSERT_GE(peaks.size(), 4u);
      const double expected = std::exp(-2 * M_PI * zeta / std::sqrt(1 - zeta * zeta));
      EXPECT_NEAR(peaks[2] / peaks[0], expected, 2e-3) << (closing ? "closing" : "holding") << " rope";
      EXPECT_NEAR(peaks[3] / peaks[1], expected, 2e-3) << (closing ? "closing" : "holding") << " rope";
    }
}

// While the shells turn and the hinge moves, a taut rope's tension is k e + c de/dt, with the
// stretch's rate from the rope's length differentiated numerically along the motion, plus the
// drum's hauling speed.
TEST(RopeGrab, RopeTensionIsElasticPlusDampingOfTheStretchRate)
{
  RopeGrabDesign design       = coarse_grab();
  design.closing_rope_damping = 3e3;
  design.holding_rope_damping = 1e3;
  const RopeGrab  grab(design);
  RopeGrab::State s;
  s.z                  = 1.5;
  s.angle              = 0.5;
  s.z_rate             = 0.3;
  s.angle_rate         = -0.8;
  s.closing_drum_speed = 0.6;
  s.holding_drum_speed = -0.4;
  grab.tension_ropes(s, 2000, 3000);
  const Winch  free_pull{0.6, std::numeric_limits<double>::infinity()};
  const double h    = 1e-6;
  const auto   rate = [&](auto length) {
    return (length(s.z + h * s.z_rate, s.angle + h * s.angle_rate) -
            length(s.z - h * s.z_rate, s.angle - h * s.angle_rate)) / (2 * h);
  };
  const double closing_rate =
    rate([&](double z, double a) { return grab.closing_rope_length(z, a); }) + s.closing_drum_speed;
  const double holding_rate =
    rate([&](double z, double a) { return grab.holding_rope_length(z, a); }) + s.holding_drum_speed;
  EXPECT_NEAR(grab.closing_tension(s, free_pull), 2000 + 3e3 * closing_rate, 1e-5);
  EXPECT_NEAR(grab.holding_tension(s, free_pull), 3000 + 1e3 * holding_rate, 1e-5);
  EXPECT_GT(std::abs(closing_rate), 0.5); // the damping is a real part of the tension here
}

// A drum reaches the speed asked for at the winch's acceleration: paying out from rest, it has
// paid out a t^2 / 2 after t.
TEST(RopeGrab, DrumsRampUpAtTheWinchsAcceleration)
{
  const RopeGrabDesign design = coarse_grab();
  RopeGrab             grab(design);
  RopeGrab::State      s = hanging_open(grab);
  const double paid = s.holding_paid_out, dt = 1e-5, t = 0.2;
  for (int i = 0; i < int(std::lround(t / dt)); ++i)
    grab.step(s, dt, Eigen::Vector2d::Zero(), g, Winch{0, 0}, Winch{-1.0, std::numeric_limits<double>::infinity()});
  EXPECT_NEAR(s.holding_drum_speed, -design.winch_acceleration * t, 1e-9);
  EXPECT_NEAR(s.holding_paid_out - paid, 0.5 * design.winch_acceleration * t * t, 1e-5);
}

// A drum that follows its rope (pull 0) is at rest when a powered phase begins: it then
// speeds up at the winch's acceleration.
// A drum that keeps its rope just slack (pull 0) still turns at its winch's speed, reached at
// the winch's acceleration; a winch that takes the rope over again ramps from that speed, not
// from rest (a closing winch paying out as the grab lands is reversed, not stopped at once).
TEST(RopeGrab, ASlackDrumTurnsAtItsWinchsSpeed)
{
  const RopeGrabDesign design = coarse_grab();
  RopeGrab             grab(design);
  RopeGrab::State      s = hanging_open(grab);
  const double dt = 1e-5, inf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 1000; ++i) // the closing drum pays out, its rope slack
    grab.step(s, dt, Eigen::Vector2d::Zero(), g, Winch{-1.0, 0}, Winch{0, inf});
  EXPECT_NEAR(s.closing_drum_speed, -design.winch_acceleration * 1000 * dt, 1e-12) << "ramping";
  EXPECT_EQ(grab.closing_tension(s, Winch{-1.0, 0}), 0) << "slack";
  for (int i = 0; i < int(1.0 / (design.winch_acceleration * dt)) + 10; ++i) // (past its speed)
    grab.step(s, dt, Eigen::Vector2d::Zero(), g, Winch{-1.0, 0}, Winch{0, inf});
  EXPECT_EQ(s.closing_drum_speed, -1.0);
  grab.step(s, dt, Eigen::Vector2d::Zero(), g, Winch{1.0, inf}, Winch{0, inf});
  EXPECT_NEAR(s.closing_drum_speed, -1.0 + design.winch_acceleration * dt, 1e-15);
}

TEST(RopeGrab, RefusesALinkageThatCannotWork)
{
  RopeGrabDesign d = coarse_grab();
  d.tie_rod_length = 0.1; // cannot reach the shells
  EXPECT_THROW(d.check(), RopeGrabDesignError);
  d                = coarse_grab();
  d.closed_angle   = 2.5; // passes the toggle point (or the heads meet) before closing
  EXPECT_THROW(d.check(), RopeGrabDesignError);
  d            = coarse_grab();
  d.shell_mass = 0;
  EXPECT_THROW(d.check(), RopeGrabDesignError);
  // massless heads and a shell without inertia whose centre of mass is on the hinge's
  // vertical at some angle: a motion without inertia
  d                 = coarse_grab();
  d.lower_head_mass = d.upper_head_mass = d.shell_inertia = 0;
  d.shell_centre    = {0.3, 0.0}; // level with the hinge at the open pose
  try
    {
      d.check();
      ADD_FAILURE() << "a singular mass matrix was accepted";
    }
  catch (const RopeGrabDesignError &e)
    {
      EXPECT_EQ(e.parameter, "Lower head mass");
    }
  EXPECT_NO_THROW(coarse_grab().check());
}
