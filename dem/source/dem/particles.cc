// The particles, structure of arrays: adding, removing, reordering (particles.h).
#include <abrade/common/error.h>
#include <abrade/dem/parallel.h>
#include <abrade/dem/particles.h>

#include <cmath>

namespace abrade::dem
{
  template <typename F>
  void ParticleStore::for_each_array(F &&f)
  {
    for (auto *a : {&x, &y, &z, &vx, &vy, &vz, &wx, &wy, &wz, &fx, &fy, &fz, &tx, &ty, &tz, &rolling,
                    &radius, &mass, &inv_mass, &inv_inertia})
      f(*a);
    f(material);
    f(id);
  }

  std::size_t ParticleStore::add(std::int64_t pid, double px, double py, double pz, double r,
                                 double density, int mat)
  {
    if (n_ghost > 0)
      throw RunError("internal: particles added while ghost particles are present");
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
    n_ghost = n_distributed = 0;
  }

  void ParticleStore::resize_arrays(std::size_t n)
  {
    for_each_array([n](auto &a) { a.resize(n); });
    n_ghost = 0;
  }

  void ParticleStore::permute_range(std::size_t first, const std::vector<std::size_t> &order)
  {
    for_each_array([&](auto &a) {
      std::remove_reference_t<decltype(a)> b(order.size());
      for (std::size_t k = 0; k < order.size(); ++k)
        b[k] = a[first + order[k]];
      std::copy(b.begin(), b.end(), a.begin() + first);
    });
  }

  void ParticleStore::pack(std::size_t i, std::vector<double> &out) const
  {
    const_cast<ParticleStore *>(this)->for_each_array([&](auto &a) {
      using T = typename std::remove_reference_t<decltype(a)>::value_type;
      if constexpr (std::is_same_v<T, double>)
        out.push_back(a[i]);
      else
        out.push_back(pack_integer(a[i]));
    });
  }

  std::size_t ParticleStore::unpack(const double *in)
  {
    int k = 0;
    for_each_array([&](auto &a) {
      using T = typename std::remove_reference_t<decltype(a)>::value_type;
      if constexpr (std::is_same_v<T, double>)
        a.push_back(in[k++]);
      else
        a.push_back(static_cast<T>(unpack_integer(in[k++])));
    });
    return x.size() - 1;
  }
} // namespace abrade::dem
