// The wear footprint fitted with W (footprint_fit.h).
#include <abrade/field/footprint_fit.h>
#include <abrade/field/golden_section.h>

#include <boost/math/distributions/students_t.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

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

  namespace
  {
    /// The profile's minimum in ln r between the best candidate's neighbours (golden sections),
    /// the candidates sorted by r; NaN when the best is the smallest or largest (no minimum
    /// between candidates).
    double profile_minimum(const std::vector<FootprintCandidate> &c, const Profile &profile, bool in_log_r)
    {
      const std::size_t best = std::min_element(c.begin(), c.end(), [](const auto &a, const auto &b) {
                                 return a.rss < b.rss;
                               }) - c.begin();
      if (c.size() < 3 || best == 0 || best + 1 == c.size())
        return std::numeric_limits<double>::quiet_NaN();
      return golden_section_minimum([&](double x) { return profile(std::exp(x), false, in_log_r).rss; },
                                    std::log(c[best - 1].r), std::log(c[best + 1].r), 1e-7, 60);
    }
  } // namespace

  namespace
  {
    /// The fit of the footprint r and W to the candidates (footprint_fit.h), in its steps.
    class FootprintFitter
    {
    public:
      FootprintFitter(std::vector<FootprintCandidate> candidates, const Profile &profile, const ProfileWithout &without)
        : c(std::move(candidates)), profile(profile), without(without)
      {}

      FootprintFit fit()
      {
        if (const std::string why = why_not_identifiable(); !why.empty())
        {
          f.reason = why;
          return f;
        }
        locate_the_minimum();
        leave_out_candidates();
        const FootprintCandidate at = profile(f.r, true, true); // the fit there
        if (!(at.w > 0) || !(at.rss >= 0))
          {
            f        = assumed;
            f.reason = "the fit between the candidates failed (no positive W at the profile's minimum)";
            return f;
          }
        if (!interval_of_r(at))
          return f;
        w_and_its_interval(at);
        return f;
      }

    private:
      /// The usable candidates (a footprint, a positive W, a residual), sorted by r, and the
      /// best; W for the footprint assumed (the first run given) until the fit succeeds. Why
      /// the footprint cannot be fitted from them ("": it can).
      std::string why_not_identifiable()
      {
        c.erase(std::remove_if(c.begin(), c.end(),
                               [](const FootprintCandidate &k) { return !(k.r > 0 && k.w > 0 && std::isfinite(k.rss)); }),
                c.end());
        if (!c.empty()) // not identifiable: W for the footprint assumed (the first run given)
          f.r = f.r_low = f.r_high = c.front().r, f.w = c.front().w;
        assumed = f;
        std::sort(c.begin(), c.end(), [](const auto &a, const auto &b) { return a.r < b.r; });
        if (c.empty())
          return "no candidate run records its footprint (Smoothing radius) and a positive fitted W";
        best = std::size_t(std::min_element(c.begin(), c.end(), [](const auto &a, const auto &b) { return a.rss < b.rss; }) -
                           c.begin());
        char text[480];
        for (std::size_t k = 1; k < c.size(); ++k)
          if (!(c[k].r > c[k - 1].r * (1 + 1e-9)))
            {
              std::snprintf(text, sizeof text, "two candidates have the same footprint (%.4g m)", c[k].r);
              return text;
            }
        if (c.size() < 3)
          return "fewer than three footprints (Smoothing radius) among the runs: W holds for the best run's";
        // (a single depth, or a few close points: before the best's place, which is then arbitrary)
        f.dof = double(c[best].blocks - 2);
        if (f.dof < 1)
          return "the measurements fall into too few spatial blocks to tell the footprint from W (a single depth, or "
                 "a few close points: W and the footprint are degenerate)";
        if (best == 0 || best + 1 == c.size())
          {
            std::snprintf(text, sizeof text,
                          "the best footprint is the %s candidate (%.4g m): the fit lies beyond the candidates; add a "
                          "run at a %s Smoothing radius",
                          best == 0 ? "smallest" : "largest", c[best].r, best == 0 ? "smaller" : "larger");
            return text;
          }
        t = boost::math::quantile(boost::math::students_t_distribution<double>(f.dof), 0.975);
        return "";
      }

      /// r^: the profile's minimum between the best candidate's neighbours (golden sections on
      /// ln r), with the candidates' predictions interpolated in ln r and in r: the two minima
      /// differ by the interpolation's error, and half their distance widens the interval.
      void locate_the_minimum()
      {
        x_log = profile_minimum(c, profile, true);
        const double x_lin   = profile_minimum(c, profile, false);
        f.half_interpolation = 0.5 * std::abs(x_log - x_lin);
        f.r                  = std::exp(0.5 * (x_log + x_lin));
      }

      /// The candidates' own error (a replay's geometry feedback left out, a run's beds): r^
      /// again without each candidate in turn that enters the interpolation from beyond the
      /// best and its neighbours (the best +- 2: leaving out one of those three would measure
      /// the interpolation at twice the spacing, not that candidate), and without each replay
      /// among them wherever it sits (a biased replay as the best or its neighbour, not left out,
      /// took r's coverage to 0-83 % in test_footprint_coverage), where the rest still hold a
      /// minimum between them.
      void leave_out_candidates()
      {
        if (without)
          for (std::size_t k = 0; k < c.size(); ++k)
            {
              const bool outer = k + 2 == best || k == best + 2, in_bracket = k + 1 >= best && k <= best + 1;
              if (!outer && !(in_bracket && c[k].replay))
                continue;
              std::vector<FootprintCandidate> rest = c;
              rest.erase(rest.begin() + long(k));
              const double x = profile_minimum(rest, without(c[k].r), true);
              if (std::isfinite(x))
                f.candidate_sensitivity = std::max(f.candidate_sensitivity, std::abs(x - x_log)), left_out.push_back(c[k].r);
              else if (c[k].replay)
                f.replays_not_assessed.push_back(c[k].r);
            }
        f.candidates_left_out = int(left_out.size());
      }

      /// r's interval from the fit @p at r^: the level of the residuals (with the residuals'
      /// design effect), its ends outwards from r^ (the first candidate above the level, then
      /// bisection between it and the point inside), widened by the interpolation's or the
      /// candidates' error. None within the candidates: not identifiable (false, f says why).
      bool interval_of_r(const FootprintCandidate &at)
      {
        const double n     = double(at.measurements);
        const double ratio = n > 2 ? 1 + std::clamp(at.design_effect, 1.0, n / f.dof) * t * t / (n - 2)
                                   : 1 + t * t / f.dof;
        const double level = at.rss * ratio;
        auto         rss   = [&](double x) { return profile(std::exp(x), false, true).rss; };
        auto         end   = [&](int direction) {
          double inside = x_log;
          for (long k = long(best); k >= 0 && k < long(c.size()); k += direction)
            {
              if ((std::log(c[k].r) - inside) * direction <= 0)
                continue;
              if (c[k].rss <= level)
                {
                  inside = std::log(c[k].r);
                  continue;
                }
              double outside = std::log(c[k].r);
              for (int it = 0; it < 50 && std::abs(outside - inside) > 1e-7; ++it)
                {
                  const double x = 0.5 * (inside + outside);
                  (rss(x) <= level ? inside : outside) = x;
                }
              return std::exp(0.5 * (inside + outside));
            }
          return 0.0;
        };
        const double widen = std::max(f.half_interpolation, f.candidate_sensitivity);
        f.r_low = end(-1) * std::exp(-widen), f.r_high = end(+1) * std::exp(widen);
        if (!(f.r_low > 0) || !(f.r_high > 0))
          {
            char text[480];
            std::snprintf(text, sizeof text,
                          "the measurements cannot tell the footprint: the residuals do not rise above %.3g of the "
                          "best within the candidates (%.4g ... %.4g m) on %s side, so W and the footprint are "
                          "degenerate (a single depth, or no width information); W is given for the footprint assumed "
                          "(the first run's)",
                          ratio, c.front().r, c.back().r, f.r_low > 0 ? "the larger" : f.r_high > 0 ? "the smaller" : "either");
            const double dof = f.dof;
            f = assumed, f.reason = text, f.dof = dof;
            return false;
          }
        f.identifiable = true, f.reason.clear();
        f.sd_log_r     = std::log(f.r_high / f.r_low) / (2 * t);
        return true;
      }

      /// W at r^ and along the ridge, the life along it from the three candidates' lives, W
      /// given r (the fit's relative standard error at r^ and the candidates' own error), W's
      /// interval with r's uncertainty in it, and the joint region (joint_distance).
      void w_and_its_interval(const FootprintCandidate &at)
      {
        f.w               = at.w;
        const double step = 0.05;
        f.dlnw_dlnr = std::log(profile(f.r * std::exp(step), false, true).w / profile(f.r * std::exp(-step), false, true).w) /
                      (2 * step);
        if (c[best - 1].life > 0 && c[best].life > 0 && c[best + 1].life > 0)
          {
            const std::array<double, 3> x = {std::log(c[best - 1].r), std::log(c[best].r), std::log(c[best + 1].r)};
            auto life = [](const FootprintCandidate &k) { return std::log(k.life / k.scale); };
            const auto [p, q, unused] = parabola(x, {life(c[best - 1]), life(c[best]), life(c[best + 1])});
            f.dlnlife_dlnr            = 2 * p * std::log(f.r) + q;
          }
        f.sd_log_w       = at.relative_se;
        f.w_dof          = at.w_dof >= 1 ? std::min(at.w_dof, f.dof) : f.dof;
        const double t_w = boost::math::quantile(boost::math::students_t_distribution<double>(f.w_dof), 0.975);
        // W given r carries the candidates' own error too: W at r^ without each candidate left
        // out above (the profile between the rest)
        for (const double r : left_out)
          f.w_candidate_sensitivity =
            std::max(f.w_candidate_sensitivity, std::abs(std::log(without(r)(f.r, false, true).w / f.w)));
        const double given_r = t_w * f.sd_log_w + f.w_candidate_sensitivity; // (W given r's half-width on ln W)
        // (the two parts' half-widths, each at its own degrees of freedom, added in quadrature:
        // r's along the ridge, W's given r)
        const double below = std::hypot(f.dlnw_dlnr * std::log(f.r / f.r_low), given_r);
        const double above = std::hypot(f.dlnw_dlnr * std::log(f.r_high / f.r), given_r);
        f.w_low            = f.w * std::exp(-(f.dlnw_dlnr >= 0 ? below : above));
        f.w_high           = f.w * std::exp(f.dlnw_dlnr >= 0 ? above : below);
        // the joint region's axes: r's interval on each side and W's given r, each at its own
        // degrees of freedom, scaled to the normal's 1.96: chi-square(2)'s 95 % level then
        f.joint_sd_w  = given_r / z95;
        f.joint_level = 5.991464547; // chi-square(0.95; 2)
      }

      std::vector<FootprintCandidate> c;
      const Profile                  &profile;
      const ProfileWithout           &without;
      FootprintFit                    f, assumed;
      std::size_t                     best = 0;
      double                          t = 0, x_log = 0;
      std::vector<double>             left_out; ///< the footprints of the candidates left out in turn
    };
  } // namespace

  FootprintFit fit_footprint(std::vector<FootprintCandidate> c, const Profile &profile, const ProfileWithout &without)
  {
    return FootprintFitter(std::move(c), profile, without).fit();
  }

  namespace
  {
    /// The joint region's scale on ln r on the side of @p a (r's interval is not symmetric).
    double joint_sd_r(const FootprintFit &f, double a)
    {
      return std::max(a < 0 ? std::log(f.r / f.r_low) : std::log(f.r_high / f.r), 1e-12) / z95;
    }
  } // namespace

  double joint_distance(const FootprintFit &f, double r, double w)
  {
    if (!f.identifiable || !(r > 0) || !(w > 0))
      return std::numeric_limits<double>::infinity();
    const double a = std::log(r / f.r), b = std::log(w / f.w);
    const double sr = joint_sd_r(f, a), sw = std::max(f.joint_sd_w, 1e-12);
    const double e  = b - f.dlnw_dlnr * a;
    return a * a / (sr * sr) + e * e / (sw * sw);
  }

  std::vector<std::array<double, 2>> joint_region_outline(const FootprintFit &f, int points)
  {
    std::vector<std::array<double, 2>> outline;
    if (!f.identifiable)
      return outline;
    const double q = std::sqrt(f.joint_level);
    for (int k = 0; k < points; ++k)
      {
        const double angle = 2 * M_PI * k / points;
        const double a = q * joint_sd_r(f, std::cos(angle)) * std::cos(angle), e = q * f.joint_sd_w * std::sin(angle);
        outline.push_back({f.r * std::exp(a), f.w * std::exp(f.dlnw_dlnr * a + e)});
      }
    return outline;
  }

  FootprintFit fit_footprint(const std::vector<RunSeries> &runs, const std::vector<CalibrationResult> &results,
                             const std::vector<double> &lives, const std::vector<Measurement> &ms, double block)
  {
    auto candidate = [&](const CalibrationResult &r, double life) {
      FootprintCandidate k;
      k.r = r.smoothing_radius, k.rss = r.rms_residual * r.rms_residual * double(ms.size());
      k.w = r.archard_coefficient > 0 ? r.archard_coefficient : r.scale, k.life = life, k.scale = r.scale;
      k.blocks = r.blocks, k.measurements = long(ms.size()), k.design_effect = r.design_effect;
      k.relative_se = r.scale > 0 ? std::hypot(r.se_fit, r.se_replicates) / r.scale : 0.0, k.w_dof = r.dof;
      return k;
    };
    std::vector<FootprintCandidate> candidates;
    std::vector<std::size_t>        by_r; // the runs with a footprint, by it
    for (std::size_t i = 0; i < results.size(); ++i)
      {
        candidates.push_back(candidate(results[i], i < lives.size() ? lives[i] : 0.0));
        candidates.back().replay = runs[i].replay;
        if (runs[i].smoothing_radius > 0 && results[i].scale > 0)
          by_r.push_back(i);
      }
    std::sort(by_r.begin(), by_r.end(), [&](auto a, auto b) { return runs[a].smoothing_radius < runs[b].smoothing_radius; });
    // the profile at r: a run interpolated between the candidates (run_between: the nearest is
    // its reference, its W0 and beds), its W by least squares near the nearest's; without the
    // candidate at footprint @p dropped (0: all)
    auto profile_without = [&, by_r](double dropped) -> Profile {
      std::vector<std::size_t>       kept;
      std::vector<const RunSeries *> with_footprint;
      for (const std::size_t i : by_r)
        if (runs[i].smoothing_radius != dropped)
          kept.push_back(i), with_footprint.push_back(&runs[i]);
      return [&, kept, with_footprint](double r, bool full, bool in_log_r) {
        std::size_t first = kept.front();
        for (const std::size_t i : kept)
          if (std::abs(std::log(runs[i].smoothing_radius / r)) < std::abs(std::log(runs[first].smoothing_radius / r)))
            first = i;
        const RunSeries between = run_between(with_footprint, r, in_log_r);
        if (full)
          return candidate(calibrate(between, ms, block), 0.0);
        const double guess = results[first].scale; // (between is in the nearest run's W0)
        auto [s, sum]      = least_squares_scale(between, ms, guess / 2, guess * 2);
        if (s < guess / 1.99 || s > guess * 1.99) // (at the bracket's end: the full search)
          return candidate(calibrate(between, ms, block), 0.0);
        FootprintCandidate p;
        p.r = r, p.rss = sum, p.w = s * (between.archard_coefficient > 0 ? between.archard_coefficient : 1.0);
        return p;
      };
    };
    if (by_r.empty())
      return fit_footprint(candidates, Profile{});
    return fit_footprint(candidates, profile_without(0.0), profile_without);
  }
} // namespace abrade::field
