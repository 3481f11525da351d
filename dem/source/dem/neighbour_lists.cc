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
    const bool        distributed = m.parallel.distributed();
    const std::size_t n_old       = store.size();

    // 1. Grid over the particles that are still inside the domain (under MPI, with a margin of
    //    one interaction range for the ghosts).
    std::vector<char> keep(n_old, 1);
    Vec3              lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    double            r_max = 0;
    for (std::size_t i = 0; i < n_old; ++i)
      {
        const Vec3 p(store.x[i], store.y[i], store.z[i]);
        if (!(p.array() >= config.domain_min.array()).all() || !(p.array() <= config.domain_max.array()).all())
          {
            keep[i] = 0; // lost; reported by step() before we get here
            continue;
          }
        lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
        r_max = std::max(r_max, store.radius[i]);
      }
    if (lo[0] > hi[0])
      lo = hi = Vec3::Zero();
    r_max = m.parallel.max(r_max);
    const double cutoff = 2 * r_max + skin;
    if (distributed)
      lo -= Vec3::Constant(cutoff), hi += Vec3::Constant(cutoff);
    m.cell = std::max(cutoff, 1e-12);
    // keep the number of cells bounded (a few particles far apart must not allocate a huge grid)
    const double max_cells = 8.0 * std::max<std::size_t>(n_old, 64);
    while (((hi - lo) / m.cell).array().floor().prod() > max_cells)
      m.cell *= 1.5;
    m.lo = lo - Vec3::Constant(1e-9);
    m.nx = std::max(1L, long((hi[0] - m.lo[0]) / m.cell) + 1);
    m.ny = std::max(1L, long((hi[1] - m.lo[1]) / m.cell) + 1);
    m.nz = std::max(1L, long((hi[2] - m.lo[2]) / m.cell) + 1);
    const long n_cells = m.nx * m.ny * m.nz;

    // 2. Sort particles by cell (counting sort), dropping lost ones.
    const std::vector<std::size_t> order = m.sort_by_cell(store, 0, n_old, &keep, m.cell_start);
    const std::size_t              n     = order.size();
    store.permute(order, m.team());
    permute_wall_histories(order);
    store.n_distributed = store.size();

    // 3. The ghost layer, sorted by cell too.
    if (distributed)
      {
        exchange_ghosts(cutoff);
        sort_ghosts();
      }
    else
      m.ghost_cell_start.assign(n_cells + 1, static_cast<int>(n));
    const std::size_t n_local = store.n_local();
    m.one_material = n_local > 0 ? store.material[0] : -1;
    for (std::size_t i = 1; i < n_local && m.one_material >= 0; ++i)
      if (store.material[i] != m.one_material)
        m.one_material = -1;

    // 4. Half neighbour list: own cell (j > i) and the 13 forward neighbour cells for owned
    //    partners, all 27 cells for ghosts (each rank computes a pair across its boundary).
    //    The particles are sorted by cell and cells are numbered x fastest, so a row of three
    //    cells along x is one contiguous range of particles: the forward half is five ranges
    //    (the rest of the own cell with the cell after it, three cells of the next row, and
    //    three rows of three cells in the layer above), the ghosts nine. Each thread lists a
    //    contiguous block of rows into its own buffer (one pass, branch-free appends), and the
    //    blocks are then copied into place.
    const double *X = store.x.data(), *Y = store.y.data(), *Z = store.z.data(), *R = store.radius.data();
    const double  sk = skin;
    const bool    any_ghosts = store.n_ghost > 0;
    // the ranges of row i's candidates: begin/end pairs, returns their number
    auto candidate_ranges = [&](std::size_t i, int (&range)[2 * 14]) {
      const int *start = m.cell_start.data(), *ghost_start = m.ghost_cell_start.data();
      const long c  = m.cell_of(X[i], Y[i], Z[i]);
      const long ci = c % m.nx, cj = (c / m.nx) % m.ny, ck = c / (m.nx * m.ny);
      const long a0 = std::max(0L, ci - 1), a1 = std::min(m.nx - 1, ci + 1);
      int        n_ranges = 0;
      auto       add = [&](const int *first, long c0, long c1) { // cells c0 .. c1 (one row)
        range[2 * n_ranges] = first[c0], range[2 * n_ranges + 1] = first[c1 + 1], ++n_ranges;
      };
      range[0] = int(i) + 1, range[1] = start[(ci + 1 < m.nx ? c + 1 : c) + 1], n_ranges = 1;
      if (cj + 1 < m.ny)
        add(start, c + m.nx - ci + a0, c + m.nx - ci + a1);
      if (ck + 1 < m.nz)
        for (long b = std::max(0L, cj - 1); b <= std::min(m.ny - 1, cj + 1); ++b)
          {
            const long row = ((ck + 1) * m.ny + b) * m.nx;
            add(start, row + a0, row + a1);
          }
      if (any_ghosts)
        for (long d = std::max(0L, ck - 1); d <= std::min(m.nz - 1, ck + 1); ++d)
          for (long b = std::max(0L, cj - 1); b <= std::min(m.ny - 1, cj + 1); ++b)
            {
              const long row = (d * m.ny + b) * m.nx;
              add(ghost_start, row + a0, row + a1);
            }
      return n_ranges;
    };
    m.offsets.assign(n + 1, 0);
    std::vector<std::size_t> block(m.n_threads + 1, n);
    for (int t = 0; t < m.n_threads; ++t)
      block[t] = n * t / m.n_threads;
    std::vector<std::size_t> length(m.n_threads, 0);
    if (m.thread_lists.size() < std::size_t(m.n_threads))
      m.thread_lists.resize(m.n_threads);
#pragma omp parallel num_threads(m.team())
    for (int t = omp_get_thread_num(); t < m.n_threads; t += omp_get_num_threads())
      {
        std::vector<int> &list = m.thread_lists[t]; // its size is its capacity; used: its length
        std::size_t       used = 0;
        for (std::size_t i = block[t]; i < block[t + 1]; ++i)
          {
            int       range[2 * 14];
            const int n_ranges = candidate_ranges(i, range);
            std::size_t bound    = 0;
            for (int r = 0; r < n_ranges; ++r)
              bound += std::max(0, range[2 * r + 1] - range[2 * r]);
            if (list.size() < used + bound)
              list.resize(std::max(2 * list.size(), used + bound));
            int *__restrict out = list.data();
            std::size_t k = used;
            const double xi = X[i], yi = Y[i], zi = Z[i], ri = R[i] + sk;
            for (int r = 0; r < n_ranges; ++r)
              for (int j = range[2 * r]; j < range[2 * r + 1]; ++j)
                {
                  const double dx = xi - X[j], dy = yi - Y[j], dz = zi - Z[j];
                  const double cut = ri + R[j];
                  out[k] = j;
                  k += dx * dx + dy * dy + dz * dz < cut * cut;
                }
            used = k;
            m.offsets[i + 1] = k;
          }
        length[t] = used;
      }
    // offsets so far: each row's end within its thread's list
    for (int t = 0; t < m.n_threads; ++t)
      for (std::size_t i = block[t + 1]; i-- > block[t] + 1;)
        m.offsets[i + 1] -= m.offsets[i];
    for (std::size_t i = 0; i < n; ++i)
      m.offsets[i + 1] += m.offsets[i];
    if (m.offsets[n] > std::numeric_limits<unsigned>::max())
      throw RunError("the neighbour list of one process has more than 2^32 pairs: run on more MPI ranks");
    m.neighbours.resize(m.offsets[n]);
    m.row_of.resize(m.offsets[n]);
    m.shear.assign(m.history * m.offsets[n], 0.0);
    m.touching.assign(m.offsets[n], 0);
    const std::int64_t *ID = store.id.data();
#pragma omp parallel num_threads(m.team())
    for (int t = omp_get_thread_num(); t < m.n_threads; t += omp_get_num_threads())
      {
        std::copy_n(m.thread_lists[t].begin(), length[t], m.neighbours.begin() + m.offsets[block[t]]);
        // each slot's row, and the tangential history of pairs that had one, from the row's
        // carried list
        for (std::size_t i = block[t]; i < block[t + 1]; ++i)
          {
            std::fill(m.row_of.begin() + m.offsets[i], m.row_of.begin() + m.offsets[i + 1], int(i));
            const std::size_t row = order[i];
            if (!m.carries(row, ID[i]))
              continue;
            const std::size_t c0 = m.carried_offsets[row], c1 = m.carried_offsets[row + 1];
            for (std::size_t q = m.offsets[i]; q < m.offsets[i + 1] && c0 < c1; ++q)
              {
                const std::int64_t partner = ID[m.neighbours[q]];
                for (std::size_t c = c0; c < c1; ++c)
                  if (m.carried_partner[c] == partner)
                    {
                      for (int d = 0; d < m.history; ++d)
                        m.shear[m.history * q + d] = m.carried_shear[m.history * c + d];
                      m.touching[q] = 1;
                      break;
                    }
              }
          }
      }
    m.carried_owner.clear(); // used up

    // balanced ranges for the pair loop: equal shares of (pairs + a constant per particle)
    m.thread_begin.assign(m.n_threads + 1, n);
    m.thread_begin[0] = 0;
    {
      const double total = double(m.offsets[n]) + 4.0 * n;
      std::size_t  i     = 0;
      for (int t = 1; t < m.n_threads; ++t)
        {
          const double target = total * t / m.n_threads;
          while (i < n && double(m.offsets[i]) + 4.0 * i < target)
            ++i;
          m.thread_begin[t] = i;
        }
    }

    // 5. Wall candidates: owned particles within radius + skin of each triangle.
    std::vector<std::vector<std::array<int, 3>>> found(m.n_threads);
    for (std::size_t w = 0; w < walls.size(); ++w)
      {
        const Wall  &wall = walls[w];
        const double *V   = wall.current.data();
        // (which thread finds a candidate changes the order of a particle's candidates, not its
        // contacts: wall_forces sorts the hits by wall, distance, feature and triangle)
#pragma omp parallel for schedule(dynamic, 16) num_threads(m.team())
        for (std::size_t t = 0; t < wall.mesh.n_triangles(); ++t)
          {
            const auto   &tri = wall.mesh.triangles[t];
            const double *a = V + 3 * tri[0], *b = V + 3 * tri[1], *c = V + 3 * tri[2];
            long          lo_c[3], hi_c[3];
            const long    dims[3] = {m.nx, m.ny, m.nz};
            bool          empty   = false;
            for (int d = 0; d < 3; ++d)
              {
                const double mn = std::min({a[d], b[d], c[d]}) - r_max - sk;
                const double mx = std::max({a[d], b[d], c[d]}) + r_max + sk;
                lo_c[d] = std::max(0L, long(std::floor((mn - m.lo[d]) / m.cell)));
                hi_c[d] = std::min(dims[d] - 1, long(std::floor((mx - m.lo[d]) / m.cell)));
                empty |= lo_c[d] > hi_c[d];
              }
            if (empty)
              continue;
            auto &out = found[omp_get_thread_num()];
            for (long kk = lo_c[2]; kk <= hi_c[2]; ++kk)
              for (long jj = lo_c[1]; jj <= hi_c[1]; ++jj)
                for (long ii = lo_c[0]; ii <= hi_c[0]; ++ii)
                  {
                    const long cc = (kk * m.ny + jj) * m.nx + ii;
                    for (int p = m.cell_start[cc]; p < m.cell_start[cc + 1]; ++p)
                      {
                        const double q[3] = {X[p], Y[p], Z[p]};
                        const auto   cp   = closest_point_on_triangle(q, a, b, c);
                        const double dx = q[0] - cp.p[0], dy = q[1] - cp.p[1], dz = q[2] - cp.p[2];
                        const double cut = R[p] + sk;
                        if (dx * dx + dy * dy + dz * dz < cut * cut)
                          out.push_back({p, int(w), int(t)});
                      }
                  }
          }
      }
    m.wall_offsets.assign(n + 1, 0);
    for (const auto &f : found)
      for (const auto &e : f)
        ++m.wall_offsets[e[0] + 1];
    for (std::size_t i = 0; i < n; ++i)
      m.wall_offsets[i + 1] += m.wall_offsets[i];
    m.candidate_wall.resize(m.wall_offsets[n]);
    m.candidate_triangle.resize(m.wall_offsets[n]);
    {
      std::vector<std::size_t> fill(m.wall_offsets.begin(), m.wall_offsets.end() - 1);
      for (const auto &f : found)
        for (const auto &e : f)
          {
            const std::size_t k   = fill[e[0]]++;
            m.candidate_wall[k]     = e[1];
            m.candidate_triangle[k] = e[2];
          }
    }

    // the particles the wall pass visits; the others have no wall contact until the next build
    m.wall_particles.clear();
    for (std::size_t i = 0; i < n; ++i)
      if (m.wall_offsets[i + 1] > m.wall_offsets[i])
        m.wall_particles.push_back(static_cast<int>(i));
      else
        std::fill(&m.hist_wall[Impl::K * i], &m.hist_wall[Impl::K * i] + Impl::K, -1);

    // 6. Reference positions for the displacement criterion.
    m.x0.assign(store.x.begin(), store.x.begin() + n);
    m.y0.assign(store.y.begin(), store.y.begin() + n);
    m.z0.assign(store.z.begin(), store.z.begin() + n);
    m.max_displacement = 0;
    for (auto &w : walls)
      w.mark_build();
    for (auto &b : m.buffers)
      b.assign(7 * n_local, 0.0);
    m.force_rebuild = false;
    ++stats.rebuilds;
  }
} // namespace abrade::dem
