// Materials and the contact coefficients of each pair (material.h).
#include <abrade/dem/material.h>

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

namespace abrade::dem
{
  Material Material::from_shear_modulus(const std::string &name, double G, double nu, double rho,
                                        bool rotation)
  {
    return Material{name, 2 * G * (1 + nu), nu, rho, rotation};
  }

  double edem_beta(double e)
  {
    if (e >= 1)
      return 0;
    const double l = std::log(e);
    return l / std::sqrt(l * l + M_PI * M_PI);
  }

  // Dimensionless Hertz contact with EDEM-type damping: with K = 4/3 E* sqrt(R*), lengths scaled
  // by L and times by T = sqrt(m*/(K sqrt(L))) such that the impact speed is 1, the equation of
  // motion  m* d'' = -K d^1.5 - c sqrt(1.5 K m* d^0.5) d'  becomes
  //   x'' = -x^1.5 - c sqrt(1.5) x^0.25 x',  x(0) = 0, x'(0) = 1,
  // so the restitution |x'| at separation depends on the damping factor c alone.
  double hertz_restitution(double damping)
  {
    const double g = damping * std::sqrt(1.5);
    auto         acc = [g](double x, double v) {
      const double xp = std::max(x, 0.0);
      return -std::pow(xp, 1.5) - g * std::pow(xp, 0.25) * v;
    };
    double       x = 0, v = 1;
    const double h = 5e-4; // the undamped contact lasts 3.2 time units
    for (int step = 0; step < 1000000; ++step)
      {
        // classical RK4
        const double k1x = v, k1v = acc(x, v);
        const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
        const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
        const double k4x = v + h * k3v, k4v = acc(x + h * k3x, v + h * k3v);
        const double xn  = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        const double vn  = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
        if (xn <= 0 && step > 0)
          {
            // interpolate the crossing linearly
            const double s = x / (x - xn);
            return -(v + s * (vn - v));
          }
        x = xn;
        v = vn;
      }
    return 0; // overdamped: never separates within 200 contact times
  }

  double calibrated_damping(double e)
  {
    if (e >= 1)
      return 0;
    if (e <= 0)
      throw std::invalid_argument("restitution must be positive");
    static std::mutex             mutex;
    static std::map<double, double> cache;
    std::lock_guard<std::mutex>   lock(mutex);
    if (auto it = cache.find(e); it != cache.end())
      return it->second;
    // bracket around EDEM's value (which is close), then bisect
    const double guess = -2 * std::sqrt(5.0 / 6.0) * edem_beta(e);
    double       lo = 0.5 * guess, hi = 1.5 * guess + 1e-3;
    while (hertz_restitution(lo) < e && lo > 1e-12)
      lo *= 0.5;
    while (hertz_restitution(hi) > e && hi < 100)
      hi *= 2;
    for (int it = 0; it < 30; ++it)
      {
        const double mid = 0.5 * (lo + hi);
        (hertz_restitution(mid) > e ? lo : hi) = mid;
      }
    return cache[e] = 0.5 * (lo + hi);
  }

  PairCoefficients make_pair_coefficients(const Material &a, const Material &b,
                                          const Interaction &i, DampingModel model)
  {
    PairCoefficients c;
    c.e_star = 1.0 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                      (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
    c.g_star = 1.0 / ((2 - a.poisson_ratio) / a.shear_modulus() +
                      (2 - b.poisson_ratio) / b.shear_modulus());
    c.damping = model == DampingModel::edem ? -2 * std::sqrt(5.0 / 6.0) * edem_beta(i.restitution)
                                            : calibrated_damping(i.restitution);
    c.sqrt_2e          = std::sqrt(2 * c.e_star);
    c.sqrt_8g          = std::sqrt(8 * c.g_star);
    c.friction         = i.friction;
    c.rolling_friction = i.rolling_friction;
    c.restitution      = i.restitution;
    c.cohesion_energy_density = i.cohesion_energy_density;
    c.rolling_damping         = i.rolling_damping;
    return c;
  }
} // namespace abrade::dem
