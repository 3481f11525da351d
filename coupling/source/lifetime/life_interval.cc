#include <abrade/coupling/lifetime/life_interval.h>

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace abrade::coupling::lifetime
{
  double student_t_quantile(double p, unsigned dof)
  {
    return boost::math::quantile(boost::math::students_t_distribution<double>(dof), p);
  }

  LifeInterval life_interval(double life, const std::vector<double> &f, double confidence)
  {
    LifeInterval r;
    r.seeds = f.size(), r.life = life, r.confidence = confidence;
    if (f.size() < 2 || !(life > 0))
      return r;
    const double n    = double(f.size());
    const double mean = std::accumulate(f.begin(), f.end(), 0.0) / n;
    double       var  = 0;
    for (double x : f)
      var += (x - mean) * (x - mean) / (n - 1);
    r.relative_sd = std::sqrt(var) / mean; // the factors' mean is 1 up to round-off
    r.half_width  = student_t_quantile(0.5 + 0.5 * confidence, unsigned(f.size() - 1)) * r.relative_sd / std::sqrt(n);
    r.low         = life / (1 + r.half_width);
    r.high        = r.half_width < 1 ? life / (1 - r.half_width) : 0.0;
    r.spread_low  = life / (1 + r.relative_sd);
    r.spread_high = r.relative_sd < 1 ? life / (1 - r.relative_sd) : 0.0;
    return r;
  }

  void SeedFactors::add(double cycles, double mean_rate, const std::vector<double> &seed_rates)
  {
    if (seed_rates.size() != weighted.size())
      throw std::logic_error("SeedFactors::add: one rate per seed expected");
    total += cycles * mean_rate;
    for (std::size_t s = 0; s < weighted.size(); ++s)
      weighted[s] += cycles * seed_rates[s];
  }

  std::vector<double> SeedFactors::factors() const
  {
    std::vector<double> f(weighted.size(), 1.0);
    if (total > 0)
      for (std::size_t s = 0; s < f.size(); ++s)
        f[s] = weighted[s] / total;
    return f;
  }

  std::vector<double> SeedFactors::sums() const
  {
    std::vector<double> s{total};
    s.insert(s.end(), weighted.begin(), weighted.end());
    return s;
  }

  void SeedFactors::set_sums(const std::vector<double> &s)
  {
    if (s.size() != weighted.size() + 1)
      throw std::invalid_argument("seed factor sums: " + std::to_string(weighted.size() + 1) + " numbers expected, " +
                                  std::to_string(s.size()) + " found");
    total = s[0];
    weighted.assign(s.begin() + 1, s.end());
  }
} // namespace abrade::coupling::lifetime
