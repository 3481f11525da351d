// Wear laws against analytic answers (shared/reference/verification.md):
//  - a frictionless non-rotating sphere of mass m sliding at constant speed v for time T on one
//    triangle: Q = W m g v T, depth = Q / A, exact to round-off; on many triangles the summed
//    volume is still exact (edge and vertex contacts are split, not counted twice);
//  - a non-rotating sphere launched at v0 on a plane with friction mu: Q = W m v0^2 / (2 mu),
//    and the tangential (friction) energy of the relative wear law equals the initial kinetic
//    energy;
//  - per vertex, the wear lands where it happened: sliding along a straight path on one
//    triangle, each vertex receives Q times its barycentric weight at the path's midpoint (the
//    weights are linear along the path), exactly; over many triangles the vertex values sum to
//    the per-triangle total;
//  - per-phase fields add up to the total; Finnie wear vanishes at normal incidence and for
//    receding particles and scales with k_finnie.
#include "dem_test_helpers.h"

#include <abrade/dem/wear.h>

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material steel = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, false);
  constexpr double R = 0.05, W = 1e-12, g = 9.81;

  Material block_material() // a 1 kg sphere of radius 5 cm
  {
    return Material::from_shear_modulus("block", 1e9, 0.25, 1.0 / (4.0 / 3.0 * M_PI * R * R * R), false);
  }

  struct Setup
  {
    Simulation                    sim;
    std::shared_ptr<WearRecorder> wear;
  };

  /// A sphere resting (at its equilibrium overlap) on @p mesh, moving at v0 along x.
  std::unique_ptr<Setup> sliding(const TriangleMesh &mesh, double friction, double v0, const Vec3 &start,
                                 WallWearLaws laws = {make_wear_law("archard", {{"Coefficient", W}}),
                                                      make_wear_law("relative", {})})
  {
    auto s = std::make_unique<Setup>(Setup{Simulation(quiet_settings(1e-4, true)), nullptr});
    const Material b  = block_material();
    const int      mb = s->sim.add_material(b), mw = s->sim.add_material(steel);
    s->sim.set_interaction(mb, mw, {0.5, friction, 0.0});
    Wall w;
    w.name = "plate", w.mesh = mesh, w.material = mw;
    s->sim.add_wall(w);
    const double m     = sphere_mass(R, b.density);
    const double delta = std::pow(m * g / (4.0 / 3.0 * e_star(b, steel) * std::sqrt(R)), 2.0 / 3.0);
    s->sim.particles().add(0, start[0], start[1], R - delta, R, b.density, mb);
    s->sim.particles().vx[0] = v0;
    s->sim.setup();
    s->wear = std::make_shared<WearRecorder>(s->sim, std::vector<WallWearLaws>{laws});
    s->sim.add_hook(s->wear);
    return s;
  }

  TriangleMesh one_triangle(double size)
  {
    TriangleMesh m;
    m.vertices  = {Vec3(-size, -size, 0), Vec3(size, -size, 0), Vec3(0, size, 0)};
    m.triangles = {{0, 1, 2}};
    return m;
  }
} // namespace

TEST(Archard, ConstantSpeedSlidingOnOneTriangleIsExact)
{
  auto         s = sliding(one_triangle(10), 0.0, 1.0, Vec3(-2, -1, 0));
  const double T = 1.0;
  s->sim.run_phase("slide", T);
  const double m = s->sim.particles().mass[0];
  EXPECT_NEAR(m, 1.0, 1e-12);
  const double expected = W * m * g * 1.0 * T; // 9.81e-12 m^3
  EXPECT_NEAR(s->wear->total(0, "archard_volume") / expected, 1, 1e-9);
  EXPECT_NEAR(s->wear->depth(0, "archard_volume")[0] / (expected / 200.0), 1, 1e-9); // area 200 m^2
}

TEST(Archard, ConstantSpeedSlidingOverManyTrianglesConservesVolume)
{
  // 5 cm triangles: the sphere crosses faces, edges and vertices; y = 0 runs along edges
  for (double y : {0.0, 0.0123})
    {
      auto s = sliding(primitives::plate(Vec3::Zero(), 2, 4, 4, 0.05), 0.0, 1.0, Vec3(-1, y, 0));
      s->sim.run_phase("slide", 1.0);
      const double expected = W * s->sim.particles().mass[0] * g;
      EXPECT_NEAR(s->wear->total(0, "archard_volume") / expected, 1, 1e-9) << "y = " << y;
      int touched = 0;
      for (double q : s->wear->values(0, "archard_volume"))
        touched += q > 0;
      EXPECT_GT(touched, 20);
    }
}

TEST(Archard, VertexValuesAreTheBarycentricWeightsOfTheContactPoints)
{
  auto         s = sliding(one_triangle(10), 0.0, 1.0, Vec3(-2, -1, 0));
  s->sim.run_phase("slide", 1.0); // from x = -2 to x = -1 at y = -1
  const double Q = W * s->sim.particles().mass[0] * g;
  // barycentric weights of the path's midpoint (-1.5, -1) in (-10,-10), (10,-10), (0,10)
  const double l2 = (-1.0 + 10) / 20;            // weight of (0, 10): y from -10 to 10
  const double l1 = (-1.5 + 10 - 10 * l2) / 20;  // x = -10 + 20 l1 + 10 l2
  const double l0 = 1 - l1 - l2;
  const auto   q  = s->wear->vertex_values(0, "archard_volume");
  ASSERT_EQ(q.size(), 3u);
  // (the contact point is sampled once per step: the samples' mean lies up to half a step's
  // travel, 5e-5 m, from the midpoint, 1.3e-5 of l1)
  EXPECT_NEAR(q[0] / (l0 * Q), 1, 1e-4);
  EXPECT_NEAR(q[1] / (l1 * Q), 1, 1e-4);
  EXPECT_NEAR(q[2] / (l2 * Q), 1, 1e-4);
  // a third each, as the volume once went to the vertices, is far from it
  EXPECT_GT(std::abs(l1 - 1.0 / 3), 0.1);
}

TEST(Archard, VertexValuesConserveTheVolumeOverManyTriangles)
{
  auto s = sliding(primitives::plate(Vec3::Zero(), 2, 4, 4, 0.05), 0.0, 1.0, Vec3(-1, 0.0123, 0));
  s->sim.run_phase("slide", 1.0);
  double sum = 0;
  for (double q : s->wear->vertex_values(0, "archard_volume"))
    sum += q;
  EXPECT_NEAR(sum / s->wear->total(0, "archard_volume"), 1, 1e-12);
}

TEST(Archard, EdgeContactIsSplitEqually)
{
  // sliding exactly along the edge y = 0 shared by two triangles
  TriangleMesh plate;
  plate.vertices  = {Vec3(-5, 0, 0), Vec3(0, -5, 0), Vec3(5, 0, 0), Vec3(0, 5, 0)};
  plate.triangles = {{0, 1, 2}, {0, 2, 3}};
  auto s          = sliding(plate, 0.0, 1.0, Vec3(-1, 0, 0));
  s->sim.run_phase("slide", 1.0);
  const auto q = s->wear->values(0, "archard_volume");
  EXPECT_NEAR(q[0] + q[1], W * g, 1e-9 * W * g);
  EXPECT_NEAR(q[0] / q[1], 1, 1e-6);
}

TEST(Archard, DeceleratingSphereAndFrictionEnergy)
{
  const double mu = 0.3, v0 = 2.0;
  auto         s  = sliding(one_triangle(20), mu, v0, Vec3(-3, -2, 0));
  s->sim.run_phase("slide", v0 / (mu * g) + 0.2); // stops after v0 / (mu g) = 0.68 s
  const double m = s->sim.particles().mass[0];
  EXPECT_NEAR(s->sim.particles().vx[0], 0, 1e-4);
  EXPECT_NEAR(s->wear->total(0, "archard_volume") / (W * m * v0 * v0 / (2 * mu)), 1, 1e-3);
  EXPECT_NEAR(s->wear->total(0, "relative_tangential_energy") / (0.5 * m * v0 * v0), 1, 1e-3);
  EXPECT_LT(s->wear->total(0, "relative_normal_energy"), 1e-6 * 0.5 * m * v0 * v0);
}

TEST(Archard, PhasesAddUpToTheTotal)
{
  auto s = sliding(one_triangle(10), 0.0, 1.0, Vec3(-2, -1, 0));
  s->sim.run_phase("first", 0.3);
  s->sim.run_phase("second", 0.5);
  const double a = s->wear->total(0, "archard_volume", "first");
  const double b = s->wear->total(0, "archard_volume", "second");
  EXPECT_NEAR(a / (W * g * 0.3), 1, 1e-9);
  EXPECT_NEAR(b / (W * g * 0.5), 1, 1e-9);
  EXPECT_NEAR(s->wear->total(0, "archard_volume"), a + b, 1e-20);
  EXPECT_EQ(s->wear->phases(), (std::vector<std::string>{"first", "second"}));
}

TEST(Finnie, ZeroAtNormalIncidenceAndForRecedingParticlesLinearInK)
{
  auto impact = [](double angle_deg, double k) {
    Simulation     sim(quiet_settings(2e-6));
    const Material b  = block_material();
    const int      mb = sim.add_material(b), mw = sim.add_material(steel);
    sim.set_interaction(mb, mw, {0.5, 0.3, 0.0});
    Wall w;
    w.name = "plate", w.mesh = one_triangle(10), w.material = mw;
    sim.add_wall(w);
    sim.particles().add(0, 0, -1, R + 1e-6, R, b.density, mb);
    const double th = angle_deg * M_PI / 180;
    sim.particles().vx[0] = 2 * std::sin(th), sim.particles().vz[0] = -2 * std::cos(th);
    sim.setup();
    auto wear = std::make_shared<WearRecorder>(sim, std::vector<WallWearLaws>{{make_wear_law("finnie", {{"Coefficient", k}})}});
    sim.add_hook(wear);
    sim.run_phase("impact", 0.01);
    return wear->total(0, "finnie_wear");
  };
  const double a = impact(70, 1), b = impact(70, 2.5);
  EXPECT_GT(a, 0);
  // head-on: f(90 deg) = cos^2/3 = 0 (up to round-off in the angle), and it rebounds straight
  EXPECT_LT(impact(0, 1), 1e-12 * a);
  EXPECT_NEAR(b / a, 2.5, 1e-12);
}
