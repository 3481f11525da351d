// Two lives compared pair by pair on common beds (paired_life.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/csv_reader.h>
#include <abrade/common/error.h>
#include <abrade/common/finite_number.h>
#include <abrade/coupling/lifetime/life_interval.h>
#include <abrade/coupling/lifetime/paired_life.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

namespace abrade::coupling::lifetime
{
  namespace
  {
    /// e_j = r_j / mean - 1; empty where the update has fewer than two beds or no wear there.
    std::vector<double> deviations(const UpdateBeds &u)
    {
      if (u.rates.size() < 2)
        return {};
      const double mean = std::accumulate(u.rates.begin(), u.rates.end(), 0.0) / double(u.rates.size());
      if (!(mean > 0))
        return {};
      std::vector<double> e;
      for (double r : u.rates)
        e.push_back(r / mean - 1);
      return e;
    }

    /// The pooled c^2 of a run and its degrees of freedom, as its own interval pools them
    /// (pooled_relative_variance()).
    std::pair<double, double> pooled(const LifeBeds &run)
    {
      std::vector<UpdateRecord> records;
      for (const auto &u : run.updates)
        records.push_back({0, 0, u.rates.size(), relative_variance(u.rates)});
      return pooled_relative_variance(records);
    }

    /// The beds both runs drew in one update (the same seed): each run's rates of them.
    struct SharedBeds
    {
      std::vector<double> a, b;
    };

    SharedBeds shared(const UpdateBeds &a, const UpdateBeds &b)
    {
      SharedBeds s;
      for (std::size_t i = 0; i < a.seeds.size() && i < a.rates.size(); ++i)
        for (std::size_t j = 0; j < b.seeds.size() && j < b.rates.size(); ++j)
          if (a.seeds[i] == b.seeds[j])
            {
              s.a.push_back(a.rates[i]), s.b.push_back(b.rates[j]);
              break;
            }
      return s;
    }

    /// sum_u f^2 c^2 g(u)^2 / n_u of a run (its own part of the variance).
    template <class Elasticity>
    double own(const LifeBeds &run, double c2, Elasticity g)
    {
      double v = 0;
      for (const auto &u : run.updates)
        if (!u.rates.empty())
          v += c2 * g(u) * g(u) / double(u.rates.size());
      return v;
    }
  } // namespace

  PairedChange paired_life_change(const LifeBeds &variant, const LifeBeds &baseline, double confidence)
  {
    PairedChange r;
    if (!(variant.life > 0 && baseline.life > 0))
      return r;
    r.ratio = r.low = r.high = variant.life / baseline.life;
    const auto [ca2, dof_a] = pooled(variant);
    const auto [cb2, dof_b] = pooled(baseline);
    if (dof_a < 1 || dof_b < 1)
      return r; // a run without an interval: none for the change either
    // the two concepts' beds' correlation rho, from the beds both drew (the same seed), their
    // deviations from their own means pooled over the updates (as c^2 is: the same cycle on
    // slowly changing parts); its estimate lies in [-1, 1] (all three sums from the same beds),
    // so the variance below is never negative
    const std::size_t   both = std::min(variant.updates.size(), baseline.updates.size());
    std::vector<double> shared_count(both, 0.0);
    double              saa = 0, sbb = 0, sab = 0, dof_c = 0;
    for (std::size_t u = 0; u < both; ++u)
      {
        const SharedBeds s = shared(variant.updates[u], baseline.updates[u]);
        const auto ea = deviations({0, 0, {}, s.a}), eb = deviations({0, 0, {}, s.b});
        if (ea.empty() || eb.empty())
          continue;
        shared_count[u] = double(ea.size()), r.pairs += ea.size();
        if (u == 0 && both > 1)
          continue; // (the first update's cycles can be the same cycle: see above)
        dof_c += double(ea.size() - 1);
        for (std::size_t j = 0; j < ea.size(); ++j)
          saa += ea[j] * ea[j], sbb += eb[j] * eb[j], sab += ea[j] * eb[j];
      }
    const double rho = saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
    // V for the elasticities g, each run's scaled by f: the runs' own parts less twice the
    // covariance of their update means, m rho c_A c_B / (n_A n_B) over the m shared beds
    auto V = [&](auto g, double fa, double fb) {
      double v = fa * fa * own(variant, ca2, g) + fb * fb * own(baseline, cb2, g);
      for (std::size_t u = 0; u < both; ++u)
        if (shared_count[u] > 0)
          v -= 2 * fa * fb * g(variant.updates[u]) * g(baseline.updates[u]) * shared_count[u] * rho *
               std::sqrt(ca2 * cb2) /
               (double(variant.updates[u].rates.size()) * double(baseline.updates[u].rates.size()));
      return v;
    };
    const auto   held = [](const UpdateBeds &u) { return u.held; };
    const auto   free = [](const UpdateBeds &u) { return u.free; };
    // V(phi H) + max(0, V(F) - V(H)), as a run's own interval has it
    const double var = std::max(0.0, V(held, std::sqrt(variant.place_factor), std::sqrt(baseline.place_factor))) +
                       std::max(0.0, V(free, 1, 1) - V(held, 1, 1));
    const double dof = dof_c > 0 ? std::min({dof_a, dof_b, dof_c}) : std::min(dof_a, dof_b);
    const double h   = student_t_quantile(0.5 + 0.5 * confidence, dof) * std::sqrt(var);
    r.low = r.ratio * std::exp(-h), r.high = r.ratio * std::exp(h);
    r.interval    = true;
    r.significant = r.low > 1 || r.high < 1;
    return r;
  }

  LifeBeds life_beds(const std::vector<UpdateRecord> &records, const LifeInterval &interval)
  {
    LifeBeds b;
    b.life = interval.life.tonnes, b.place_factor = interval.place_factor;
    for (std::size_t u = 0; u < records.size(); ++u)
      b.updates.push_back({u < interval.elasticity_held.size() ? interval.elasticity_held[u] : 0.0,
                           u < interval.elasticity_free.size() ? interval.elasticity_free[u] : 0.0,
                           records[u].bed_seeds, records[u].bed_rates});
    return b;
  }

  void write_life_beds(const std::string &path, const LifeBeds &beds)
  {
    std::ostringstream out;
    out.precision(17);
    out << "life,place_factor,update,elasticity_held,elasticity_free,bed_seed,rate\n";
    for (std::size_t u = 0; u < beds.updates.size(); ++u)
      {
        const auto &b = beds.updates[u];
        for (std::size_t j = 0; j < b.rates.size() && j < b.seeds.size(); ++j)
          out << beds.life << ',' << beds.place_factor << ',' << u + 1 << ',' << b.held << ',' << b.free << ','
              << b.seeds[j] << ',' << b.rates[j] << '\n';
      }
    io::write_file_atomically(path, out.str());
  }

  LifeBeds read_life_beds(const std::string &path)
  {
    const io::CsvTable t = io::read_csv(path);
    const int          cl = t.column("life"), cf = t.column("place_factor"), cu = t.column("update"),
              ch = t.column("elasticity_held"), cg = t.column("elasticity_free"), cs = t.column("bed_seed"),
              cr = t.column("rate");
    LifeBeds b;
    for (std::size_t i = 0; i < t.rows.size(); ++i)
      {
        const auto       &row   = t.rows[i];
        const std::string where = "line " + std::to_string(t.line[i]);
        auto              number = [&](int c) {
          const auto v = io::finite_number(row[c]);
          if (!v)
            throw InputError(path, where + ": '" + row[c] + "' is not a finite number");
          return *v;
        };
        const double u = number(cu);
        if (u < 1 || u != std::floor(u) || u > double(b.updates.size()) + 1 || u < double(b.updates.size()))
          throw InputError(path, where + ": update " + row[cu] + " out of order");
        b.life = number(cl), b.place_factor = number(cf);
        if (u > double(b.updates.size()))
          b.updates.push_back({number(ch), number(cg), {}, {}});
        b.updates.back().seeds.push_back(int(number(cs)));
        b.updates.back().rates.push_back(number(cr));
      }
    return b;
  }
} // namespace abrade::coupling::lifetime
