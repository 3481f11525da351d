#include <abrade/dem/particles.h>

#include <cmath>

namespace abrade::dem
{
  template <typename F>
  void ParticleStore::for_each_array(F &&f)
  {
    for (auto *a : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &fx, &fy, &fz, &tx, &ty, &tz,
                    &radius, &mass, &inv_mass, &inv_inertia})
      f(*a);
    f(material);
    f(id);
  }

  std::size_t ParticleStore::add(std::int64_t pid, double px, double py, double pz, double r,
                                 double density, int mat)
  {
    const double m = density * 4.0 / 3.0 * M_PI * r * r * r;
    for_each_array([](auto &a) { a.emplace_back(); });
    const std::size_t k = x.size() - 1;
    x[k] = px, y[k] = py, z[k] = pz;
    radius[k]      = r;
    mass[k]        = m;
    inv_mass[k]    = 1 / m;
    inv_inertia[k] = 1 / (0.4 * m * r * r);
    material[k]    = mat;
    id[k]          = pid;
    return k;
  }

  void ParticleStore::permute(const std::vector<std::size_t> &order, int threads)
  {
    for_each_array([&](auto &a) {
      std::remove_reference_t<decltype(a)> b(order.size());
      const long                           n = static_cast<long>(order.size());
#pragma omp parallel for schedule(static) num_threads(threads)
      for (long k = 0; k < n; ++k)
        b[k] = a[order[k]];
      a.swap(b);
    });
  }

  void ParticleStore::clear()
  {
    for_each_array([](auto &a) { a.clear(); });
  }
} // namespace abrade::dem
