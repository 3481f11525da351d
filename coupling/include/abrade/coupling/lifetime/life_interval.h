#pragma once
// The uncertainty of a predicted life from replicate beds (Lifetime/Seeds).
//
// Every seed's DEM cycle gives its own wear rate. The loop moves the knife with the seeds' mean,
// and follows, for each seed, its rate of the quantity that ends life relative to that mean (at
// the deepest point, at the followed point, or of the whole worn volume), averaged over the
// updates with their cycles as weights: the seed factors f_s, whose mean is 1. The life scales
// inversely with the rate, so the interval is formed on the mean rate and carried over:
//
//   h = t_{1-a/2, n-1} s_f / sqrt(n)            (s_f: the factors' sample standard deviation)
//   life in [L / (1 + h), L / (1 - h)]           (the (1-a) t-interval of the mean rate)
//   spread  [L / (1 + s_f), L / (1 - s_f)]       (one bed's life: the beds' scatter)
//
// With normally scattered rates the interval covers the true life in a fraction 1-a of all
// runs (test_lifetime_steps.cc checks this over 400 runs of a known scatter). One seed: no
// interval. Where h >= 1 the upper bound is unbounded (reported as 0 with a warning).
#include <vector>

namespace abrade::coupling::lifetime
{
  struct LifeInterval
  {
    std::size_t seeds = 0;
    double      life  = 0;
    double      confidence    = 0.95;
    double      relative_sd   = 0; ///< s_f
    double      half_width    = 0; ///< h, relative
    double      low = 0, high = 0; ///< the t-interval [t]; 0: none (one seed) or unbounded (high)
    double      spread_low = 0, spread_high = 0;
  };

  /// The two-sided Student t quantile t_{p, dof} (Boost.Math).
  double student_t_quantile(double p, unsigned dof);

  LifeInterval life_interval(double life, const std::vector<double> &seed_factors, double confidence = 0.95);

  /// Accumulates the seed factors over the updates: add() once per update with its cycles, the
  /// seeds' mean rate and each seed's rate of the quantity that ends life.
  class SeedFactors
  {
  public:
    explicit SeedFactors(std::size_t seeds = 0) : weighted(seeds, 0.0) {}
    void add(double cycles, double mean_rate, const std::vector<double> &seed_rates);
    /// f_s = sum_u n_u r_s,u / sum_u n_u r_mean,u (all 1 before the first update).
    std::vector<double> factors() const;
    /// For the resume state: the sums, and setting them back.
    std::vector<double> sums() const;
    void                set_sums(const std::vector<double> &sums);

  private:
    double              total = 0;
    std::vector<double> weighted;
  };
} // namespace abrade::coupling::lifetime
