// The wear footprint fitted with W (footprint_fit.h).
#include <abrade/field/footprint_fit.h>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace abrade::field
{
  namespace
  {
    /// The parabola y = a x^2 + b x + c through three points.
    std::array<double, 3> parabola(const std::array<double, 3> &x, const std::array<double, 3> &y)
    {
      const double d0 = (x[0] - x[1]) * (x[0] - x[2]), d1 = (x[1] - x[0]) * (x[1] - x[2]),
                   d2 = (x[2] - x[0]) * (x[2] - x[1]);
      const double a = y[0] / d0 + y[1] / d1 + y[2] / d2;
      const double b = -(y[0] * (x[1] + x[2]) / d0 + y[1] * (x[0] + x[2]) / d1 + y[2] * (x[0] + x[1]) / d2);
      const double c = y[0] * x[1] * x[2] / d0 + y[1] * x[0] * x[2] / d1 + y[2] * x[0] * x[1] / d2;
      return {a, b, c};
    }
  } // namespace

  FootprintFit fit_footprint(std::vector<FootprintCandidate> c)
  {
    FootprintFit f;
    c.erase(std::remove_if(c.begin(), c.end(), [](const FootprintCandidate &k) { return !(k.r > 0 && k.w > 0); }),
            c.end());
    if (!c.empty()) // not identifiable: W for the footprint assumed (the first run given)
      f.r = f.r_low = f.r_high = c.front().r, f.w = c.front().w;
    std::sort(c.begin(), c.end(), [](const auto &a, const auto &b) { return a.r < b.r; });
    if (c.empty())
      {
        f.reason = "no candidate run records its footprint (Smoothing radius) and a positive fitted W";
        return f;
      }
    const std::size_t best = std::min_element(c.begin(), c.end(), [](const auto &a, const auto &b) {
                               return a.rss < b.rss;
                             }) - c.begin();
    char text[480];
    for (std::size_t k = 1; k < c.size(); ++k)
      if (!(c[k].r > c[k - 1].r * (1 + 1e-9)))
        {
          std::snprintf(text, sizeof text, "two candidates have the same footprint (%.4g m)", c[k].r);
          f.reason = text;
          return f;
        }
    if (c.size() < 3)
      {
        f.reason = "fewer than three footprints (Smoothing radius) among the runs: W holds for the best run's";
        return f;
      }
    if (best == 0 || best + 1 == c.size())
      {
        std::snprintf(text, sizeof text,
                      "the best footprint is the %s candidate (%.4g m): the fit lies beyond the candidates; add a run "
                      "at a %s Smoothing radius",
                      best == 0 ? "smallest" : "largest", c[best].r, best == 0 ? "smaller" : "larger");
        f.reason = text;
        return f;
      }
    f.dof = double(c[best].blocks - 2);
    if (f.dof < 1)
      {
        f.reason = "the measurements fall into too few spatial blocks to tell the footprint from W (a single "
                   "depth, or a few close points: W and the footprint are degenerate)";
        return f;
      }
    // (in r: a footprint that is off by dr widens the pattern by about dr, so the residuals add
    // (k dr)^2 to the noise's; in ln r the vertex was pulled towards the steeper side)
    const double t     = boost::math::quantile(boost::math::students_t_distribution<double>(f.dof), 0.975);
    // (the measurements per independent one: the design effect, at most all of a block's)
    const double n     = double(c[best].measurements);
    const double ratio = n > 2 ? 1 + std::clamp(c[best].design_effect, 1.0, n / f.dof) * t * t / (n - 2)
                               : 1 + t * t / f.dof;
    // The profile is known at the candidates only. Its minimum by a parabola in r (a footprint
    // off by dr widens the pattern by about dr, adding (k dr)^2 to the residuals) and by one in
    // ln r (a relative misfit): the first is pulled towards the steeper side where the
    // residuals rise unevenly in r, the second where they do in ln r (a band's own width, the
    // DEM's spread contacts); the estimate is their geometric mean and half their distance (on
    // ln r) is added to the statistical half-width as the interpolation's error.
    struct Minimum
    {
      bool   ok = false;
      double x = 0, half = 0; ///< on ln r
    };
    auto minimum = [&](bool in_log) {
      auto                        coordinate = [&](double r) { return in_log ? std::log(r) : r; };
      const std::array<double, 3> x = {coordinate(c[best - 1].r), coordinate(c[best].r), coordinate(c[best + 1].r)};
      const auto [a, b, k]        = parabola(x, {c[best - 1].rss, c[best].rss, c[best + 1].rss});
      Minimum m;
      if (!(a > 0))
        return m;
      const double xm = -b / (2 * a), rss_min = k - b * b / (4 * a);
      const double level = std::max(rss_min, 0.0) * ratio;
      const double half  = std::sqrt(std::max(0.0, (level - rss_min) / a));
      // the interval: where the parabola reaches the level; it must lie within the candidates'
      // range and the residuals must rise to it (a flat profile: one depth, no width information)
      const double low = in_log ? std::exp(xm - half) : xm - half, high = in_log ? std::exp(xm + half) : xm + half;
      m.ok = low > c.front().r && high < c.back().r && std::max(c[best - 1].rss, c[best + 1].rss) > level;
      m.x = in_log ? xm : std::log(xm), m.half = in_log ? half : std::log(high / xm);
      return m;
    };
    const Minimum in_r = minimum(false), in_log_r = minimum(true);
    if (!in_r.ok || !in_log_r.ok)
      {
        std::snprintf(text, sizeof text,
                      "the measurements cannot tell the footprint: the residuals do not rise above %.3g of the best "
                      "within the candidates (%.4g ... %.4g m), so W and the footprint are degenerate (a single depth, "
                      "or no width information); W is given for the footprint assumed (the first run's)",
                      ratio, c.front().r, c.back().r);
        f.reason = text;
        return f;
      }
    const double xm   = 0.5 * (in_r.x + in_log_r.x);
    const double half = std::max(in_r.half, in_log_r.half) + 0.5 * std::abs(in_r.x - in_log_r.x);
    f.identifiable = true, f.reason.clear();
    f.r = std::exp(xm), f.r_low = std::exp(xm - half), f.r_high = std::exp(xm + half);
    f.sd_log_r = half / t;
    // W and the life along the ridge: parabolas in ln r through the same three candidates
    const std::array<double, 3> x = {std::log(c[best - 1].r), std::log(c[best].r), std::log(c[best + 1].r)};
    auto along = [&](auto value) {
      const auto [p, q, s] = parabola(x, {value(c[best - 1]), value(c[best]), value(c[best + 1])});
      return std::array<double, 2>{p * xm * xm + q * xm + s, 2 * p * xm + q}; // value, d/d ln r at xm
    };
    const auto w = along([](const FootprintCandidate &k) { return std::log(k.w); });
    f.w = std::exp(w[0]), f.dlnw_dlnr = w[1];
    if (c[best - 1].life > 0 && c[best].life > 0 && c[best + 1].life > 0)
      f.dlnlife_dlnr = along([](const FootprintCandidate &k) { return std::log(k.life / k.scale); })[1];
    return f;
  }
} // namespace abrade::field
