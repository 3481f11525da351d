// The particles spread over MPI ranks by recursive coordinate bisection (decomposition.h).
#include <abrade/dem/decomposition.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace abrade::dem
{
  void Decomposition::reset(int n_ranks)
  {
    nodes.assign(1, Node());
    boxes.assign(n_ranks, Box());
  }

  void Decomposition::balance(const Parallel &parallel, const double *x, const double *y, const double *z,
                              std::size_t n)
  {
    const int P = parallel.size();
    reset(P);
    if (P == 1)
      return;
    const double *const coordinate[3] = {x, y, z};
    std::vector<Part>   parts{{0, 0, P, Box()}};
    std::vector<int>    part_of(n, 0); // index into parts, for this rank's particles; -1: in a finished box
    while (!parts.empty())
      {
        Cuts cuts = axes_and_targets(parallel, coordinate, n, parts, part_of);
        bisect(parallel, coordinate, n, part_of, cuts);
        parts = split(parts, cuts, coordinate, n, part_of);
      }
  }

  Decomposition::Cuts Decomposition::axes_and_targets(const Parallel &parallel, const double *const coordinate[3],
                                                      std::size_t n, const std::vector<Part> &parts,
                                                      const std::vector<int> &part_of)
  {
    const std::size_t np = parts.size();
    // extent of each part's particles: max of (-lo, hi)
    std::vector<double> extent(6 * np, -std::numeric_limits<double>::infinity());
    std::vector<double> total(np, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      {
        const int s = part_of[i];
        if (s < 0)
          continue;
        total[s] += 1;
        for (int d = 0; d < 3; ++d)
          {
            extent[6 * s + d]     = std::max(extent[6 * s + d], -coordinate[d][i]);
            extent[6 * s + 3 + d] = std::max(extent[6 * s + 3 + d], coordinate[d][i]);
          }
      }
    parallel.max(extent);
    parallel.sum(total);

    Cuts c;
    c.axis.assign(np, 0), c.lo.resize(np), c.hi.resize(np), c.target.resize(np), c.cut.resize(np);
    for (std::size_t s = 0; s < np; ++s)
      {
        double best = -1;
        for (int d = 0; d < 3; ++d)
          {
            const double e = extent[6 * s + 3 + d] + extent[6 * s + d];
            if (e > best)
              best = e, c.axis[s] = d;
          }
        c.lo[s] = -extent[6 * s + c.axis[s]], c.hi[s] = extent[6 * s + 3 + c.axis[s]];
        if (!(total[s] > 0)) // no particles: cut the box (or space) anywhere
          c.lo[s] = c.hi[s] = 0;
        const int mid = parts[s].first + (parts[s].last - parts[s].first) / 2;
        c.target[s]   = std::round(total[s] * (mid - parts[s].first) / double(parts[s].last - parts[s].first));
      }
    return c;
  }

  void Decomposition::bisect(const Parallel &parallel, const double *const coordinate[3], std::size_t n,
                             const std::vector<int> &part_of, Cuts &c)
  {
    // every part's cut plane at once: the plane below which `target` lie
    const std::size_t   np = c.axis.size();
    std::vector<double> below(np);
    for (int iteration = 0; iteration < 64; ++iteration)
      {
        for (std::size_t s = 0; s < np; ++s)
          c.cut[s] = 0.5 * (c.lo[s] + c.hi[s]);
        std::fill(below.begin(), below.end(), 0.0);
        for (std::size_t i = 0; i < n; ++i)
          {
            const int s = part_of[i];
            if (s >= 0)
              below[s] += coordinate[c.axis[s]][i] < c.cut[s];
          }
        parallel.sum(below);
        bool done = true;
        for (std::size_t s = 0; s < np; ++s)
          {
            if (below[s] == c.target[s])
              continue;
            done = false;
            (below[s] < c.target[s] ? c.lo[s] : c.hi[s]) = c.cut[s];
          }
        if (done)
          break;
      }
  }

  std::vector<Decomposition::Part> Decomposition::split(const std::vector<Part> &parts, const Cuts &c,
                                                        const double *const coordinate[3], std::size_t n,
                                                        std::vector<int> &part_of)
  {
    // the children, as nodes of the tree; a child of one rank is that rank's box
    const std::size_t np = parts.size();
    std::vector<Part> next;
    std::vector<int>  first_child(np);
    for (std::size_t s = 0; s < np; ++s)
      {
        const Part p   = parts[s];
        const int  mid = p.first + (p.last - p.first) / 2;
        const int  l   = static_cast<int>(nodes.size());
        nodes[p.node].axis = c.axis[s], nodes[p.node].cut = c.cut[s], nodes[p.node].left = l;
        nodes.emplace_back(), nodes.emplace_back();
        Box left = p.box, right = p.box;
        left.hi[c.axis[s]] = right.lo[c.axis[s]] = c.cut[s];
        const Part children[2] = {{l, p.first, mid, left}, {l + 1, mid, p.last, right}};
        nodes[l].box = left, nodes[l + 1].box = right;
        first_child[s] = static_cast<int>(next.size());
        for (const Part &child : children)
          {
            if (child.last - child.first == 1)
              {
                nodes[child.node].rank = child.first;
                boxes[child.first]     = child.box;
              }
            next.push_back(child); // finished children stay in the list until the particles move on
          }
      }
    // particles into the children; drop the finished parts
    std::vector<int>  renumber(next.size(), -1);
    std::vector<Part> open;
    for (std::size_t k = 0; k < next.size(); ++k)
      if (next[k].last - next[k].first > 1)
        renumber[k] = static_cast<int>(open.size()), open.push_back(next[k]);
    for (std::size_t i = 0; i < n; ++i)
      {
        const int s = part_of[i];
        if (s < 0)
          continue;
        const int k = first_child[s] + (coordinate[c.axis[s]][i] < c.cut[s] ? 0 : 1);
        part_of[i]  = renumber[k]; // -1: in a finished box
      }
    return open;
  }
} // namespace abrade::dem
