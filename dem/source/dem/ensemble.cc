// Independent simulations side by side on groups of ranks (ensemble.h).
#include <abrade/dem/ensemble.h>

#include <algorithm>

namespace abrade::dem
{
  Ensemble::Ensemble(const Parallel &all_ranks, std::size_t members, int ranks_per_member) : all(all_ranks)
  {
    const int size  = all.size();
    const int wish  = ranks_per_member > 0 ? std::max(1, size / ranks_per_member) : size;
    n_groups        = int(std::max<std::size_t>(1, std::min<std::size_t>(members, std::size_t(wish))));
    // contiguous blocks: rank r in group floor(r G / size), sizes differing by one at most
    my_group        = int(long(all.rank()) * n_groups / size);
    own             = n_groups > 1 ? all.split(my_group) : all;
  }

  int Ensemble::root_of(std::size_t m) const
  {
    // the first rank r with floor(r G / size) = g: ceil(g size / G)
    const long g = long(m % n_groups);
    return int((g * all.size() + n_groups - 1) / n_groups);
  }

  void Ensemble::share(std::vector<double> &values, std::size_t m) const
  {
    if (n_groups > 1)
      all.broadcast(values, root_of(m));
  }

  void Ensemble::share(std::string &text, std::size_t m) const
  {
    if (n_groups > 1)
      text = all.broadcast(text, root_of(m));
  }

  void Ensemble::fail_together(const std::exception_ptr &failure) const
  {
    all.fail_together(failure);
  }
} // namespace abrade::dem
