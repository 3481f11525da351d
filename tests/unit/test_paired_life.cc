// Two lives compared pair by pair on common beds (coupling/include/abrade/coupling/lifetime/paired_life.h):
//  - a run against no shared beds: the two runs' own variances added (the elasticities carry a
//    run's own variance, the place factor and the extrapolation's part included);
//  - a run against itself, and against a copy whose every rate is doubled (what doubling W
//    does): the ratio 1 and 1/2 with no width; beds that are not the same ones (other seeds)
//    are not paired;
//  - coverage through the loop's steps: two concepts on the same fresh beds every update, their
//    bed rates correlated by rho (the shared bed) and scattered by 20 %, each update sized from
//    the previous update's rate as the loop does (update_size.h), the records and life_interval
//    as the loop keeps them; over 4,000 pairs of runs the 95 % interval of L_A / L_B holds the
//    true ratio (the same runs without scatter) in 93.5-96.5 % of them: with rho = 0.8 and
//    rho = 0, reached lives and lives extrapolated past three updates, and a variant whose wear
//    slows as it wears (its elasticities unlike the baseline's). With rho = 0.8 the paired
//    interval is less than 0.6 of the two intervals combined, which hold the truth in more
//    than 99 % (too wide, the reason to pair). Broken once: with the covariance left out the
//    rho = 0.8 coverage is 99.8 % and the test fails.
#include <abrade/coupling/lifetime/life_interval.h>
#include <abrade/coupling/lifetime/paired_life.h>
#include <abrade/coupling/lifetime/update_size.h>
#include <abrade/coupling/lifetime/wear_source.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <random>

using namespace abrade::coupling;
using namespace abrade::coupling::lifetime;

namespace
{
  /// A run of the loop's steps on one place: each update's 3 beds wear at
  /// mean_rate(depth, tonnes) x factor(u, j) per tonne, 10 t a cycle, the update sized by the previous update's
  /// mean rate (a tenth of a 15 mm mesh), the depth moved by the beds' mean, to 12 mm or
  /// @p max_updates. @p factor gives bed j's factor in update u.
  template <class Rate, class Factor>
  std::vector<UpdateRecord> run(Rate mean_rate, Factor factor, long max_updates)
  {
    std::vector<UpdateRecord> records;
    double                    depth = 0, tonnes = 0, previous = mean_rate(0.0, 0.0) * 10;
    for (long u = 1; u <= max_updates && depth < 0.012; ++u)
      {
        UpdateRecord r;
        double       mean = 0;
        for (int j = 0; j < 3; ++j)
          {
            r.bed_seeds.push_back(bed_seed(j + 1, u));
            r.bed_rates.push_back(mean_rate(depth, tonnes) * 10 * factor(u, j));
            mean += r.bed_rates.back() / 3;
          }
        const long n = cycles_for_update(0, 0.1, 0.015, previous, mean);
        previous     = mean;
        depth += n * mean, tonnes += n * 10.0;
        r.tonnes = tonnes, r.value = depth, r.beds = 3, r.relative_variance = relative_variance(r.bed_rates);
        records.push_back(r);
      }
    return records;
  }


  struct Coverage
  {
    double covered = 0, combined_covered = 0, width_over_combined = 0;
  };

  enum class Course
  {
    steady,   ///< A wears at 1.2 um/t
    slowing,  ///< A at 1.6 um/t x exp(-T / 20 kt): its elasticities unlike the baseline's
    feedback, ///< A at 1.6 um/t x (1 - depth / 24 mm): the deeper, the slower (the corner rounding)
  };

  /// 4,000 pairs: variant A (@p course) against baseline B at 1 um/t; bed j's factor in update u
  /// is 1 + 0.2 (sqrt(rho) z_uj + sqrt(1 - rho) y_uj), z shared by A and B: correlated by rho.
  Coverage coverage(double rho, long max_updates, Course course)
  {
    auto rate_a = [&](double d, double t) {
      return course == Course::steady    ? 1.2e-6
             : course == Course::slowing ? 1.6e-6 * std::exp(-t / 20000)
                                         : 1.6e-6 * (1 - d / 0.024);
    };
    auto rate_b = [](double, double) { return 1e-6; };
    auto one    = [](long, int) { return 1.0; };
    auto life   = [](const std::vector<UpdateRecord> &r) { return life_interval(0.012, r).life.tonnes; };
    const double truth = life(run(rate_a, one, max_updates)) / life(run(rate_b, one, max_updates));

    std::mt19937_64                  random(17);
    std::normal_distribution<double> normal;
    Coverage                         c;
    const int                        trials = 4000;
    for (int trial = 0; trial < trials; ++trial)
      {
        double z[200][3], ya[200][3], yb[200][3];
        for (int u = 0; u < 200; ++u)
          for (int j = 0; j < 3; ++j)
            z[u][j] = normal(random), ya[u][j] = normal(random), yb[u][j] = normal(random);
        const double w = std::sqrt(rho), s = std::sqrt(1 - rho);
        const auto   ra = run(rate_a, [&](long u, int j) { return 1 + 0.2 * (w * z[u][j] + s * ya[u][j]); },
                            max_updates);
        const auto   rb = run(rate_b, [&](long u, int j) { return 1 + 0.2 * (w * z[u][j] + s * yb[u][j]); },
                            max_updates);
        const LifeInterval a = life_interval(0.012, ra), b = life_interval(0.012, rb);
        const PairedChange p = paired_life_change(life_beds(ra, a), life_beds(rb, b));
        c.covered += (p.low <= truth && truth <= p.high) / double(trials);
        // the two intervals combined on the log scale, as if the lives were independent
        const double h = std::hypot(0.5 * std::log(a.high / a.low), 0.5 * std::log(b.high / b.low));
        c.combined_covered += (std::abs(std::log(p.ratio / truth)) <= h) / double(trials);
        c.width_over_combined += 0.5 * std::log(p.high / p.low) / h / trials;
      }
    std::cout << "rho " << rho << (max_updates < 10 ? ", extrapolated" : ", reached")
              << (course == Course::slowing ? ", slowing" : course == Course::feedback ? ", feedback" : "")
              << ": true ratio " << truth << ", paired coverage " << 100 * c.covered << " %, combined "
              << 100 * c.combined_covered << " %, paired / combined width " << c.width_over_combined << '\n';
    return c;
  }
} // namespace

TEST(PairedLife, WithoutSharedBedsTheRunsOwnVariancesAdd)
{
  for (long max_updates : {100L, 3L})
    {
      std::mt19937_64                  random(5);
      std::normal_distribution<double> normal;
      auto       draw = [&](long, int) { return 1 + 0.2 * normal(random); };
      const auto ra   = run([](double, double) { return 1e-6; }, draw, max_updates);
      const auto rb   = run([](double, double) { return 1.3e-6; }, draw, max_updates);
      const LifeInterval a = life_interval(0.012, ra, 0.95, 0.7), b = life_interval(0.012, rb, 0.95, 0.5);
      EXPECT_EQ(a.life.reached, max_updates > 3);
      if (max_updates == 3)
        {
          EXPECT_GT(a.relative_sd_extrapolation, 0);
        }
      auto other = life_beds(rb, b);
      for (auto &u : other.updates)
        for (int &s : u.seeds)
          s += 1000;
      const PairedChange p = paired_life_change(life_beds(ra, a), other);
      EXPECT_EQ(p.pairs, 0u);
      EXPECT_NEAR(p.ratio, a.life.tonnes / b.life.tonnes, 1e-12);
      // t at the smaller of the two runs' degrees of freedom (equal here)
      const double t = student_t_quantile(0.975, std::min(a.dof, b.dof));
      EXPECT_NEAR(0.5 * std::log(p.high / p.low) / t, std::hypot(a.relative_sd, b.relative_sd), 1e-9);
    }
}

TEST(PairedLife, ARunAgainstItselfAndAgainstDoubledWearHasNoWidth)
{
  std::mt19937_64                  random(9);
  std::normal_distribution<double> normal;
  std::vector<double>              f(400);
  for (double &x : f)
    x = 1 + 0.2 * normal(random);
  auto       factor = [&](long u, int j) { return f[3 * u + j]; };
  const auto base   = run([](double, double) { return 1e-6; }, factor, 100);
  const auto twice  = run([](double, double) { return 2e-6; }, factor, 100);
  const LifeInterval b = life_interval(0.012, base), w = life_interval(0.012, twice);
  ASSERT_GT(b.relative_half_width, 0.02);
  const PairedChange self = paired_life_change(life_beds(base, b), life_beds(base, b));
  EXPECT_DOUBLE_EQ(self.ratio, 1);
  EXPECT_NEAR(self.high / self.low, 1, 1e-6); // (a difference of sums: rounding)
  EXPECT_EQ(self.pairs, 3 * base.size());
  // (not zero: each update's cycles are a whole number, so the doubled run's updates end 0.3 %
  // elsewhere)
  const PairedChange half = paired_life_change(life_beds(twice, w), life_beds(base, b));
  EXPECT_NEAR(half.ratio, 0.5, 1e-3);
  EXPECT_LT(std::log(half.high / half.low), 1e-2 * std::log(b.high / b.low));
  EXPECT_TRUE(half.significant); // (half the life: no bed scatter hides it)
  // and the table round-trips
  const std::string path = (std::filesystem::temp_directory_path() / "abrade_life_beds_test.csv").string();
  write_life_beds(path, life_beds(base, b));
  const LifeBeds back = read_life_beds(path);
  EXPECT_EQ(back.life, b.life.tonnes);
  EXPECT_EQ(back.place_factor, b.place_factor);
  ASSERT_EQ(back.updates.size(), base.size());
  for (std::size_t u = 0; u < base.size(); ++u)
    {
      EXPECT_EQ(back.updates[u].seeds, base[u].bed_seeds);
      EXPECT_EQ(back.updates[u].rates, base[u].bed_rates);
      EXPECT_EQ(back.updates[u].held, b.elasticity_held[u]);
      EXPECT_EQ(back.updates[u].free, b.elasticity_free[u]);
    }
  std::filesystem::remove(path);
}

TEST(PairedLife, CoverageOnCommonBedsThroughTheLoopsSteps)
{
  const Coverage shared = coverage(0.8, 100, Course::steady);
  EXPECT_GE(shared.covered, 0.935);
  EXPECT_LE(shared.covered, 0.965);
  EXPECT_GT(shared.combined_covered, 0.99);
  EXPECT_LT(shared.width_over_combined, 0.55); // (sqrt(1 - rho) = 0.45 expected)
  const Coverage apart = coverage(0.0, 100, Course::steady);
  EXPECT_GE(apart.covered, 0.935);
  EXPECT_LE(apart.covered, 0.965);
  const Coverage slowing = coverage(0.8, 100, Course::slowing);
  EXPECT_GE(slowing.covered, 0.935);
  EXPECT_LE(slowing.covered, 0.965);
  // wear that slows as it deepens corrects itself (a deep update is followed by slower ones),
  // which the first-order variance does not know: its interval, and a run's own, is wider than
  // it scatters (the safe side)
  const Coverage feedback = coverage(0.8, 100, Course::feedback);
  EXPECT_GE(feedback.covered, 0.935);
}

TEST(PairedLife, CoverageOfExtrapolatedLivesOnCommonBeds)
{
  for (Course course : {Course::steady, Course::slowing})
    {
      const Coverage c = coverage(0.8, 3, course);
      EXPECT_GE(c.covered, 0.935);
      EXPECT_LE(c.covered, 0.965);
    }
}
