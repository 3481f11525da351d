// The wear-law plugins (dem/wear_law.h):
//  - Oka's erosion law against its formula (Oka et al. 2005), written out here independently of
//    the plugin, for single impacts of a sphere on a plate over angles and speeds (1e-6): the
//    volume is recorded once per impact, with the launch velocity (no gravity, so the velocity
//    at the first contact step is the launch velocity exactly), however the sphere rebounds;
//  - a coarse-grained particle (factor f) erodes with its real diameter 2 r / f;
//  - the registry: every law has fields, parameters and a unique name; an unknown name is an
//    input error that names the allowed ones.
#include "dem_test_helpers.h"

#include <abrade/common/error.h>
#include <abrade/dem/wear.h>

#include <gtest/gtest.h>

#include <set>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  constexpr double R = 0.01, rho = 3700;

  struct Impact
  {
    double volume;   ///< recorded
    double expected; ///< Oka's formula at the launch velocity
  };

  /// A sphere launched at @p speed and @p angle_deg to a plate made of @p n x @p n squares.
  Impact oka_impact(double speed, double angle_deg, double coarse_graining = 1, int n = 1)
  {
    const double e90 = 2e-8, hv = 1.3, n1 = 0.8, n2 = 1.5, k2 = 2.4, k3 = 0.2, v_ref = 104, d_ref = 326e-6;
    Simulation   sim(quiet_settings(2e-6));
    const int    mp = sim.add_material({"ore", 2.5e8, 0.25, rho, false});
    const int    mw = sim.add_material({"steel", 2e11, 0.3, 7800, false});
    sim.set_interaction(mp, mw, {0.5, 0.3, 0.0});
    Wall w;
    w.name = "plate", w.material = mw;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        w.mesh.vertices.push_back(Vec3(-1 + 2.0 * i / n, -1 + 2.0 * j / n, 0));
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j)
        {
          const int a = i * (n + 1) + j, b = a + n + 1;
          w.mesh.triangles.push_back({a, b, b + 1});
          w.mesh.triangles.push_back({a, b + 1, a + 1});
        }
    sim.add_wall(w);
    sim.particles().add(0, 0.013, 0.017, R + 1e-7, R, rho, mp); // (off the mesh's edges and vertices)
    const double a = angle_deg * M_PI / 180;
    sim.particles().vx[0] = speed * std::cos(a), sim.particles().vz[0] = -speed * std::sin(a);
    sim.setup();
    const double mass = sim.particles().mass[0];
    WearContext  context;
    context.coarse_graining = coarse_graining;
    auto law = make_wear_law("oka", {{"Coefficient", e90}, {"Hardness", hv}, {"n1", n1}, {"n2", n2},
                                     {"Velocity exponent", k2}, {"Size exponent", k3},
                                     {"Reference velocity", v_ref}, {"Reference diameter", d_ref}},
                             context);
    auto wear = std::make_shared<WearRecorder>(sim, std::vector<WallWearLaws>{{std::move(law)}});
    sim.add_hook(wear);
    sim.run_phase("impact", 4 * R / speed + 0.002); // through the impact and away
    EXPECT_GT(sim.particles().vz[0], 0) << "the sphere did not rebound";

    const double s        = std::sin(a);
    const double diameter = 2 * R / coarse_graining;
    const double expected = mass * e90 * std::pow(speed / v_ref, k2) * std::pow(diameter / d_ref, k3) *
                            std::pow(s, n1) * std::pow(1 + hv * (1 - s), n2);
    return {wear->total(0, "oka_volume"), expected};
  }
} // namespace

TEST(Oka, SingleImpactsFollowTheFormulaOverAnglesAndSpeeds)
{
  for (double speed : {0.5, 2.0, 8.0})
    for (double angle : {10.0, 30.0, 45.0, 60.0, 80.0, 90.0})
      {
        const Impact i = oka_impact(speed, angle);
        EXPECT_GT(i.expected, 0);
        EXPECT_NEAR(i.volume / i.expected, 1, 1e-6) << speed << " m/s at " << angle << " deg";
      }
}

TEST(Oka, OneImpactOnAFineMeshIsCountedOnce)
{
  const Impact coarse = oka_impact(3, 40, 1, 1), fine = oka_impact(3, 40, 1, 40); // 5 cm triangles
  EXPECT_NEAR(fine.volume / fine.expected, 1, 1e-6);
  EXPECT_NEAR(fine.volume / coarse.volume, 1, 1e-6);
}

// An impact is a contact whose history begins: a sphere sliding across many triangles (edges and
// vertices) keeps its one history, so it is one impact however many triangles it crosses.
TEST(Oka, SlidingAcrossTrianglesIsOneContact)
{
  struct BeganCounter : StepHook
  {
    int  began = 0;
    void after_step(const Simulation &, const ContactLog &log) override
    {
      log.for_each([&](const WallContactRecord &r) { began += r.began; });
    }
  };
  Simulation sim(quiet_settings(1e-5, true));
  const int  mp = sim.add_material({"ore", 2.5e8, 0.25, rho, false});
  const int  mw = sim.add_material({"steel", 2e11, 0.3, 7800, false});
  sim.set_interaction(mp, mw, {0.5, 0.05, 0.0});
  sim.add_wall(floor_wall(mw, 2.0, 0.05)); // 5 cm triangles
  sim.particles().add(0, -0.5, 0.013, R * 0.999, R, rho, mp);
  sim.particles().vx[0] = 1;
  sim.setup();
  auto counter = std::make_shared<BeganCounter>();
  sim.add_hook(counter);
  const double x0 = sim.particles().x[0];
  sim.run_phase("slide", 0.5);
  EXPECT_GT(sim.particles().x[0] - x0, 0.3); // across several triangles
  EXPECT_EQ(counter->began, 1);
}

TEST(Oka, CoarseGrainedParticlesErodeWithTheirRealSize)
{
  const Impact real = oka_impact(3, 40, 1), coarse = oka_impact(3, 40, 2.5);
  EXPECT_NEAR(coarse.volume / coarse.expected, 1, 1e-6);
  EXPECT_NEAR(coarse.volume / real.volume, std::pow(1 / 2.5, 0.2), 1e-6); // (D / D_ref)^k3 with D = 2 r / f
}

TEST(WearLawRegistry, EveryLawHasANameFieldsAndParameters)
{
  std::set<std::string> names, fields;
  for (const auto &law : registered_wear_laws())
    {
      EXPECT_TRUE(names.insert(law->name()).second) << law->name() << " registered twice";
      EXPECT_FALSE(law->documentation().empty());
      EXPECT_FALSE(law->fields().empty());
      for (const auto &f : law->fields())
        {
          EXPECT_TRUE(fields.insert(f.name).second) << "field " << f.name << " recorded by two laws";
          EXPECT_EQ(wear_law_of_field(f.name), law.get());
        }
      EXPECT_EQ(make_wear_law(law->name(), {})->name(), law->name());
    }
  for (const char *law : {"archard", "relative", "finnie", "oka"}) // (and any added since)
    EXPECT_EQ(names.count(law), 1u) << law;
  EXPECT_EQ(wear_law_of_field("archard_volume")->coefficient_name(), "Coefficient");
  EXPECT_EQ(registered_wear_laws()[0]->fields()[0].depth_name(), "archard_depth");
}

TEST(WearLawRegistry, UnknownNamesAndParametersAreInputErrors)
{
  try
    {
      make_wear_law("archad");
      FAIL() << "an unknown law was made";
    }
  catch (const abrade::InputError &e)
    {
      const std::string m = e.what();
      EXPECT_NE(m.find("'archad'"), std::string::npos) << m;
      EXPECT_NE(m.find(wear_law_names()), std::string::npos) << m;
      EXPECT_NE(m.find("oka"), std::string::npos) << m;
    }
  EXPECT_THROW(make_wear_law("archard", {{"Coeficient", 1.0}}), abrade::InputError);
  EXPECT_THROW(make_wear_law("archard", {{"Coefficient", -1.0}}), abrade::InputError);
}
