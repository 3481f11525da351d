// The footprint fit (coupling/include/abrade/field/footprint_fit.h) on candidates whose residual
// sums of squares are known: RSS(r) = R0 (1 + (ln(r / r0) / s)^2), r0 = 12 mm, at five footprints
// 1.5 times apart around it. Checks what the interval's level RSS(r^) (1 + D F(1, nu) / (n - 2))
// promises:
//  - r^ recovers r0 within 5 % (the geometric mean of the minima of a parabola in r and one in
//    ln r: exact in ln r here, the one in r is pulled: +4.1 %) and its interval holds it;
//  - D, the best candidate's design effect, is clamped to [1, n / nu]: D = 0.3 gives the interval
//    of D = 1 and D = 1e9 that of D = n / nu, to the last bit (without the clamp they differ);
//  - the interval widens with D (1 < 4 < n / nu), and on ln r its half-width is at least the
//    parabola in ln r's, s sqrt(D t^2 / (n - 2)) (t = t(0.975, nu) = 2.306 for nu = 8), which is
//    exact here;
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
  constexpr double r0 = 0.012, R0 = 1e-8, s = 0.3;
  constexpr long   blocks = 10, n = 400; // nu = 8

  std::vector<FootprintCandidate> candidates(double design_effect, long measurements = n)
  {
    std::vector<FootprintCandidate> c;
    for (int k = -2; k <= 2; ++k)
      {
        FootprintCandidate x;
        x.r             = r0 * std::pow(1.5, k);
        const double l  = std::log(x.r / r0) / s;
        x.rss           = R0 * (1 + l * l);
        x.w             = 3e-14 * std::pow(x.r / r0, 0.9); // W rises along the ridge
        x.blocks        = blocks;
        x.measurements  = measurements;
        x.design_effect = design_effect;
        c.push_back(x);
      }
    return c;
  }

  double half_on_log(const FootprintFit &f) { return 0.5 * std::log(f.r_high / f.r_low); }
} // namespace

TEST(FootprintFit, RecoversTheFootprintAndHoldsIt)
{
  const FootprintFit f = fit_footprint(candidates(1));
  ASSERT_TRUE(f.identifiable) << f.reason;
  EXPECT_NEAR(f.r / r0, 1, 0.05);
  EXPECT_LT(f.r_low, r0);
  EXPECT_GT(f.r_high, r0);
  EXPECT_NEAR(f.dof, blocks - 2, 0);
  EXPECT_NEAR(f.dlnw_dlnr, 0.9, 0.05);
  EXPECT_NEAR(f.w / (3e-14 * std::pow(f.r / r0, 0.9)), 1, 0.02);
}

TEST(FootprintFit, DesignEffectIsClampedToOneAndToTheBlocks)
{
  const double full = double(n) / double(blocks - 2);
  const FootprintFit below = fit_footprint(candidates(0.3)), one = fit_footprint(candidates(1));
  const FootprintFit huge = fit_footprint(candidates(1e9)), all = fit_footprint(candidates(full));
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
      const FootprintFit f = fit_footprint(candidates(d));
      ASSERT_TRUE(f.identifiable) << f.reason;
      const double half = half_on_log(f);
      EXPECT_GT(half, previous) << "D = " << d;
      // the parabola in ln r is exact here: its half-width is s sqrt(ratio - 1)
      EXPECT_GE(half, s * std::sqrt(d * t * t / (n - 2)) * (1 - 1e-12)) << "D = " << d;
      previous = half;
    }
  // n unknown: the blocks are the independent measurements (level 1 + t^2 / nu), close to D = n / nu
  const FootprintFit unknown = fit_footprint(candidates(1, 0));
  ASSERT_TRUE(unknown.identifiable);
  EXPECT_NEAR(half_on_log(unknown) / previous, 1, 0.01);
}

TEST(FootprintFit, RefusesWhatCannotBeTold)
{
  auto flat = candidates(1);
  for (auto &c : flat)
    c.rss = R0;
  EXPECT_FALSE(fit_footprint(flat).identifiable);
  auto edge = candidates(1);
  edge.erase(edge.begin(), edge.begin() + 2); // the best is now the smallest
  EXPECT_FALSE(fit_footprint(edge).identifiable);
  auto two = candidates(1);
  two.resize(2);
  EXPECT_FALSE(fit_footprint(two).identifiable);
  auto few = candidates(1);
  for (auto &c : few)
    c.blocks = 2;
  EXPECT_FALSE(fit_footprint(few).identifiable);
  EXPECT_EQ(fit_footprint(few).r, r0 / 2.25); // W for the footprint assumed: the first run's
}
