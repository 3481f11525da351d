// The beds' scatter at many places and the factor for the worst of them (place_scatter.h).
#include <abrade/coupling/lifetime/place_scatter.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace abrade::coupling::lifetime
{
  void PlaceScatter::add_update(const std::vector<double> &increment, const std::vector<std::vector<double>> &bed_rates)
  {
    if (beds.empty())
      n_places = increment.size();
    if (increment.size() != n_places)
      throw std::logic_error("PlaceScatter: " + std::to_string(increment.size()) + " places, was " +
                             std::to_string(n_places));
    const std::size_t n = bed_rates.size();
    if (n < 2)
      {
        beds.push_back(0);
        return;
      }
    for (const auto &b : bed_rates)
      if (b.size() != n_places)
        throw std::logic_error("PlaceScatter: a bed's rates at another number of places");
    beds.push_back(n);
    const double scale = std::sqrt(double(n) / double(n - 1)) / double(n);
    for (const auto &b : bed_rates)
      for (std::size_t p = 0; p < n_places; ++p)
        {
          double mean = 0;
          for (const auto &c : bed_rates)
            mean += c[p] / double(n);
          deviations.push_back(mean > 0 ? increment[p] * (b[p] / mean - 1) * scale : 0.0);
        }
  }

  namespace
  {
    /// The deviations of the places that can lead, as rows (one per bed of an update) of
    /// columns (the places), and draws of the quantity at them.
    struct Rivals
    {
      std::vector<std::size_t> place;
      std::size_t              lead = 0; ///< its column
      std::vector<double>      e;        ///< rows x columns
      std::size_t              rows = 0;

      /// Over @p draws draws centred on @p centre (one value per column): the standard
      /// deviations of the maximum and of the lead column.
      std::pair<double, double> spread(const std::vector<double> &centre, unsigned draws, std::mt19937_64 &random) const
      {
        const std::size_t   cols = place.size();
        std::vector<double> q(cols);
        double              sum_max = 0, sum_max2 = 0, sum_lead = 0, sum_lead2 = 0;
        for (unsigned d = 0; d < draws; ++d)
          {
            draw(centre, random, q);
            const double m = *std::max_element(q.begin(), q.end()), l = q[lead];
            sum_max += m, sum_max2 += m * m, sum_lead += l, sum_lead2 += l * l;
          }
        auto sd = [&](double sum, double sum2) {
          return std::sqrt(std::max(0.0, sum2 / draws - (sum / draws) * (sum / draws)));
        };
        return {sd(sum_max, sum_max2), sd(sum_lead, sum_lead2)};
      }
      void draw(const std::vector<double> &centre, std::mt19937_64 &random, std::vector<double> &q) const
      {
        const std::size_t cols = place.size();
        q                      = centre;
        for (std::size_t r = 0; r < rows; ++r)
          {
            const double  w   = (random() & 1) ? 1.0 : -1.0;
            const double *row = e.data() + r * cols;
            for (std::size_t c = 0; c < cols; ++c)
              q[c] += w * row[c];
          }
      }
    };
  } // namespace

  double PlaceScatter::maximum_factor(const std::vector<double> &values, unsigned draws) const
  {
    if (values.size() != n_places || n_places < 2 || draws < 20)
      return 1;
    // each place's standard deviation over the draws (the root of its summed squared deviations)
    std::vector<double> sd(n_places, 0.0);
    std::size_t         rows = 0;
    for (std::size_t k = 0, at = 0; k < beds.size(); ++k)
      for (std::size_t b = 0; b < beds[k]; ++b, at += n_places, ++rows)
        for (std::size_t p = 0; p < n_places; ++p)
          sd[p] += deviations[at + p] * deviations[at + p];
    for (double &s : sd)
      s = std::sqrt(s);
    const std::size_t lead = std::max_element(values.begin(), values.end()) - values.begin();
    if (!(sd[lead] > 0))
      return 1;
    // the places that can lead in a draw (within six standard deviations of the leader's reach)
    Rivals r;
    r.rows = rows;
    for (std::size_t p = 0; p < n_places; ++p)
      if (p == lead || values[p] + 6 * sd[p] >= values[lead] - 6 * sd[lead])
        {
          if (p == lead)
            r.lead = r.place.size();
          r.place.push_back(p);
        }
    if (r.place.size() < 2)
      return 1;
    const std::size_t cols = r.place.size();
    r.e.resize(rows * cols);
    for (std::size_t row = 0; row < rows; ++row)
      for (std::size_t c = 0; c < cols; ++c)
        r.e[row * cols + c] = deviations[row * n_places + r.place[c]];
    std::vector<double> centre(cols);
    for (std::size_t c = 0; c < cols; ++c)
      centre[c] = values[r.place[c]];
    // (the work is draws x rows x columns, five times over with the second level: on a large
    // run -- thousands of nearly equal places, many beds, many updates -- fewer draws, at least
    // 200, keep it to about a second; phi's own scatter then grows from about +-0.02 to +-0.06)
    const double work = 5.0 * double(rows) * double(cols);
    draws             = unsigned(std::clamp(2e9 / work, 200.0, double(draws)));
    std::mt19937_64 random(20261204);
    const auto [s_max, s_lead] = r.spread(centre, draws, random);
    if (!(s_lead > 0))
      return 1;
    // Centred on the observed field, the draws keep the margin by which the observed leader won
    // (noise spread the places apart): the ratio phi = s_max / s_lead is overstated. The same
    // bootstrap from the draws' own fields overstates the draws' ratio about as much: a double
    // bootstrap corrects it, phi^2 / phi*, phi* the mean ratio from 40 first-level draws' fields
    // (as ratios over the same draws, places that scatter together give exactly 1).
    const double        phi    = s_max / s_lead;
    double              second = 0;
    const unsigned      first  = 40;
    std::vector<double> q;
    for (unsigned b = 0; b < first; ++b)
      {
        r.draw(centre, random, q);
        const auto [m, l] = r.spread(q, std::max(20u, draws / 10), random);
        second += (l > 0 ? m / l : 1.0) / first;
      }
    const double corrected = second > 0 ? phi * phi / second : phi;
    return std::clamp(corrected * corrected, 0.0, 1.0);
  }

  std::vector<double> PlaceScatter::numbers() const
  {
    std::vector<double> r{double(n_places), double(beds.size())};
    r.insert(r.end(), beds.begin(), beds.end());
    r.insert(r.end(), deviations.begin(), deviations.end());
    return r;
  }

  void PlaceScatter::set_numbers(const std::vector<double> &numbers)
  {
    if (numbers.size() < 2)
      throw std::invalid_argument("a place scatter of fewer than two numbers");
    const std::size_t places = std::size_t(numbers[0]), updates = std::size_t(numbers[1]);
    if (numbers.size() < 2 + updates)
      throw std::invalid_argument("a place scatter cut short");
    std::vector<std::size_t> b(numbers.begin() + 2, numbers.begin() + 2 + updates);
    std::size_t              expected = 2 + updates;
    for (std::size_t n : b)
      expected += n * places;
    if (numbers.size() != expected)
      throw std::invalid_argument("a place scatter of " + std::to_string(numbers.size()) + " numbers, " +
                                  std::to_string(expected) + " expected");
    n_places = places;
    beds     = b;
    deviations.assign(numbers.begin() + 2 + updates, numbers.end());
  }
} // namespace abrade::coupling::lifetime
