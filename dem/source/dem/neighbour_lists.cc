// Neighbour lists of a Simulation: the cell grid, the particle-particle half list with its
// tangential histories, and the particle-wall candidates. Built when a particle (or a wall) has
// moved far enough since the last build to bring a new pair within reach (Verlet skin).
//
// Order of a build: carry the pair histories out of the old list (keyed by id); under MPI drop
// the ghosts, rebalance and migrate; drop lost particles and sort the owned ones by cell; under
// MPI fetch the new ghost layer and sort it by cell; build the lists, picking up each pair's
// history by the partner's id; find the wall candidates.
#include "simulation_impl.h"

#include <abrade/common/closest_point.h>
#include <abrade/common/error.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace abrade::dem
{
  std::vector<std::size_t> Simulation::Impl::sort_by_cell(const ParticleStore &P, std::size_t first,
                                                         std::size_t count, const std::vector<char> *keep,
                                                         std::vector<int> &start) const
  {
    const long        n_cells = nx * ny * nz;
    std::vector<long> cell_index(count);
    start.assign(n_cells + 1, 0);
    for (std::size_t k = 0; k < count; ++k)
      if (!keep || (*keep)[k])
        {
          const std::size_t i = first + k;
          cell_index[k]       = cell_of(P.x[i], P.y[i], P.z[i]);
          ++start[cell_index[k] + 1];
        }
    for (long c = 0; c < n_cells; ++c)
      start[c + 1] += start[c];
    std::vector<std::size_t> order(start[n_cells]);
    std::vector<int>         fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < count; ++k)
      if (!keep || (*keep)[k])
        order[fill[cell_index[k]]++] = k;
    return order;
  }

  void Simulation::build_neighbour_lists()
  {
    Impl &m = *impl;
    carry_pair_histories();
    drop_ghosts();
    if (store.n_distributed != store.size() && m.parallel.distributed())
      distribute_new_particles();
    m.resize_wall_histories(store.size()); // particles added since the last build: no histories yet
    rebalance_and_migrate();

    // 1. Grid over the particles that are still inside the domain.
    std::vector<char> keep(store.size(), 1);
    double            cutoff = 0;
    const double      r_max  = m.make_grid(store, config.domain_min, config.domain_max, skin, keep, cutoff);

    // 2. Sort particles by cell (counting sort), dropping lost ones.
    const std::vector<std::size_t> order = m.sort_by_cell(store, 0, store.size(), &keep, m.cell_start);
    store.permute(order, m.team());
    permute_wall_histories(order);
    store.n_distributed = store.size();

    // 3. The ghost layer, sorted by cell too.
    if (m.parallel.distributed())
      {
        exchange_ghosts(cutoff);
        sort_ghosts();
      }
    else
      m.ghost_cell_start.assign(m.nx * m.ny * m.nz + 1, static_cast<int>(store.size()));
    const std::size_t n_local = store.n_local();
    m.one_material = n_local > 0 ? store.material[0] : -1;
    for (std::size_t i = 1; i < n_local && m.one_material >= 0; ++i)
      if (store.material[i] != m.one_material)
        m.one_material = -1;

    // 4. The pairs, with their histories, and the pair loop's shares.
    m.list_pairs(store, skin);
    m.pick_up_pair_histories(store, order);
    m.balance_pair_shares(store.size());

    // 5. Wall candidates: owned particles within radius + skin of each triangle.
    m.find_wall_candidates(store, walls, r_max, skin);

    // 6. Reference positions for the displacement criterion.
    const std::size_t n = store.size();
    m.x0.assign(store.x.begin(), store.x.begin() + n);
    m.y0.assign(store.y.begin(), store.y.begin() + n);
    m.z0.assign(store.z.begin(), store.z.begin() + n);
    m.max_displacement = 0;
    for (auto &w : walls)
      w.mark_build();
    for (auto &b : m.buffers) // (each step zeroes what its share touches: share_spans)
      b.resize(7 * n_local);
    m.force_rebuild = false;
    ++stats.rebuilds;
  }

  double Simulation::Impl::make_grid(const ParticleStore &P, const Vec3 &domain_min, const Vec3 &domain_max,
                                     double skin, std::vector<char> &keep, double &cutoff)
  {
    const std::size_t n_old = P.size();
    Vec3              lo_p = Vec3::Constant(1e300), hi_p = Vec3::Constant(-1e300);
    double            r_max = 0;
    for (std::size_t i = 0; i < n_old; ++i)
      {
        const Vec3 p(P.x[i], P.y[i], P.z[i]);
        if (!(p.array() >= domain_min.array()).all() || !(p.array() <= domain_max.array()).all())
          {
            keep[i] = 0; // lost; reported by step() before we get here
            continue;
          }
        lo_p = lo_p.cwiseMin(p), hi_p = hi_p.cwiseMax(p);
        r_max = std::max(r_max, P.radius[i]);
      }
    if (lo_p[0] > hi_p[0])
      lo_p = hi_p = Vec3::Zero();
    r_max  = parallel.max(r_max);
    cutoff = 2 * r_max + skin;
    if (parallel.distributed())
      lo_p -= Vec3::Constant(cutoff), hi_p += Vec3::Constant(cutoff);
    cell = std::max(cutoff, 1e-12);
    // keep the number of cells bounded (a few particles far apart must not allocate a huge grid)
    const double max_cells = 8.0 * std::max<std::size_t>(n_old, 64);
    while (((hi_p - lo_p) / cell).array().floor().prod() > max_cells)
      cell *= 1.5;
    lo = lo_p - Vec3::Constant(1e-9);
    nx = std::max(1L, long((hi_p[0] - lo[0]) / cell) + 1);
    ny = std::max(1L, long((hi_p[1] - lo[1]) / cell) + 1);
    nz = std::max(1L, long((hi_p[2] - lo[2]) / cell) + 1);
    return r_max;
  }

  int Simulation::Impl::candidate_ranges(std::size_t i, const double *X, const double *Y, const double *Z,
                                         bool any_ghosts, int (&range)[2 * 14]) const
  {
    const int *start = cell_start.data(), *ghost_start = ghost_cell_start.data();
    const long c  = cell_of(X[i], Y[i], Z[i]);
    const long ci = c % nx, cj = (c / nx) % ny, ck = c / (nx * ny);
    const long a0 = std::max(0L, ci - 1), a1 = std::min(nx - 1, ci + 1);
    int        n_ranges = 0;
    auto       add = [&](const int *first, long c0, long c1) { // cells c0 .. c1 (one row)
      range[2 * n_ranges] = first[c0], range[2 * n_ranges + 1] = first[c1 + 1], ++n_ranges;
    };
    range[0] = int(i) + 1, range[1] = start[(ci + 1 < nx ? c + 1 : c) + 1], n_ranges = 1;
    if (cj + 1 < ny)
      add(start, c + nx - ci + a0, c + nx - ci + a1);
    if (ck + 1 < nz)
      for (long b = std::max(0L, cj - 1); b <= std::min(ny - 1, cj + 1); ++b)
        {
          const long row = ((ck + 1) * ny + b) * nx;
          add(start, row + a0, row + a1);
        }
    if (any_ghosts)
      for (long d = std::max(0L, ck - 1); d <= std::min(nz - 1, ck + 1); ++d)
        for (long b = std::max(0L, cj - 1); b <= std::min(ny - 1, cj + 1); ++b)
          {
            const long row = (d * ny + b) * nx;
            add(ghost_start, row + a0, row + a1);
          }
    return n_ranges;
  }

  void Simulation::Impl::list_pairs(const ParticleStore &P, double skin)
  {
    // Own cell (j > i) and the 13 forward neighbour cells for owned partners, all 27 cells for
    // ghosts (each rank computes a pair across its boundary). The particles are sorted by cell
    // and cells are numbered x fastest, so a row of three cells along x is one contiguous range
    // of particles: the forward half is five ranges (the rest of the own cell with the cell
    // after it, three cells of the next row, and three rows of three cells in the layer
    // above), the ghosts nine. Each share lists a contiguous block of rows into its own buffer
    // (one pass, branch-free appends), and the blocks are then copied into place.
    const std::size_t n = P.size();
    const double *X = P.x.data(), *Y = P.y.data(), *Z = P.z.data(), *R = P.radius.data();
    const bool    any_ghosts = P.n_ghost > 0;
    offsets.assign(n + 1, 0);
    std::vector<std::size_t> block(n_threads + 1, n);
    for (int t = 0; t < n_threads; ++t)
      block[t] = n * t / n_threads;
    std::vector<std::size_t> length(n_threads, 0);
    if (thread_lists.size() < std::size_t(n_threads))
      thread_lists.resize(n_threads);
#pragma omp parallel num_threads(team())
    for (int t = omp_get_thread_num(); t < n_threads; t += omp_get_num_threads())
      {
        std::vector<int> &list = thread_lists[t]; // its size is its capacity; used: its length
        std::size_t       used = 0;
        for (std::size_t i = block[t]; i < block[t + 1]; ++i)
          {
            int       range[2 * 14];
            const int n_ranges = candidate_ranges(i, X, Y, Z, any_ghosts, range);
            std::size_t bound    = 0;
            for (int r = 0; r < n_ranges; ++r)
              bound += std::max(0, range[2 * r + 1] - range[2 * r]);
            if (list.size() < used + bound)
              list.resize(std::max(2 * list.size(), used + bound));
            int *__restrict out = list.data();
            std::size_t k = used;
            const double xi = X[i], yi = Y[i], zi = Z[i], ri = R[i] + skin;
            for (int r = 0; r < n_ranges; ++r)
              for (int j = range[2 * r]; j < range[2 * r + 1]; ++j)
                {
                  const double dx = xi - X[j], dy = yi - Y[j], dz = zi - Z[j];
                  const double cut = ri + R[j];
                  out[k] = j;
                  k += dx * dx + dy * dy + dz * dz < cut * cut;
                }
            used = k;
            offsets[i + 1] = k;
          }
        length[t] = used;
      }
    // offsets so far: each row's end within its share's list
    for (int t = 0; t < n_threads; ++t)
      for (std::size_t i = block[t + 1]; i-- > block[t] + 1;)
        offsets[i + 1] -= offsets[i];
    for (std::size_t i = 0; i < n; ++i)
      offsets[i + 1] += offsets[i];
    if (offsets[n] > std::numeric_limits<unsigned>::max())
      throw RunError("the neighbour list of one process has more than 2^32 pairs: run on more MPI ranks");
    neighbours.resize(offsets[n]);
    row_of.resize(offsets[n]);
#pragma omp parallel num_threads(team())
    for (int t = omp_get_thread_num(); t < n_threads; t += omp_get_num_threads())
      {
        std::copy_n(thread_lists[t].begin(), length[t], neighbours.begin() + offsets[block[t]]);
        for (std::size_t i = block[t]; i < block[t + 1]; ++i)
          std::fill(row_of.begin() + offsets[i], row_of.begin() + offsets[i + 1], int(i));
      }
  }

  void Simulation::Impl::pick_up_pair_histories(const ParticleStore &P, const std::vector<std::size_t> &order)
  {
    const std::size_t n = P.size();
    shear.assign(history * offsets[n], 0.0);
    touching.assign(offsets[n], 0);
    const std::int64_t *ID = P.id.data();
#pragma omp parallel for schedule(static) num_threads(team())
    for (std::size_t i = 0; i < n; ++i)
      {
        const std::size_t row = order[i];
        if (!carries(row, ID[i]))
          continue;
        const std::size_t c0 = carried_offsets[row], c1 = carried_offsets[row + 1];
        for (std::size_t q = offsets[i]; q < offsets[i + 1] && c0 < c1; ++q)
          {
            const std::int64_t partner = ID[neighbours[q]];
            for (std::size_t c = c0; c < c1; ++c)
              if (carried_partner[c] == partner)
                {
                  for (int d = 0; d < history; ++d)
                    shear[history * q + d] = carried_shear[history * c + d];
                  touching[q] = 1;
                  break;
                }
          }
      }
    carried_owner.clear(); // used up
  }

  void Simulation::Impl::balance_pair_shares(std::size_t n)
  {
    thread_begin.assign(n_threads + 1, n);
    thread_begin[0]    = 0;
    const double total = double(offsets[n]) + 4.0 * n;
    std::size_t  i     = 0;
    for (int t = 1; t < n_threads; ++t)
      {
        const double target = total * t / n_threads;
        while (i < n && double(offsets[i]) + 4.0 * i < target)
          ++i;
        thread_begin[t] = i;
      }
    // what each share's pairs touch (its buffer's extent)
    share_spans.assign(n_threads, {});
    for (int t = 0; t < n_threads; ++t)
      {
        ShareSpan &s = share_spans[t];
        s.owned_begin = thread_begin[t], s.owned_end = thread_begin[t + 1];
        s.ghost_begin = std::numeric_limits<std::size_t>::max(), s.ghost_end = 0;
        for (std::size_t k = offsets[thread_begin[t]]; k < offsets[thread_begin[t + 1]]; ++k)
          {
            const std::size_t j = std::size_t(neighbours[k]);
            if (j < n)
              s.owned_begin = std::min(s.owned_begin, j), s.owned_end = std::max(s.owned_end, j + 1);
            else
              s.ghost_begin = std::min(s.ghost_begin, j), s.ghost_end = std::max(s.ghost_end, j + 1);
          }
        if (s.ghost_begin >= s.ghost_end)
          s.ghost_begin = s.ghost_end = n;
      }
  }

  void Simulation::Impl::find_wall_candidates(const ParticleStore &P, const std::vector<Wall> &walls, double r_max,
                                              double skin)
  {
    const std::size_t n = P.size();
    const double *X = P.x.data(), *Y = P.y.data(), *Z = P.z.data(), *R = P.radius.data();
    std::vector<std::vector<std::array<int, 3>>> found(n_threads);
    for (std::size_t w = 0; w < walls.size(); ++w)
      {
        const Wall   &wall = walls[w];
        const double *V    = wall.current.data();
        // (which thread finds a candidate changes the order of a particle's candidates, not its
        // contacts: wall_forces sorts the hits by wall, distance, feature and triangle)
#pragma omp parallel for schedule(dynamic, 16) num_threads(team())
        for (std::size_t t = 0; t < wall.mesh.n_triangles(); ++t)
          {
            const auto   &tri = wall.mesh.triangles[t];
            const double *a = V + 3 * tri[0], *b = V + 3 * tri[1], *c = V + 3 * tri[2];
            long          lo_c[3], hi_c[3];
            const long    dims[3] = {nx, ny, nz};
            bool          empty   = false;
            for (int d = 0; d < 3; ++d)
              {
                const double mn = std::min({a[d], b[d], c[d]}) - r_max - skin;
                const double mx = std::max({a[d], b[d], c[d]}) + r_max + skin;
                lo_c[d] = std::max(0L, long(std::floor((mn - lo[d]) / cell)));
                hi_c[d] = std::min(dims[d] - 1, long(std::floor((mx - lo[d]) / cell)));
                empty |= lo_c[d] > hi_c[d];
              }
            if (empty)
              continue;
            auto &out = found[omp_get_thread_num()];
            for (long kk = lo_c[2]; kk <= hi_c[2]; ++kk)
              for (long jj = lo_c[1]; jj <= hi_c[1]; ++jj)
                for (long ii = lo_c[0]; ii <= hi_c[0]; ++ii)
                  {
                    const long cc = (kk * ny + jj) * nx + ii;
                    for (int p = cell_start[cc]; p < cell_start[cc + 1]; ++p)
                      {
                        const double q[3] = {X[p], Y[p], Z[p]};
                        const auto   cp   = closest_point_on_triangle(q, a, b, c);
                        const double dx = q[0] - cp.p[0], dy = q[1] - cp.p[1], dz = q[2] - cp.p[2];
                        const double cut = R[p] + skin;
                        if (dx * dx + dy * dy + dz * dz < cut * cut)
                          out.push_back({p, int(w), int(t)});
                      }
                  }
          }
      }
    wall_offsets.assign(n + 1, 0);
    for (const auto &f : found)
      for (const auto &e : f)
        ++wall_offsets[e[0] + 1];
    for (std::size_t i = 0; i < n; ++i)
      wall_offsets[i + 1] += wall_offsets[i];
    candidate_wall.resize(wall_offsets[n]);
    candidate_triangle.resize(wall_offsets[n]);
    std::vector<std::size_t> fill(wall_offsets.begin(), wall_offsets.end() - 1);
    for (const auto &f : found)
      for (const auto &e : f)
        {
          const std::size_t k   = fill[e[0]]++;
          candidate_wall[k]     = e[1];
          candidate_triangle[k] = e[2];
        }

    // the particles the wall pass visits; the others have no wall contact until the next build
    wall_particles.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (wall_offsets[i + 1] > wall_offsets[i])
        wall_particles.push_back(static_cast<int>(i));
      else
        std::fill(&hist_wall[K * i], &hist_wall[K * i] + K, -1);
  }
} // namespace abrade::dem
