// Paired comparison of a variant with a baseline on common beds (paired_change.h).
#include <abrade/coupling/lifetime/life_interval.h>
#include <abrade/coupling/studies/paired_change.h>

#include <cmath>
#include <numeric>

namespace abrade::coupling
{
  PairedChange paired_change(const std::vector<double> &variant, const std::vector<double> &baseline)
  {
    std::vector<double> log_ratio;
    for (std::size_t i = 0; i < variant.size() && i < baseline.size(); ++i)
      if (variant[i] > 0 && baseline[i] > 0)
        log_ratio.push_back(std::log(variant[i] / baseline[i]));
    PairedChange r;
    r.pairs = log_ratio.size();
    if (log_ratio.empty())
      return r;
    const double n    = double(log_ratio.size());
    const double mean = std::accumulate(log_ratio.begin(), log_ratio.end(), 0.0) / n;
    r.ratio = r.low = r.high = std::exp(mean);
    if (log_ratio.size() < 2)
      return r;
    double var = 0;
    for (double x : log_ratio)
      var += (x - mean) * (x - mean) / (n - 1);
    const double h = lifetime::student_t_quantile(0.975, n - 1) * std::sqrt(var / n);
    r.low = std::exp(mean - h), r.high = std::exp(mean + h);
    r.interval    = true;
    r.significant = r.low > 1 || r.high < 1;
    return r;
  }
} // namespace abrade::coupling
