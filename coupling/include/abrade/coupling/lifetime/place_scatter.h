#pragma once
// The place that ends life is the worst of many: the deepest vertex, the gauge's most receded
// station, the thinnest station. The interval (life_interval.h) takes the beds' scatter at that
// one place, as if it had been chosen beforehand. But the worst of many nearly equal places
// scatters less than any one of them (a maximum of random walks: when the leader lags, another
// takes over), so that interval is up to 2x too wide with 20 nearly equal places (the model in
// tests/unit/test_life_interval.cc; the small default case: phi = 0.81). Where one place leads
// clearly (the knife-bed knife's corner) the factor is 1.
//
// PlaceScatter keeps, for every update and every bed, the bed's deviation from the update's bed
// mean at every place, in the quantity's own units (the place's increment in the update times
// the bed's relative deviation of its rate there). A wild bootstrap of the whole run draws a
// sign for each bed of each update (Rademacher weights: one draw perturbs every place by the
// same bed's deviation, so the places' correlation is kept) and adds the signed deviations,
// summed over the updates, to the quantity at every place:
//
//   Q*_p = Q_p + sum_u sum_b w_ub e_ubp,   e_ubp = dQ_up (r_ubp / rbar_up - 1) sqrt(n_u / (n_u - 1)) / n_u
//
// (the sum's variance at one place is then the beds' sample variance of the mean, as the
// interval's). The factor on the interval's variance is the draws' variance of the maximum
// over the places against their variance at the leading place:
//
//   phi^2 = Var*(max_p Q*_p) / Var*(Q*_p0),  p0 the leading place,  at most 1
//
// With one place, or places far behind the leader, phi = 1 (the interval as before); with many
// nearly equal places phi < 1. Centred on the observed field the bootstrap keeps the margin by
// which the observed leader won (noise spreads the places apart), so fewer places compete in the
// draws than in reality: a second level of draws from the first level's fields measures that
// bias and divides it out (a double bootstrap). Model: real / stated 0.49 at the leading place,
// 0.78 with the factor (20 independent equal places), 0.88 with neighbours correlated 0.8, 1.03
// with one place, 0.99 with one place 20 % ahead (docs/lifetime.md).
#include <cstddef>
#include <utility>
#include <vector>

namespace abrade::coupling::lifetime
{
  class PlaceScatter
  {
  public:
    /// One update: @p increment[p], the quantity's growth at place p in it (the beds' mean moved
    /// the part); @p bed_rates[b][p], bed b's rate at place p (any unit: only its ratio to the
    /// beds' mean there counts). One bed: no deviation to keep (the update adds no scatter, as it
    /// adds no degree of freedom to the interval). The place count is fixed by the first update.
    void add_update(const std::vector<double> &increment, const std::vector<std::vector<double>> &bed_rates);

    /// phi^2 for the quantity @p values[p] at each place now; 1 without two places or a scatter.
    /// The draws' seed is fixed: the same run gives the same factor on any machine. On a large
    /// run (draws x beds of all updates x places that can lead above about 4e8) fewer draws,
    /// at least 200 (3,000 equal places, 12 beds and 40 updates: 2 s on a busy 2-core machine).
    double maximum_factor(const std::vector<double> &values, unsigned draws = 2000) const;

    std::size_t places() const { return n_places; }
    std::size_t updates() const { return beds.size(); }

    /// For a checkpoint: the state as numbers, and back (std::invalid_argument if malformed).
    std::vector<double> numbers() const;
    void                set_numbers(const std::vector<double> &numbers);

  private:
    std::size_t              n_places = 0;
    std::vector<std::size_t> beds;       ///< per update
    std::vector<double>      deviations; ///< per update, per bed, per place: e_ubp
  };
} // namespace abrade::coupling::lifetime
