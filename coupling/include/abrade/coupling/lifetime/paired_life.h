#pragma once
// Two lives compared pair by pair (common random numbers; docs/lifetime.md, "Two lives on the
// same beds"). `abrade concepts` runs every concept's lifetime on the same Lifetime/Seeds, so
// update u of every concept draws the same beds (bed_seed()). To first order a life's relative
// error is a sum over the updates of its elasticity G_u (life_interval.h: dL/d dQ_u dQ_u / L)
// times the update's mean bed error, e_uj = r_uj / E[r_u] - 1 of bed j's rate at the place that
// ends life (estimated from the deviations from the update's mean):
//
//   d ln L = sum_u G_u mean_j(e_uj)
//
// For a variant A against a baseline B the beds' shared part cancels in
// d ln (L_A / L_B) = sum_u (G^A_u mean_j e^A_uj - G^B_u mean_j e^B_uj). With each run's pooled
// c^2 (life_interval.h) and the concepts' bed correlation rho, the variance of the log ratio for
// elasticities G^A, G^B is
//
//   V(G^A, G^B) = c_A^2 sum_u (G^A_u)^2 / n^A_u + c_B^2 sum_u (G^B_u)^2 / n^B_u
//                 - 2 rho c_A c_B sum_u G^A_u G^B_u m_u / (n^A_u n^B_u),
//
// m_u the beds both drew in update u (the same seed, whatever the two runs' counts: a target
// interval's extra beds are the seeds' further rounds). rho is pooled as c^2 is (the same cycle on
// slowly changing parts) from the shared beds' deviations, all three sums over the same beds so
// that |rho| <= 1 and V >= 0, over the updates after the first: in the first update two concepts
// can run the very same cycle (the same design at another W, say, or the same shape before the
// shapes part), which a DEM's chaos undoes after it, so its correlation would overstate the
// rest's (pooled with it, 90 % coverage instead of 95 % where the correlation is 1 there and 0
// after; tests/unit/test_paired_life.cc). Assumed: the correlation the same in the later updates.
// As a run's own interval has it (the worst-of-many factor phi^2 on the beds' part, the
// exponent held; the extrapolation's part what the fitted exponent adds):
//
//   Var ln (L_A / L_B) = V(phi_A H^A, phi_B H^B) + max(0, V(F^A, F^B) - V(H^A, H^B))
//
// (H held, F free elasticities). Without shared beds it is the two runs' own variances added.
// The interval is (L_A / L_B) exp(+-t s), t at the smallest of the pools' degrees of freedom
// (conservative: the sum of several has more).
#include <abrade/coupling/studies/paired_change.h>

#include <string>
#include <vector>

namespace abrade::coupling::lifetime
{
  struct LifeInterval;
  struct UpdateRecord;

  /// One update's beds at the place that ends life and the life's elasticities to it.
  struct UpdateBeds
  {
    double              held = 0, free = 0; ///< the elasticities (life_interval.h)
    std::vector<int>    seeds;              ///< each bed's seed (bed_seed())
    std::vector<double> rates;              ///< each bed's rate at the place, in the same order
  };

  /// A run's life and what its interval came from.
  struct LifeBeds
  {
    double                  life         = 0; ///< [t]
    double                  place_factor = 1; ///< phi^2 (place_scatter.h)
    std::vector<UpdateBeds> updates;
  };

  /// The change of life variant / baseline with its interval, the beds paired where both runs
  /// drew the same ones; `pairs` counts the beds paired.
  PairedChange paired_life_change(const LifeBeds &variant, const LifeBeds &baseline, double confidence = 0.95);

  /// The life of @p interval with the beds of @p records.
  LifeBeds life_beds(const std::vector<UpdateRecord> &records, const LifeInterval &interval);

  /// life_beds.csv: one row per update and bed (life, place_factor: the run's, in every row;
  /// update, elasticity_held, elasticity_free, bed_seed, rate); written atomically (a RunError
  /// names the file when it cannot be).
  void write_life_beds(const std::string &path, const LifeBeds &beds);
  /// Reads what write_life_beds() wrote; an InputError names the file and the line of a bad value.
  LifeBeds read_life_beds(const std::string &path);
} // namespace abrade::coupling::lifetime
