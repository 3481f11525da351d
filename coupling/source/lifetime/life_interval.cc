// The predicted life from the whole trajectory and its interval (life_interval.h).
#include <abrade/coupling/lifetime/end_of_life.h>
#include <abrade/coupling/lifetime/life_interval.h>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace abrade::coupling::lifetime
{
  double student_t_quantile(double p, double dof)
  {
    return boost::math::quantile(boost::math::students_t_distribution<double>(dof), p);
  }

  namespace
  {
    /// The exponent b of Q ~ T^b on the recent half of the run: the least-squares slope of
    /// ln Q over ln T on the points with T >= T_U / 2 and Q > 0; 1 with fewer than two of them.
    /// Held within [1/4, 4] (a trajectory that stalls or leaps in one update says little more).
    double recent_exponent(const std::vector<double> &tonnes, const std::vector<double> &values)
    {
      const double        last = tonnes.back();
      std::vector<double> x, y;
      for (std::size_t u = 0; u < tonnes.size(); ++u)
        if (tonnes[u] >= 0.5 * last * (1 - 1e-12) && tonnes[u] > 0 && values[u] > 0)
          x.push_back(std::log(tonnes[u])), y.push_back(std::log(values[u]));
      if (x.size() < 2)
        return 1.0;
      const double mx = std::accumulate(x.begin(), x.end(), 0.0) / x.size();
      const double my = std::accumulate(y.begin(), y.end(), 0.0) / y.size();
      double       sxy = 0, sxx = 0;
      for (std::size_t i = 0; i < x.size(); ++i)
        sxy += (x[i] - mx) * (y[i] - my), sxx += (x[i] - mx) * (x[i] - mx);
      const double b = sxx > 0 ? sxy / sxx : 1.0;
      return std::isfinite(b) ? std::clamp(b, 0.25, 4.0) : 1.0;
    }
  } // namespace

  LifeOnTrajectory life_from_trajectory(const std::vector<double> &tonnes, const std::vector<double> &values,
                                        double limit, double exponent)
  {
    LifeOnTrajectory r;
    double           t0 = 0, v0 = 0;
    for (std::size_t u = 0; u < tonnes.size(); ++u)
      {
        if (values[u] >= limit)
          {
            r.tonnes = v0 >= limit ? t0 : crossing(t0, v0, tonnes[u], values[u], limit);
            r.reached = true, r.update = long(u) + 1;
            return r;
          }
        t0 = tonnes[u], v0 = values[u];
      }
    if (tonnes.empty() || !(values.back() > 0) || !(tonnes.back() > 0))
      return r;
    r.exponent = exponent > 0 ? exponent : recent_exponent(tonnes, values);
    r.tonnes   = tonnes.back() * std::pow(limit / values.back(), 1 / r.exponent);
    return r;
  }

  double relative_variance(const std::vector<double> &rates)
  {
    if (rates.size() < 2)
      return 0;
    const double n    = double(rates.size());
    const double mean = std::accumulate(rates.begin(), rates.end(), 0.0) / n;
    if (!(mean > 0))
      return -1; // no wear at the place: no estimate of the scatter
    double var = 0;
    for (double x : rates)
      var += (x - mean) * (x - mean) / (n - 1);
    return var / (mean * mean);
  }

  std::pair<double, double> pooled_relative_variance(const std::vector<UpdateRecord> &updates)
  {
    double sum = 0, dof = 0;
    for (const auto &u : updates)
      if (u.beds > 1 && u.relative_variance >= 0) // (< 0: the place did not wear, nothing to pool)
        sum += (u.beds - 1) * u.relative_variance, dof += double(u.beds - 1);
    return {dof > 0 ? sum / dof : 0.0, dof};
  }

  LifeInterval life_interval(double limit, const std::vector<UpdateRecord> &updates, double confidence,
                             double place_factor)
  {
    LifeInterval r;
    r.confidence   = confidence;
    r.place_factor = place_factor;
    std::vector<double> tonnes, values, step;
    double              before = 0;
    for (const auto &u : updates)
      {
        tonnes.push_back(u.tonnes), values.push_back(u.value);
        step.push_back(u.value - before), before = u.value;
      }
    r.life = life_from_trajectory(tonnes, values, limit);
    if (!(r.life.tonnes > 0))
      return r;
    const auto [c2, dof] = pooled_relative_variance(updates);
    r.dof                = dof;
    r.bed_relative_sd    = std::sqrt(c2);
    // the life as a function of the updates' increments, with the exponent fitted (free) or
    // held at the estimate's; its gradient by central differences
    auto life_of = [&](const std::vector<double> &d, double held) {
      std::vector<double> v(d.size());
      std::partial_sum(d.begin(), d.end(), v.begin());
      return life_from_trajectory(tonnes, v, limit, held).tonnes;
    };
    double              var_free = 0, var_held = 0;
    std::vector<double> g_free_of(step.size(), 0.0), g_held_of(step.size(), 0.0);
    for (std::size_t u = 0; u < step.size(); ++u)
      {
        if (!(step[u] > 0))
          continue;
        const double        h = 1e-6 * step[u];
        std::vector<double> up = step, down = step;
        up[u] += h, down[u] -= h;
        const double var_u = c2 * step[u] * step[u] / double(std::max<std::size_t>(1, updates[u].beds));
        const double g_free = (life_of(up, 0) - life_of(down, 0)) / (2 * h);
        const double held   = r.life.reached ? 0 : r.life.exponent;
        const double g_held = (life_of(up, held) - life_of(down, held)) / (2 * h);
        var_free += g_free * g_free * var_u, var_held += g_held * g_held * var_u;
        g_free_of[u] = g_free * step[u], g_held_of[u] = g_held * step[u];
      }
    // the worst of many places scatters less than the leading one: the beds' part (the level
    // the quantity reached) scaled by phi^2; not the extrapolation's (the exponent's own scatter,
    // of which the bootstrap of the places' levels says nothing: scaled too, an extrapolated
    // life was stated up to 1.7x too narrow in the model of tests/unit/test_life_interval.cc)
    const double extrapolation  = std::max(0.0, var_free - var_held);
    var_held *= place_factor;
    const double L              = r.life.tonnes;
    r.relative_sd               = std::sqrt(var_held + extrapolation) / L;
    r.relative_sd_beds          = std::sqrt(var_held) / L;
    r.relative_sd_extrapolation = std::sqrt(extrapolation) / L;
    r.elasticity_held.resize(step.size()), r.elasticity_free.resize(step.size());
    for (std::size_t u = 0; u < step.size(); ++u)
      r.elasticity_held[u] = g_held_of[u] / L, r.elasticity_free[u] = g_free_of[u] / L;
    if (dof < 1)
      return r;
    const double t        = student_t_quantile(0.5 + 0.5 * confidence, dof);
    r.low                 = L * std::exp(-t * r.relative_sd);
    r.high                = L * std::exp(t * r.relative_sd);
    r.relative_half_width = (r.high - r.low) / (2 * L);
    return r;
  }
  LifeInterval add_calibration(LifeInterval r, double relative_sd, double dof)
  {
    if (!(relative_sd > 0) || !(dof >= 1) || !(r.life.tonnes > 0))
      return r;
    r.relative_sd_calibration = relative_sd;
    if (r.dof < 1)
      return r; // no beds' interval (one bed an update): none with the calibration either
    const double beds2 = r.relative_sd * r.relative_sd, cal2 = relative_sd * relative_sd;
    r.relative_sd      = std::sqrt(beds2 + cal2);
    r.dof              = (beds2 + cal2) * (beds2 + cal2) / (beds2 * beds2 / r.dof + cal2 * cal2 / dof);
    const double L = r.life.tonnes, t = student_t_quantile(0.5 + 0.5 * r.confidence, r.dof);
    r.low                 = L * std::exp(-t * r.relative_sd);
    r.high                = L * std::exp(t * r.relative_sd);
    r.relative_half_width = (r.high - r.low) / (2 * L);
    return r;
  }
} // namespace abrade::coupling::lifetime
