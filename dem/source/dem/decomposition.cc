// The particles spread over MPI ranks by recursive coordinate bisection (decomposition.h).
#include <abrade/dem/decomposition.h>

#include <cmath>

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
    const double *coordinate[3] = {x, y, z};

    // Parts still to cut: a node of the tree, its ranks [first, last) and its box.
    struct Part
    {
      int node, first, last;
      Box box;
    };
    std::vector<Part> parts{{0, 0, P, Box()}};
    std::vector<int>  part_of(n, 0); // index into parts, for this rank's particles

    while (!parts.empty())
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

        std::vector<int>    axis(np, 0);
        std::vector<double> lo(np), hi(np), target(np);
        for (std::size_t s = 0; s < np; ++s)
          {
            double best = -1;
            for (int d = 0; d < 3; ++d)
              {
                const double e = extent[6 * s + 3 + d] + extent[6 * s + d];
                if (e > best)
                  best = e, axis[s] = d;
              }
            lo[s] = -extent[6 * s + axis[s]], hi[s] = extent[6 * s + 3 + axis[s]];
            if (!(total[s] > 0)) // no particles: cut the box (or space) anywhere
              lo[s] = hi[s] = 0;
            const int mid = parts[s].first + (parts[s].last - parts[s].first) / 2;
            target[s]     = std::round(total[s] * (mid - parts[s].first) / double(parts[s].last - parts[s].first));
          }
        // bisection on every part's cut plane at once: the plane below which `target` lie
        std::vector<double> cut(np), below(np);
        for (int iteration = 0; iteration < 64; ++iteration)
          {
            for (std::size_t s = 0; s < np; ++s)
              cut[s] = 0.5 * (lo[s] + hi[s]);
            std::fill(below.begin(), below.end(), 0.0);
            for (std::size_t i = 0; i < n; ++i)
              {
                const int s = part_of[i];
                if (s >= 0)
                  below[s] += coordinate[axis[s]][i] < cut[s];
              }
            parallel.sum(below);
            bool done = true;
            for (std::size_t s = 0; s < np; ++s)
              {
                if (below[s] == target[s])
                  continue;
                done = false;
                (below[s] < target[s] ? lo[s] : hi[s]) = cut[s];
              }
            if (done)
              break;
          }

        // children
        std::vector<Part> next;
        std::vector<int>  first_child(np);
        for (std::size_t s = 0; s < np; ++s)
          {
            const Part p   = parts[s];
            const int  mid = p.first + (p.last - p.first) / 2;
            const int  l   = static_cast<int>(nodes.size());
            nodes[p.node].axis = axis[s], nodes[p.node].cut = cut[s], nodes[p.node].left = l;
            nodes.emplace_back(), nodes.emplace_back();
            Box left = p.box, right = p.box;
            left.hi[axis[s]] = right.lo[axis[s]] = cut[s];
            const Part children[2] = {{l, p.first, mid, left}, {l + 1, mid, p.last, right}};
            nodes[l].box = left, nodes[l + 1].box = right;
            first_child[s] = static_cast<int>(next.size());
            for (const Part &c : children)
              {
                if (c.last - c.first == 1)
                  {
                    nodes[c.node].rank = c.first;
                    boxes[c.first]     = c.box;
                  }
                next.push_back(c); // finished children stay in the list until the particles move on
              }
          }
        // particles into the children; drop the finished parts
        std::vector<int> renumber(next.size(), -1);
        std::vector<Part> open;
        for (std::size_t c = 0; c < next.size(); ++c)
          if (next[c].last - next[c].first > 1)
            renumber[c] = static_cast<int>(open.size()), open.push_back(next[c]);
        for (std::size_t i = 0; i < n; ++i)
          {
            const int s = part_of[i];
            if (s < 0)
              continue;
            const int c = first_child[s] + (coordinate[axis[s]][i] < cut[s] ? 0 : 1);
            part_of[i]  = renumber[c]; // -1: in a finished box
          }
        parts.swap(open);
      }
  }
} // namespace abrade::dem
