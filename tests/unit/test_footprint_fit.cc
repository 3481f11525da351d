// The footprint fit (coupling/include/abrade/field/footprint_fit.h) on a profile that is known:
// RSS(r) = R0 (1 + (ln(r / r0) / s)^2) at the best W, r0 = 12 mm, W rising along the ridge as
// r^0.9, with candidates at five footprints 1.5 times apart around it. Checks what the
// interval's level RSS(r^) (1 + D F(1, nu) / (n - 2)) promises:
//  - r^ is r0 (the profile's minimum, found between the candidates: the first design's parabola
//    through the candidates' RSS put it 4 % off) and the interval holds it;
//  - D, the design effect at r^, is clamped to [1, n / nu]: D = 0.3 gives the interval of D = 1
//    and D = 1e9 that of D = n / nu, to the last bit (without the clamp they differ);
//  - the interval widens with D (1 < 4 < n / nu), and on ln r its half-width is
//    s sqrt(D t^2 / (n - 2)) (t = t(0.975, nu) = 2.306 for nu = 8);
//  - W at r^, d ln W / d ln r along the ridge, W's interval with r's uncertainty in it and the
//    joint region (its edge at the level, its centre inside);
//  - not identifiable: a flat profile (no width information), the best at the smallest
//    candidate, fewer than three footprints, too few blocks.
#include <abrade/field/footprint_fit.h>

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using abrade::field::fit_footprint;
using abrade::field::FootprintCandidate;
using abrade::field::FootprintFit;

namespace
{
  constexpr double r0 = 0.012, R0 = 1e-8, s = 0.3, w_se = 0.04;
  constexpr long   blocks = 10, n = 400; // nu = 8

  struct Known
  {
    double design_effect = 1;
    long   measurements  = n;
    bool   flat          = false;

    FootprintCandidate operator()(double r, bool, bool = true) const
    {
      FootprintCandidate x;
      x.r             = r;
      const double l  = std::log(r / r0) / s;
      x.rss           = flat ? R0 : R0 * (1 + l * l);
      x.w             = 3e-14 * std::pow(r / r0, 0.9); // W rises along the ridge
      x.blocks        = blocks;
      x.measurements  = measurements;
      x.design_effect = design_effect;
      x.relative_se   = w_se;
      x.w_dof         = 20;
      return x;
    }
  };

  std::vector<FootprintCandidate> candidates(const Known &profile)
  {
    std::vector<FootprintCandidate> c;
    for (int k = -2; k <= 2; ++k)
      c.push_back(profile(r0 * std::pow(1.5, k) * 1.1, true)); // (r0 between two of them)
    return c;
  }

  FootprintFit fit(const Known &profile) { return fit_footprint(candidates(profile), profile); }

  double half_on_log(const FootprintFit &f) { return 0.5 * std::log(f.r_high / f.r_low); }
} // namespace

TEST(FootprintFit, RecoversTheFootprintAndHoldsIt)
{
  const FootprintFit f = fit(Known{});
  ASSERT_TRUE(f.identifiable) << f.reason;
  EXPECT_NEAR(f.r / r0, 1, 1e-6);
  EXPECT_LT(f.r_low, r0);
  EXPECT_GT(f.r_high, r0);
  EXPECT_NEAR(f.dof, blocks - 2, 0);
  EXPECT_NEAR(f.dlnw_dlnr, 0.9, 1e-6);
  EXPECT_NEAR(f.w / 3e-14, 1, 1e-6);
  // W's interval: ln W^ +- sqrt((0.9 half_r)^2 + (t(0.975, 8) w_se)^2), half_r = t(0.975, 8) sd_log_r
  // here (r's interval symmetric in ln r)
  const double t = 2.306004135, half = std::hypot(0.9 * t * f.sd_log_r, t * w_se);
  EXPECT_NEAR(std::log(f.w_high / f.w), half, 1e-9);
  EXPECT_NEAR(std::log(f.w / f.w_low), half, 1e-9);
  // the joint region: its centre inside, its outline on the level (chi-square(0.95; 2)), its
  // extent along r 1.25 times r's interval (sqrt(5.991) / 1.96), along W given r 1.25 times
  // W's interval given r (t(0.975, 8) w_se)
  EXPECT_NEAR(f.joint_level, 5.991465, 1e-5);
  EXPECT_NEAR(f.joint_sd_w * 1.959964, t * w_se, 1e-9);
  EXPECT_NEAR(abrade::field::joint_distance(f, f.r_high, f.w * std::pow(f.r_high / f.r, 0.9)), 1.959964 * 1.959964, 1e-6);
  EXPECT_NEAR(abrade::field::joint_distance(f, f.r, f.w * std::exp(t * w_se)), 1.959964 * 1.959964, 1e-6);
  EXPECT_EQ(abrade::field::joint_distance(f, f.r, f.w), 0);
  for (const auto &p : abrade::field::joint_region_outline(f, 12))
    EXPECT_NEAR(abrade::field::joint_distance(f, p[0], p[1]), f.joint_level, 1e-9);
  // a point on the ridge at r's interval's end is inside (the region reaches further along it)
  EXPECT_LT(abrade::field::joint_distance(f, f.r_high, f.w * std::pow(f.r_high / f.r, 0.9)), f.joint_level);
}

TEST(FootprintFit, DesignEffectIsClampedToOneAndToTheBlocks)
{
  const double       full  = double(n) / double(blocks - 2);
  const FootprintFit below = fit(Known{0.3}), one = fit(Known{1});
  const FootprintFit huge = fit(Known{1e9}), all = fit(Known{full});
  ASSERT_TRUE(below.identifiable && one.identifiable && huge.identifiable && all.identifiable);
  EXPECT_EQ(below.r_low, one.r_low);
  EXPECT_EQ(below.r_high, one.r_high);
  EXPECT_EQ(huge.r_low, all.r_low);
  EXPECT_EQ(huge.r_high, all.r_high);
}

TEST(FootprintFit, IntervalWidensWithTheDesignEffect)
{
  const double t = 2.306004135; // t(0.975, 8)
  double       previous = 0;
  for (const double d : {1.0, 4.0, double(n) / double(blocks - 2)})
    {
      const FootprintFit f = fit(Known{d});
      ASSERT_TRUE(f.identifiable) << f.reason;
      const double half = half_on_log(f);
      EXPECT_GT(half, previous) << "D = " << d;
      EXPECT_NEAR(half, s * std::sqrt(d * t * t / (n - 2)), 1e-6) << "D = " << d;
      previous = half;
    }
  // n unknown: the blocks are the independent measurements (level 1 + t^2 / nu), close to D = n / nu
  const FootprintFit unknown = fit(Known{1, 0});
  ASSERT_TRUE(unknown.identifiable);
  EXPECT_NEAR(half_on_log(unknown) / previous, 1, 0.01);
}

TEST(FootprintFit, RefusesWhatCannotBeTold)
{
  const Known flat{1, n, true};
  EXPECT_FALSE(fit(flat).identifiable);
  const Known known;
  auto        edge = candidates(known);
  edge.erase(edge.begin(), edge.begin() + 2); // the best is now the smallest
  EXPECT_FALSE(fit_footprint(edge, known).identifiable);
  auto two = candidates(known);
  two.resize(2);
  EXPECT_FALSE(fit_footprint(two, known).identifiable);
  auto few = candidates(known);
  for (auto &c : few)
    c.blocks = 2;
  const FootprintFit f = fit_footprint(few, known);
  EXPECT_FALSE(f.identifiable);
  EXPECT_EQ(f.r, r0 / 2.25 * 1.1); // W for the footprint assumed: the first run's
  // a profile that rises on one side only: not identifiable, W for the first run's footprint
  auto one_sided = [&](double r, bool full, bool) {
    FootprintCandidate x = known(r, full, true);
    if (r > r0)
      x.rss = R0;
    return x;
  };
  auto c = candidates(known);
  for (auto &x : c)
    x = one_sided(x.r, true, true);
  c[3].rss *= 1.0001; // (the best is not at the end)
  c[4].rss *= 1.0002;
  const FootprintFit g = fit_footprint(c, one_sided);
  EXPECT_FALSE(g.identifiable) << g.r_low << " " << g.r_high;
  EXPECT_EQ(g.r, r0 / 2.25 * 1.1);
}
