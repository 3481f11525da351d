// The predicted life and its interval (coupling/include/abrade/coupling/lifetime/life_interval.h):
//  - the life on a trajectory: a crossing inside an update is linear in it; past the run a power
//    law through the last point, exact for power-law wear; one update extrapolates its rate;
//  - the variance carried by the gradient equals the closed form of a crossing (d L / d dQ_u);
//  - coverage through the loop's own steps: the analytic source (fresh beds each update, a
//    known lognormal scatter of 10 % and of 30 %), depth_rates, the loop's update size (from
//    the previous update's rate), the records and life_interval, 4,000 runs each of a life
//    reached within the run and of one extrapolated past three updates: the 95 % interval holds
//    the true life in 93.5-96.5 % of them (more than 4 binomial standard deviations), on both
//    sides (a life reached under 30 % scatter: 93.1 %, at least 92 % asked; the skew's share);
//    the median life is unbiased (within 1 %; sized by its own beds an update biased it long by
//    c^2 / beds, and covered 90.6 %);
//  - beds reused at every update (what the loop did before) are over-confident: the same
//    arithmetic on them covers far less than 95 % (the reason every update draws fresh beds).
#include <abrade/coupling/lifetime/end_of_life.h>
#include <abrade/coupling/lifetime/life_interval.h>
#include <abrade/coupling/lifetime/place_scatter.h>
#include <abrade/coupling/lifetime/update_size.h>
#include <abrade/coupling/lifetime/wear_rates.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/part_boundary.h>

#include <gtest/gtest.h>

#include <cmath>
#include <algorithm>
#include <iostream>
#include <numeric>
#include <random>
#include <set>

using namespace abrade;
using namespace abrade::coupling::lifetime;

TEST(LifeOnTrajectory, CrossingPowerLawAndOneUpdate)
{
  // reached: linear inside the update that crosses
  LifeOnTrajectory l = life_from_trajectory({1000, 2000, 3000}, {0.004, 0.010, 0.013}, 0.012);
  EXPECT_TRUE(l.reached);
  EXPECT_EQ(l.update, 3);
  EXPECT_NEAR(l.tonnes, 2000 + 1000 * 2.0 / 3.0, 1e-9);
  // past the run: Q = 1e-5 T^0.7 sampled at the updates is extrapolated exactly
  std::vector<double> t = {500, 1000, 1500, 2000}, q;
  for (double x : t)
    q.push_back(1e-5 * std::pow(x, 0.7));
  l = life_from_trajectory(t, q, 0.012);
  EXPECT_FALSE(l.reached);
  EXPECT_NEAR(l.exponent, 0.7, 1e-12);
  EXPECT_NEAR(l.tonnes, std::pow(0.012 / 1e-5, 1 / 0.7), 1e-6);
  // one update: its rate
  l = life_from_trajectory({1500}, {0.003}, 0.012);
  EXPECT_NEAR(l.tonnes, 6000, 1e-9);
  // nothing grows: no life
  EXPECT_EQ(life_from_trajectory({1500}, {0.0}, 0.012).tonnes, 0);
}

TEST(LifeInterval, PooledVarianceAndNoIntervalFromOneBed)
{
  EXPECT_NEAR(student_t_quantile(0.975, 2), 4.302652730, 1e-8);
  EXPECT_NEAR(relative_variance({0.9, 1.0, 1.1}), 0.01, 1e-15);
  EXPECT_NEAR(relative_variance({0.0, 1.0, 2.0}), 1.0, 1e-15);
  EXPECT_EQ(relative_variance({0.0, 0.0}), -1); // no wear at the place: left out of the pool
  // (2 x 0.01 + 1 x 0.04) / 3
  const auto [c2, dof] = pooled_relative_variance({{1000, 0.004, 3, 0.01}, {2000, 0.008, 2, 0.04}, {3000, 0.012, 1, 0}});
  EXPECT_NEAR(c2, 0.06 / 3, 1e-15);
  EXPECT_EQ(dof, 3);
  const LifeInterval one = life_interval(0.012, {{1000, 0.004, 1, 0}, {2000, 0.008, 1, 0}});
  EXPECT_NEAR(one.life.tonnes, 3000, 1e-9);
  EXPECT_EQ(one.dof, 0);
  EXPECT_EQ(one.low, 0);
  EXPECT_EQ(one.high, 0);
}

// A crossing inside update k: L = T_{k-1} + dT_k (limit - Q_{k-1}) / dQ_k, so dL/d dQ_j =
// -dT_k / dQ_k for j < k and -phi dT_k / dQ_k for j = k (phi: the fraction of update k used).
TEST(LifeInterval, GradientVarianceIsTheCrossingsClosedForm)
{
  const std::vector<UpdateRecord> u = {{1000, 0.003, 3, 0.02}, {2000, 0.0075, 4, 0.05}, {3500, 0.0135, 3, 0.03}};
  const LifeInterval              li = life_interval(0.012, u);
  ASSERT_TRUE(li.life.reached);
  const double phi = (0.012 - 0.0075) / 0.006, slope = 0.006 / 1500;
  const double c2  = (2 * 0.02 + 3 * 0.05 + 2 * 0.03) / 7;
  const double var = c2 / (slope * slope) * (0.003 * 0.003 / 3 + 0.0045 * 0.0045 / 4 + phi * phi * 0.006 * 0.006 / 3);
  EXPECT_NEAR(li.life.tonnes, 2000 + phi * 1500, 1e-9);
  EXPECT_NEAR(li.relative_sd, std::sqrt(var) / li.life.tonnes, 1e-6 * li.relative_sd);
  EXPECT_NEAR(li.relative_sd_extrapolation, 0, 1e-9);
  EXPECT_EQ(li.dof, 7);
  const double t = student_t_quantile(0.975, 7);
  EXPECT_NEAR(li.low, li.life.tonnes * std::exp(-t * li.relative_sd), 1e-6);
  EXPECT_NEAR(li.high, li.life.tonnes * std::exp(t * li.relative_sd), 1e-6);
}

namespace
{
  /// Runs of the loop's own steps on a flat 1 m^2 wearable square worn at 1 um/t, 10 t a cycle,
  /// 3 beds an update scattered by @p scatter: the true life to 12 mm is 12,000 t. Each update
  /// draws fresh beds (or, with @p reuse, the run's first beds again), chooses its cycles as the
  /// loop does (a tenth of a 15 mm mesh at the previous update's rate), moves the depth by the
  /// beds' mean and records it; the run stops at @p max_updates. Returns the fraction of
  /// @p trials whose interval holds the truth, the misses on each side, and the median life.
  struct Coverage
  {
    double covered = 0, median_life = 0;
    int    truth_below = 0, truth_above = 0, reached = 0;
  };

  Coverage coverage(int trials, long max_updates, bool reuse, double scatter = 0.1)
  {
    fem::SolidSurface square;
    square.vertices    = {dealii::Point<3>(0, 0, 0), dealii::Point<3>(1, 0, 0), dealii::Point<3>(1, 1, 0),
                          dealii::Point<3>(0, 1, 0)};
    square.triangles   = {{0, 1, 2}, {0, 2, 3}};
    square.boundary_id = {fem::wearable_boundary, fem::wearable_boundary};
    auto     source    = make_analytic_wear_source("1e-6", 10, scatter);
    std::vector<double> lives;
    Coverage c;
    int      hits = 0;
    for (int trial = 0; trial < trials; ++trial)
      {
        const std::vector<int>    seeds = {3 * trial + 1, 3 * trial + 2, 3 * trial + 3};
        std::vector<UpdateRecord> records;
        double                    depth = 0, tonnes = 0, previous = 0;
        { // the pilot cycle on beds of its own sizes the first update
          std::vector<int> pilot;
          for (int s : seeds)
            pilot.push_back(bed_seed(s, 0));
          previous = depth_rates(square, source->cycle(square, 0, pilot), 0.0).largest;
        }
        for (long update = 1; update <= max_updates && depth < 0.012; ++update)
          {
            std::vector<int> beds;
            for (int s : seeds)
              beds.push_back(bed_seed(s, reuse ? 1 : update));
            const Rates r = depth_rates(square, source->cycle(square, tonnes, beds), 0.0);
            const long  n = cycles_for_update(0, 0.1, 0.015, previous, r.largest);
            previous      = r.largest;
            std::vector<double> at_place;
            for (const auto &bed : r.seed)
              at_place.push_back(bed[0]);
            depth += n * r.mean[0], tonnes += n * 10.0;
            records.push_back({tonnes, depth, beds.size(), relative_variance(at_place)});
          }
        const LifeInterval li = life_interval(0.012, records);
        c.reached += li.life.reached;
        lives.push_back(li.life.tonnes);
        hits += li.low <= 12000 && 12000 <= li.high;
        c.truth_below += 12000 < li.low;
        c.truth_above += 12000 > li.high;
      }
    c.covered = double(hits) / trials;
    std::nth_element(lives.begin(), lives.begin() + trials / 2, lives.end());
    c.median_life = lives[trials / 2];
    return c;
  }
} // namespace

// 4,000 runs: the binomial standard deviation of a 95 % coverage is 0.34 %; 93.5-96.5 % is
// more than 4 of them, and fails a 90 % interval or t with the beds' count as the degrees of
// freedom of one update.
TEST(LifeInterval, CoverageOfReachedLivesThroughTheLoopsSteps)
{
  for (double scatter : {0.1, 0.3})
    {
      const Coverage c = coverage(4000, 100, false, scatter);
      std::cout << "reached, scatter " << scatter << ": coverage " << 100 * c.covered << " %, truth below "
                << c.truth_below << ", above " << c.truth_above << ", median life " << c.median_life << " t\n";
      EXPECT_EQ(c.reached, 4000);
      // (30 %: 93.1 % measured; the skewed scatter's low bed means come with low sample
      // variances, the interval is then too narrow on the long side: 201 misses there, 76 on the
      // other; sized by its own beds an update covered 90.6 %)
      EXPECT_GE(c.covered, scatter < 0.2 ? 0.935 : 0.92);
      EXPECT_LE(c.covered, 0.965);
      EXPECT_GT(c.truth_below, 40);
      EXPECT_GT(c.truth_above, 40);
      EXPECT_NEAR(c.median_life / 12000, 1, 0.01);
    }
}

TEST(LifeInterval, CoverageOfExtrapolatedLivesThroughTheLoopsSteps)
{
  for (double scatter : {0.1, 0.3})
    {
      const Coverage c = coverage(4000, 3, false, scatter);
      std::cout << "extrapolated from three updates, scatter " << scatter << ": coverage " << 100 * c.covered
                << " %, truth below " << c.truth_below << ", above " << c.truth_above << ", median life "
                << c.median_life << " t\n";
      EXPECT_EQ(c.reached, 0);
      EXPECT_GE(c.covered, 0.935);
      EXPECT_LE(c.covered, 0.965);
      EXPECT_GT(c.truth_below, 40);
      EXPECT_GT(c.truth_above, 40);
      EXPECT_NEAR(c.median_life / 12000, 1, 0.04); // (+0.5 % and +2.8 % measured: a fitted exponent)
    }
}

// The beds settled once and reused at every update (the loop before): the updates' scatter is
// the same draw again, the pooled degrees of freedom count it many times, and the interval is
// too narrow.
TEST(LifeInterval, BedsReusedAtEveryUpdateAreOverConfident)
{
  const Coverage c = coverage(2000, 100, true);
  std::cout << "beds reused: coverage " << 100 * c.covered << " %\n";
  EXPECT_LT(c.covered, 0.85);
}

namespace
{
  /// The deepest of many places (issue 33's DEM benchmark: the stated standard deviation was
  /// twice the disjoint groups' own). @p places places wear at 1 um/t less 0.5 % per place (the
  /// edge's nearly equal vertices), each bed scattering each place independently (lognormal,
  /// relative sd 40 %: one DEM bed at a vertex); 3 beds an update, sized as the loop sizes it;
  /// the record is the deepest place's depth and the beds' relative variance at that place (the
  /// loop's add_update_records). Returns the ratio of the lives' real relative standard
  /// deviation over the trials to the stated one (rms of relative_sd).
  struct Spread
  {
    double at_one_place = 0; ///< real / stated with the leading place's scatter alone
    double worst_of_many = 0; ///< real / stated with the factor of place_scatter.h
    double factor = 0;        ///< the mean phi
  };
  Spread spread_ratio(int places, int trials = 3000, double leader = 0, double correlation = 0, int updates = 40)
  {
    std::mt19937_64                  random(42);
    std::normal_distribution<double> normal;
    const double                     sigma = std::sqrt(std::log(1 + 0.4 * 0.4));
    std::vector<double>              lives;
    double                           stated = 0, stated_many = 0, factors = 0;
    for (int trial = 0; trial < trials; ++trial)
      {
        std::vector<double>       depth(places, 0.0);
        std::vector<UpdateRecord> records;
        PlaceScatter              scatter;
        double                    tonnes = 0, previous = 1e-5;
        for (int update = 1; update <= updates && *std::max_element(depth.begin(), depth.end()) < 0.012; ++update)
          {
            std::vector<std::vector<double>> bed(3, std::vector<double>(places));
            std::vector<double>              mean(places, 0.0);
            for (auto &b : bed)
              {
                double z = normal(random);
                for (int j = 0; j < places; ++j)
                  {
                    // (neighbouring places correlated: an AR(1) chain along them)
                    if (j > 0)
                      z = correlation * z + std::sqrt(1 - correlation * correlation) * normal(random);
                    b[j] = 1e-5 * (j == 0 ? 1 + leader : 1 - 0.005 * j) * std::exp(sigma * z - sigma * sigma / 2);
                    mean[j] += b[j] / 3;
                  }
              }
            const long n = cycles_for_update(0, 0.1, 0.015, previous, *std::max_element(mean.begin(), mean.end()));
            previous     = *std::max_element(mean.begin(), mean.end());
            std::vector<double> increment(places);
            for (int j = 0; j < places; ++j)
              depth[j] += increment[j] = n * mean[j];
            scatter.add_update(increment, bed);
            const int           deepest = std::max_element(depth.begin(), depth.end()) - depth.begin();
            std::vector<double> at_place;
            for (const auto &b : bed)
              at_place.push_back(b[deepest]);
            tonnes += n * 10.0;
            records.push_back({tonnes, depth[deepest], 3, relative_variance(at_place)});
          }
        const LifeInterval li = life_interval(0.012, records);
        lives.push_back(li.life.tonnes);
        stated += li.relative_sd * li.relative_sd / trials;
        const double       phi2 = scatter.maximum_factor(depth, 400);
        const LifeInterval many = life_interval(0.012, records, 0.95, phi2);
        stated_many += many.relative_sd * many.relative_sd / trials;
        factors += std::sqrt(phi2) / trials;
      }
    const double mean = std::accumulate(lives.begin(), lives.end(), 0.0) / trials;
    double       var  = 0;
    for (double l : lives)
      var += (l - mean) * (l - mean) / (trials - 1);
    const double real = std::sqrt(var) / mean;
    return {real / std::sqrt(stated), real / std::sqrt(stated_many), factors};
  }
} // namespace

// What the interval assumes of the place that ends life: it takes the beds' scatter at the
// leading place, as if that place had been chosen beforehand. With one place the lives scatter
// as stated (real / stated standard deviation 1 within 15 %). With many nearly equal places the
// worst of them (a maximum of random walks: when the leader lags another takes over) scatters
// about half as much as one place: at the leading place alone the stated spread is twice the
// real one (0.49 here; the knife-bed's disjoint bed groups end at a clear leader, the corner,
// where the factor is 1: docs/lifetime.md). The factor of
// place_scatter.h (a double wild bootstrap of the run's bed deviations at every place) brings
// it to 0.78 (20 independent places), 0.88 (correlated 0.8 between neighbours, as a filtered
// field is), 0.81 (5 places); where one place leads by 10-20 % it is 0.88-0.99. It must never
// be over-confident by more than 10 % (above 1.1), and must take at least a third of the
// excess off (above 0.7; at the leading place alone: below 0.6, the test fails). Stopped after
// 5 updates, the life is extrapolated: the factor scales only the beds' part, not the
// exponent's (scaled too, the referee measured 1.28 here: over-confident). The bootstrap
// centred on the observed field keeps the margin by which the observed leader won (noise spread
// the places apart), so fewer places compete in its draws than in reality: what is left of the
// conservatism (docs/lifetime.md). Tried before, in this model (session 19): the spread of each
// bed's own deepest place (0.53), Gaussian multipliers on the update's mean field (0.51), and
// the life's spread over a whole-run bootstrap's own lives (0.70).
TEST(LifeInterval, TheWorstOfManyPlacesIsStatedAsItScatters)
{
  struct Case
  {
    int    places;
    double leader, correlation, low, high;
    int    updates = 40; ///< fewer: the life extrapolated past the last update
  };
  for (const Case c : {Case{1, 0, 0, 0.85, 1.15}, Case{5, 0, 0, 0.7, 1.1}, Case{20, 0, 0, 0.7, 1.1},
                       Case{20, 0, 0.8, 0.7, 1.1}, Case{20, 0.1, 0, 0.7, 1.1}, Case{20, 0.2, 0, 0.7, 1.1},
                       Case{20, 0, 0, 0.5, 1.1, 5}, Case{20, 0, 0.8, 0.5, 1.1, 5}})
    {
      const Spread r = spread_ratio(c.places, 1000, c.leader, c.correlation, c.updates);
      std::cout << c.places << " places, leader +" << c.leader << ", correlation " << c.correlation
                << (c.updates < 40 ? ", extrapolated after " + std::to_string(c.updates) + " updates" : std::string())
                << ": real / stated standard deviation of the life: at the leading place " << r.at_one_place
                << ", with the factor for the worst place " << r.worst_of_many << " (phi " << r.factor << ")\n";
      EXPECT_GE(r.worst_of_many, c.low) << c.places << " places, leader " << c.leader << ", correlation " << c.correlation;
      EXPECT_LE(r.worst_of_many, c.high) << c.places << " places, leader " << c.leader << ", correlation " << c.correlation;
      if (c.places == 1)
        {
          EXPECT_NEAR(r.factor, 1, 1e-12);
        }
      if (c.places == 20 && c.leader == 0 && c.correlation == 0 && c.updates == 40)
        {
          EXPECT_LT(r.at_one_place, 0.6); // the conservatism the factor takes off
        }
    }
}

// Places that scatter together (the same relative deviation of every bed at every place, as the
// analytic source's one multiplier per bed gives) scatter as one: factor 1. The state survives
// a checkpoint's numbers, and malformed numbers are refused.
TEST(PlaceScatter, PlacesThatScatterTogetherScatterAsOneAndTheStateRoundTrips)
{
  PlaceScatter together, apart;
  std::mt19937_64 random(3);
  std::normal_distribution<double> normal;
  for (int u = 0; u < 6; ++u)
    {
      std::vector<std::vector<double>> same(3, std::vector<double>(10)), own(3, std::vector<double>(10));
      for (auto b = 0; b < 3; ++b)
        {
          const double f = 1 + 0.3 * normal(random);
          for (int p = 0; p < 10; ++p)
            same[b][p] = f * (1 + 0.01 * p), own[b][p] = 1 + 0.3 * normal(random);
        }
      together.add_update(std::vector<double>(10, 1e-3), same);
      apart.add_update(std::vector<double>(10, 1e-3), own);
    }
  std::vector<double> values(10, 6e-3);
  values[4] += 1e-6;
  EXPECT_NEAR(together.maximum_factor(values), 1, 1e-9);
  const double f = apart.maximum_factor(values);
  EXPECT_LT(f, 0.9); // ten independent places of equal wear: the worst scatters less
  PlaceScatter copy;
  copy.set_numbers(apart.numbers());
  EXPECT_EQ(copy.maximum_factor(values), f);
  EXPECT_EQ(copy.updates(), 6u);
  auto cut = apart.numbers();
  cut.pop_back();
  EXPECT_THROW(copy.set_numbers(cut), std::invalid_argument);
  EXPECT_THROW(copy.set_numbers({}), std::invalid_argument);
  EXPECT_THROW(apart.add_update(std::vector<double>(9, 1e-3), {}), std::logic_error);
}

TEST(BedSeed, TheFirstUpdateKeepsTheSeedLaterOnesAreFreshAndDistinct)
{
  EXPECT_EQ(bed_seed(7, 1), 7);
  EXPECT_NE(bed_seed(7, 0), 7); // the pilot's beds are its own
  std::set<int> seen;
  for (int s = 1; s <= 50; ++s)
    for (long u = 0; u <= 40; ++u)
      for (long round = 0; round < 3; ++round)
        {
          if (u == 1 && round == 0)
            continue; // the seed itself (checked above)
          const int b = bed_seed(s, u, round);
          EXPECT_GT(b, 0);
          EXPECT_TRUE(seen.insert(b).second) << "seed " << s << " update " << u << " round " << round;
        }
  // the same on every machine and after a resume: values pinned (a Python SplitMix64 gives them)
  EXPECT_EQ(bed_seed(7, 5, 2), 186921669);
  EXPECT_EQ(bed_seed(1, 4), 692341759);
}
