// Hertz impact against its analytic solution and Chung & Ooi (2011) tests 1 and 2
// (shared/reference/verification.md): peak overlap and force within 0.1 %, contact time within
// 0.1 %, rebound speed within 1e-4 (e = 1, dt = t_c / 100), and the published values to the
// digits they are given in.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  struct Result
  {
    ImpactRecorder rec;
    double         rebound_speed;
  };

  // Two identical spheres approaching head-on at +-v/2.
  Result sphere_sphere(const Material &mat, double R, double v, double dt)
  {
    Simulation sim(quiet_settings(dt));
    const int  m = sim.add_material(mat);
    sim.set_interaction(m, m, {1.0, 0.0, 0.0});
    auto &P = sim.particles();
    P.add(0, -R - 1e-6, 0, 0, R, mat.density, m);
    P.add(1, R + 1e-6, 0, 0, R, mat.density, m);
    P.vx[0] = v / 2, P.vx[1] = -v / 2;
    sim.setup();
    Result r;
    r.rec.record(0, -2e-6, 0);
    for (int s = 0; s < 100000 && (r.rec.t_end < 0); ++s)
      {
        sim.step();
        const auto   i = index_of(sim, 0), j = index_of(sim, 1);
        const double overlap = 2 * R - std::abs(sim.particles().x[j] - sim.particles().x[i]);
        r.rec.record(sim.time(), overlap, std::abs(sim.particles().fx[i]));
      }
    const auto i = index_of(sim, 0), j = index_of(sim, 1);
    r.rebound_speed = sim.particles().vx[j] - sim.particles().vx[i];
    return r;
  }

  // A sphere falling at v onto a wall (rigid when the wall's E is huge).
  Result sphere_wall(const Material &sphere, const Material &wall, double R, double v, double dt)
  {
    Simulation sim(quiet_settings(dt));
    const int  ms = sim.add_material(sphere), mw = sim.add_material(wall);
    sim.set_interaction(ms, mw, {1.0, 0.0, 0.0});
    sim.add_wall(floor_wall(mw, 20 * R));
    auto &P = sim.particles();
    P.add(0, 0, 0, R + 1e-7, R, sphere.density, ms);
    P.vz[0] = -v;
    sim.setup();
    Result r;
    r.rec.record(0, -1e-7, 0);
    for (int s = 0; s < 100000 && (r.rec.t_end < 0); ++s)
      {
        sim.step();
        r.rec.record(sim.time(), R - sim.particles().z[0], std::abs(sim.particles().fz[0]));
      }
    r.rebound_speed = sim.particles().vz[0];
    return r;
  }
} // namespace

namespace
{
  /// A material and Chung & Ooi's published peak overlap [um], peak force [kN], contact time [us].
  struct Case
  {
    Material mat;
    double   delta_um, force_kn, tc_us;
  };

  /// Analytic values within 0.1 % (rebound 1e-4); published values to their 4 digits.
  void expect_matches(const Result &r, const HertzImpact &a, double v, const Case &c)
  {
    EXPECT_NEAR(r.rec.max_overlap / a.delta_max, 1, 1e-3);
    EXPECT_NEAR(r.rec.max_force / a.force_max, 1, 1e-3);
    EXPECT_NEAR(r.rec.contact_time() / a.contact_time, 1, 1e-3);
    EXPECT_NEAR(r.rebound_speed / v, 1, 1e-4);
    EXPECT_NEAR(r.rec.max_overlap * 1e6 / c.delta_um, 1, 2e-3);
    EXPECT_NEAR(r.rec.max_force * 1e-3 / c.force_kn, 1, 5e-3);
    EXPECT_NEAR(r.rec.contact_time() * 1e6 / c.tc_us, 1, 2e-3);
  }
} // namespace

TEST(HertzImpact, SphereSphereMatchesAnalyticAndChungOoiTest1)
{
  const Case cases[] = {{{"glass", 48e9, 0.20, 2800}, 274.1, 10.70, 40.34},
                        {{"limestone", 20e9, 0.25, 2500}, 368.3, 7.11, 54.20}};
  for (const auto &c : cases)
    {
      const double R = 0.01, v = 20; // +-10 m/s
      const double m = sphere_mass(R, c.mat.density);
      const HertzImpact a(m / 2, R / 2, e_star(c.mat, c.mat), v);
      const Result      r = sphere_sphere(c.mat, R, v, a.contact_time / 100);
      SCOPED_TRACE(c.mat.name);
      expect_matches(r, a, v, c);
    }
}

TEST(HertzImpact, SphereOnRigidPlaneMatchesChungOoiTest2)
{
  const Case     cases[] = {{{"aluminium alloy", 70e9, 0.30, 2700}, 49.72, 11.37, 731.7},
                            {{"magnesium alloy", 40e9, 0.35, 1800}, 52.12, 7.23, 767.1}};
  const Material rigid{"rigid", 1e30, 0.3, 7800};
  for (const auto &c : cases)
    {
      const double R = 0.1, v = 0.2;
      const double m = sphere_mass(R, c.mat.density);
      const HertzImpact a(m, R, e_star(c.mat, rigid), v);
      const Result      r = sphere_wall(c.mat, rigid, R, v, a.contact_time / 100);
      SCOPED_TRACE(c.mat.name);
      expect_matches(r, a, v, c);
    }
}

TEST(HertzImpact, EnergyIsConservedAtPeakOverlap)
{
  // 1/2 m* v^2 = 2/5 F_max delta_max
  const Material glass{"glass", 48e9, 0.20, 2800};
  const double   R = 0.01, v = 20, m = sphere_mass(R, glass.density);
  const HertzImpact a(m / 2, R / 2, e_star(glass, glass), v);
  const Result      r = sphere_sphere(glass, R, v, a.contact_time / 200);
  EXPECT_NEAR(0.4 * r.rec.max_force * r.rec.max_overlap / (0.5 * m / 2 * v * v), 1, 1e-3);
}
