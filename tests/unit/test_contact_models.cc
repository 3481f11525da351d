// The contact law's optional sub-models (contact_law.h) against analytic answers:
//  - sjkr cohesion: the force-overlap curve of a sphere pair (through the batched pair kernel)
//    and of a sphere on a plane (through the wall contacts) is the Hertz force minus k_c times
//    the area of the circle the bodies intersect in, written here from the intersection's
//    geometry (1e-9); its minimum, the pull-off force, is -(2/3) pi^3 k_c^3 R*^2 / E*^2 (1 %);
//    a sphere hanging under a ceiling stays when its weight is below the pull-off force and
//    falls when above it;
//  - epsd rolling: a sphere launched rolling on a plane stops at 7 v0^2 / (10 mu_r g) (1 %;
//    the constant torque too), and then stays at rest without chatter; on a slope of
//    tan(theta) = mu_r / 2 it stays at rest, on tan(theta) = 2 mu_r it rolls with
//    (5/7) g (sin(theta) - mu_r cos(theta));
//  - a heap of cohesive grains stands steeper than a cohesionless one and stays as it is.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material ore = Material::from_shear_modulus("ore", 4e8, 0.25, 3000, false);

  /// The normal force on a sphere of radius @p ri at overlap @p delta with a sphere of radius
  /// @p rj (rj = 0: a plane), at rest, with cohesion @p k (sjkr), from one step of length 1e-14 s.
  double static_force(double ri, double rj, double delta, double k)
  {
    Settings s = quiet_settings(1e-14);
    s.contact.cohesion = "sjkr";
    Simulation  sim(s);
    const int   m = sim.add_material(ore);
    Interaction i{0.5, 0.5, 0.0};
    i.cohesion_energy_density = k;
    sim.set_interaction(m, m, i);
    auto &P = sim.particles();
    if (rj > 0)
      {
        P.add(0, 0, 0, 0, ri, ore.density, m);
        P.add(1, -(ri + rj - delta), 0, 0, rj, ore.density, m);
      }
    else
      {
        sim.add_wall(floor_wall(m, 1.0));
        P.add(0, 0.01, 0.02, ri - delta, ri, ore.density, m);
      }
    sim.setup();
    sim.step();
    const std::size_t a = index_of(sim, 0);
    return rj > 0 ? P.fx[a] : P.fz[a];
  }

  /// The same from the formulas: Hertz minus k pi a^2, a the radius of the intersection circle.
  double analytic_force(double ri, double rj, double delta, double k)
  {
    const double es = e_star(ore, ore);
    double       r_eff, a2;
    if (rj > 0)
      {
        const double d = ri + rj - delta, x = (d * d + ri * ri - rj * rj) / (2 * d); // centre of i to the circle
        r_eff = ri * rj / (ri + rj), a2 = ri * ri - x * x;
      }
    else
      r_eff = ri, a2 = ri * ri - (ri - delta) * (ri - delta);
    return 4.0 / 3.0 * es * std::sqrt(r_eff) * std::pow(delta, 1.5) - k * M_PI * a2;
  }
} // namespace

TEST(SjkrCohesion, ForceOverlapCurveAndPullOffOfPairsAndWalls)
{
  const double k = 2e6, es = e_star(ore, ore);
  for (const auto &[ri, rj] : {std::pair{0.01, 0.015}, std::pair{0.01, 0.0}})
    {
      const double r_eff     = rj > 0 ? ri * rj / (ri + rj) : ri;
      const double pull_off  = -2.0 / 3.0 * std::pow(M_PI * k, 3) * r_eff * r_eff / (es * es);
      const double delta_min = std::pow(M_PI * k * std::sqrt(r_eff) / es, 2); // where the curve is lowest
      double       lowest    = 0;
      for (double f = 0.1; f <= 5; f *= 1.05)
        {
          const double delta = f * delta_min, F = static_force(ri, rj, delta, k);
          EXPECT_NEAR(F, analytic_force(ri, rj, delta, k), 1e-7 * std::abs(pull_off))
            << (rj > 0 ? "pair" : "wall") << " at " << delta << " m";
          lowest = std::min(lowest, F);
        }
      EXPECT_NEAR(lowest / pull_off, 1, 0.01) << (rj > 0 ? "pair" : "wall");
      // cohesion off: Hertz alone
      EXPECT_NEAR(static_force(ri, rj, delta_min, 0), analytic_force(ri, rj, delta_min, 0), 1e-7 * std::abs(pull_off));
    }
}

TEST(SjkrCohesion, SphereHangsUnderACeilingBelowThePullOffForce)
{
  const double R = 0.01, k = 2e6, es = e_star(ore, ore);
  const double pull_off = 2.0 / 3.0 * std::pow(M_PI * k, 3) * R * R / (es * es);
  const double m        = sphere_mass(R, ore.density);
  auto         hangs    = [&](double weight_share) {
    Settings s          = quiet_settings(2e-7);
    s.contact.cohesion  = "sjkr";
    s.gravity           = Vec3(0, 0, -weight_share * pull_off / m);
    Simulation  sim(s);
    const int   mo = sim.add_material(ore);
    Interaction i{0.3, 0.5, 0.0};
    i.cohesion_energy_density = k;
    sim.set_interaction(mo, mo, i);
    Wall ceiling = floor_wall(mo, 1.0);
    ceiling.mesh.flip(); // normal -z: the sphere below it
    sim.add_wall(ceiling);
    // start where the contact force vanishes (2.25 x the overlap of the pull-off), at rest
    const double delta0 = 2.25 * std::pow(M_PI * k * std::sqrt(R) / es, 2);
    sim.particles().add(0, 0.01, 0.02, -(R - delta0), R, ore.density, mo);
    sim.setup();
    sim.run_phase("hang", 0.02);
    return sim.particles().z[0] > -R; // still overlapping the ceiling
  };
  EXPECT_TRUE(hangs(0.5));
  EXPECT_TRUE(hangs(0.85));
  EXPECT_FALSE(hangs(1.1));
}

namespace
{
  const Material glass{"glass", 48e9, 0.2, 2800, true};
  constexpr double R = 0.01, mu_r = 0.1, g = 9.81;

  /// A glass sphere resting on a plane, with rolling model @p model and gravity tilted by
  /// @p theta about y (x points down the slope).
  Simulation sphere_on_plane(const std::string &model, double theta)
  {
    Settings s       = quiet_settings(2e-6, true);
    s.gravity        = Vec3(g * std::sin(theta), 0, -g * std::cos(theta));
    s.contact.rolling = model;
    Simulation sim(s);
    const int  ms = sim.add_material(glass), mw = sim.add_material(glass);
    sim.set_interaction(ms, mw, {0.5, 0.5, mu_r});
    sim.add_wall(floor_wall(mw, 3.0));
    sim.particles().add(0, -1.0, 0, R, R, glass.density, ms);
    sim.setup();
    sim.run_phase("rest", 0.01);
    auto &P = sim.particles();
    P.vx[0] = P.vy[0] = P.vz[0] = P.wx[0] = P.wy[0] = P.wz[0] = 0;
    return sim;
  }
} // namespace

class RollingModel : public ::testing::TestWithParam<std::string>
{};

TEST_P(RollingModel, RollingSphereStopsAtTheAnalyticDistanceAndStaysThere)
{
  Simulation   sim = sphere_on_plane(GetParam(), 0);
  auto        &P   = sim.particles();
  const double v0 = 0.5, x0 = P.x[0];
  P.vx[0] = v0, P.wy[0] = v0 / R; // rolling without slip
  const double stop = v0 / (5.0 / 7.0 * mu_r * g);
  sim.run_phase("roll", 1.1 * stop);
  const double distance = P.x[0] - x0;
  EXPECT_NEAR(distance / (7 * v0 * v0 / (10 * mu_r * g)), 1, 0.01) << GetParam();
  // at rest, and it stays: no creep, no chatter of the spin
  const double x1 = P.x[0];
  double       spin = 0;
  for (int k = 0; k < 20000; ++k)
    {
      sim.step();
      spin = std::max(spin, R * std::sqrt(P.wx[0] * P.wx[0] + P.wy[0] * P.wy[0] + P.wz[0] * P.wz[0]));
    }
  EXPECT_LT(std::abs(P.x[0] - x1), 1e-6) << GetParam();
  EXPECT_LT(spin, 1e-5) << GetParam() << ": the contact point moves at up to " << spin << " m/s at rest";
}

TEST_P(RollingModel, SlopeBelowTheRollingLimitHoldsASphereAboveItRollsDown)
{
  {
    Simulation   sim = sphere_on_plane(GetParam(), std::atan(0.5 * mu_r));
    const double x0  = sim.particles().x[0];
    sim.run_phase("hold", 0.2);
    EXPECT_LT(std::abs(sim.particles().x[0] - x0), 1e-6) << GetParam();
  }
  {
    const double theta = std::atan(2 * mu_r);
    Simulation   sim   = sphere_on_plane(GetParam(), theta);
    sim.run_phase("start", 0.05);
    const double v1 = sim.particles().vx[0], t1 = sim.time();
    sim.run_phase("roll", 0.1);
    const double a = (sim.particles().vx[0] - v1) / (sim.time() - t1);
    EXPECT_NEAR(a / (5.0 / 7.0 * g * (std::sin(theta) - mu_r * std::cos(theta))), 1, 0.02) << GetParam();
  }
}

INSTANTIATE_TEST_SUITE_P(ContactModels, RollingModel, ::testing::Values("constant torque", "epsd"),
                         [](const auto &info) { return info.param == "epsd" ? "epsd" : "constant_torque"; });

TEST(SjkrCohesion, CohesiveHeapIsSteeperAndStable)
{
  auto heap = [](double k) {
    const Material grain = Material::from_shear_modulus("grain", 1e7, 0.25, 2500, false);
    Settings       s;
    s.threads          = 2;
    s.contact.cohesion = "sjkr";
    Interaction i{0.5, 0.5, 0.0};
    i.cohesion_energy_density = k;
    const PouredHeap h        = pour_heap(s, grain, i);
    std::printf("cohesion %g J/m^3: angle of repose %.1f deg after 1.5 s, %.1f deg after 2.0 s; kinetic energy %.3g J\n",
                k, h.after_pour, h.after_rest, h.kinetic_energy);
    EXPECT_NEAR(h.after_rest, h.after_pour, 1.0);
    EXPECT_LT(h.kinetic_energy, 1e-3);
    return h.after_rest;
  };
  // k_c = 1e5 J/m^3: under its own weight a grain's contacts carry an attraction of a few
  // per cent of it (k_c pi a^2 against m g)
  const double dry = heap(0), cohesive = heap(1e5);
  EXPECT_GT(cohesive, dry + 5);
}

// The pair path of the epsd model: two cohesive spheres held together in free space, one
// spinning about an axis across their contact. The rolling spring brakes the relative rotation
// until the pair turns as one; the torques on the two spheres are opposite, so the pair's
// angular momentum (spins and orbital) is kept. (Without friction: the tangential force acts at
// two contact points a distance delta apart, which changes it by O(delta / r).)
TEST(EpsdRolling, SpinningPairStopsRollingAndKeepsItsAngularMomentum)
{
  const Material ball{"ball", 1e8, 0.25, 2000, true};
  const double   r = 0.01;
  Settings       s = quiet_settings(5e-6);
  s.contact.rolling = "epsd", s.contact.cohesion = "sjkr";
  Simulation  sim(s);
  const int   mb = sim.add_material(ball);
  Interaction i{0.5, 0.0, 0.2};
  i.cohesion_energy_density = 2e6;
  sim.set_interaction(mb, mb, i);
  auto &P = sim.particles();
  P.add(0, 0, 0, 0, r, ball.density, mb);
  P.add(1, 2 * r - 2e-5, 0, 0, r, ball.density, mb);
  sim.setup();
  sim.run_phase("stick", 0.01); // the cohesion pulls them to their equilibrium overlap
  for (std::size_t k = 0; k < 2; ++k)
    P.vx[k] = P.vy[k] = P.vz[k] = P.wx[k] = P.wy[k] = P.wz[k] = 0;
  P.wz[index_of(sim, 0)] = 5; // about z, across the contact normal x

  auto angular_momentum = [&] {
    Vec3 L = Vec3::Zero();
    for (std::size_t k = 0; k < 2; ++k)
      {
        const double inertia = 0.4 * P.mass[k] * r * r;
        L += P.mass[k] * Vec3(P.x[k], P.y[k], P.z[k]).cross(Vec3(P.vx[k], P.vy[k], P.vz[k])) +
             inertia * Vec3(P.wx[k], P.wy[k], P.wz[k]);
      }
    return L;
  };
  const Vec3 L0 = angular_momentum();
  sim.run_phase("roll", 0.05);
  const Vec3 L1 = angular_momentum();
  EXPECT_LT((L1 - L0).norm(), 1e-6 * L0.norm()) << "L0 " << L0.transpose() << ", L1 " << L1.transpose();
  const std::size_t a = index_of(sim, 0), b = index_of(sim, 1);
  EXPECT_LT(std::abs(P.wz[a] - P.wz[b]), 0.01 * 5) << "still rolling: " << P.wz[a] << " vs " << P.wz[b];
}

// The epsd spring and dashpot themselves: a sphere resting on a plane, given a small rolling
// spin below the limit, rocks about its contact point. With the tangential spring k_t and the
// rolling spring k_r (I = 0.4 m R^2, x the centre, phi the rotation):
//   m x'' = -k_t (x - R phi),   I phi'' = k_t R (x - R phi) - k_r phi,
// whose slow mode has omega^2 = the smaller root of m I l^2 - (m (k_t R^2 + k_r) + I k_t) l + k_t k_r
// (about k_r / (1.4 m R^2)); the dashpot at eta_r of 2 sqrt(I_r k_r) damps it with the
// logarithmic decrement 2 pi eta_r / sqrt(1 - eta_r^2).
TEST(EpsdRolling, RockingSphereOscillatesWithTheSpringsPeriodAndDecrement)
{
  auto rock = [](double eta, std::vector<double> &spin) {
    Settings s        = quiet_settings(1e-6, true);
    s.contact.rolling = "epsd";
    Simulation  sim(s);
    const int   ms = sim.add_material(glass), mw = sim.add_material(glass);
    Interaction i{0.9, 0.5, mu_r};
    i.rolling_damping = eta;
    sim.set_interaction(ms, mw, i);
    sim.add_wall(floor_wall(mw, 1.0));
    auto &P = sim.particles();
    P.add(0, 0.013, 0.017, R, R, glass.density, ms);
    sim.setup();
    sim.run_phase("rest", 0.05);
    P.vx[0] = P.vy[0] = P.vz[0] = P.wx[0] = P.wz[0] = 0;
    P.wy[0] = 0.01, P.vx[0] = 0.01 * R; // rolling, well below the limit (about 0.03 rad/s here)
    for (int k = 0; k < 30000; ++k)
      {
        sim.step();
        spin.push_back(P.wy[0]);
      }
  };
  // the springs at the static overlap under the sphere's weight
  const double m = sphere_mass(R, glass.density), I = 0.4 * m * R * R, es = e_star(glass, glass);
  const double g_star = 1 / (2 * (2 - glass.poisson_ratio) / glass.shear_modulus());
  const double delta  = std::pow(m * g / (4.0 / 3.0 * es * std::sqrt(R)), 2.0 / 3.0);
  const double k_n = 4.0 / 3.0 * es * std::sqrt(R * delta), k_t = 8 * g_star * std::sqrt(R * delta);
  const double k_r = 2.25 * k_n * mu_r * mu_r * R * R;
  const double b = m * (k_t * R * R + k_r) + I * k_t, lambda = (b - std::sqrt(b * b - 4 * m * I * k_t * k_r)) / (2 * m * I);
  const double period = 2 * M_PI / std::sqrt(lambda);

  std::vector<double> spin;
  rock(0, spin);
  std::vector<double> crossings; // upward zero crossings [steps], interpolated
  for (std::size_t k = 1; k < spin.size(); ++k)
    if (spin[k - 1] < 0 && spin[k] >= 0)
      crossings.push_back(k - 1 + spin[k - 1] / (spin[k - 1] - spin[k]));
  ASSERT_GE(crossings.size(), 4u) << "no oscillation";
  const double measured = (crossings.back() - crossings.front()) / (crossings.size() - 1) * 1e-6;
  EXPECT_NEAR(measured / period, 1, 0.02) << "period " << measured << " s, springs " << period << " s";

  spin.clear();
  const double eta = 0.3;
  rock(eta, spin);
  std::vector<double> peaks; // successive maxima of the spin
  for (std::size_t k = 1; k + 1 < spin.size() && peaks.size() < 3; ++k)
    if (spin[k] > spin[k - 1] && spin[k] >= spin[k + 1] && spin[k] > 0)
      peaks.push_back(spin[k]);
  ASSERT_GE(peaks.size(), 3u);
  const double decrement = std::log(peaks[1] / peaks[2]);
  EXPECT_NEAR(decrement / (2 * M_PI * eta / std::sqrt(1 - eta * eta)), 1, 0.1) << "peaks " << peaks[1] << ", " << peaks[2];
}
