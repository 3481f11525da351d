#pragma once
// Independent simulations side by side: the ranks of a program cut into groups, each group
// running its share of the members (the beds of a lifetime update) on a communicator of its own,
// and then every member's result handed to every rank.
//
//   Ensemble ensemble(Parallel::world(), beds.size(), 0);
//   for (std::size_t b = 0; b < beds.size(); ++b)
//     if (ensemble.runs(b))
//       result[b] = run_bed(b, ensemble.group()); // a Simulation on Settings::ranks = group()
//   for (std::size_t b = 0; b < beds.size(); ++b)
//     ensemble.share(result[b], b);               // now on every rank
//
// Member b runs on group b mod G; the G groups are contiguous blocks of ranks whose sizes
// differ by one at most (6 ranks, 3 beds: 3 groups of 2; 3 ranks, 2 beds: 2 + 1). A group of one
// rank is serial, as a program run without mpirun is, so a member's result is the one it has
// alone on that many ranks: bitwise, as the DEM's results depend on the rank count only.
#include <abrade/dem/parallel.h>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace abrade::dem
{
  class Ensemble
  {
  public:
    /// @p members simulations on the ranks of @p all, in groups of about @p ranks_per_member
    /// ranks (0: the ranks shared out evenly, one group per member while there are enough
    /// ranks). Collective over @p all.
    Ensemble(const Parallel &all, std::size_t members, int ranks_per_member);

    /// The number of groups.
    int groups() const { return n_groups; }
    /// The fewest and the most ranks in a group (they differ by one at most).
    int smallest_group() const { return all.size() / n_groups; }
    int largest_group() const { return (all.size() + n_groups - 1) / n_groups; }
    /// This rank's group, the ranks it runs its members with.
    const Parallel &group() const { return own; }
    /// Whether this rank's group runs member @p m.
    bool runs(std::size_t m) const { return int(m % n_groups) == my_group; }

    /// @p values as the root of member @p m's group holds them, on every rank (nothing is sent
    /// with one group: every rank ran every member). Collective over all ranks.
    void share(std::vector<double> &values, std::size_t m) const;
    /// The same for a text.
    void share(std::string &text, std::size_t m) const;

    /// Fails on every rank when a member failed on any (a group's error is its own; the others
    /// would wait for its results for ever): Parallel::fail_together over all ranks.
    /// @p failure: this rank's (null: none). Collective over all ranks.
    void fail_together(const std::exception_ptr &failure) const;

  private:
    /// The rank of @p all that holds member @p m's result: its group's first.
    int root_of(std::size_t m) const;

    Parallel all, own;
    int      n_groups = 1, my_group = 0;
  };
} // namespace abrade::dem
