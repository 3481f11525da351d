// Domain decomposition of a Simulation under MPI: spreading the particles over the ranks,
// carrying pair histories across a rebuild, migrating particles to their new owner, and the
// ghost layer (built at every neighbour-list build, updated every step). In a serial run only
// carry_pair_histories() does anything.
#include "simulation_impl.h"

#include <abrade/common/error.h>

#include <omp.h>

#include <algorithm>
#include <array>
#include <numeric>
#include <tuple>

namespace abrade::dem
{
  namespace
  {
    /// What a ghost carries besides material and id: its state (x y z vx vy vz wx wy wz, the
    /// first Impl::ghost_state, updated every step), then radius and mass.
    std::array<std::vector<double> *, 11> ghost_arrays(ParticleStore &P)
    {
      return {&P.x, &P.y, &P.z, &P.vx, &P.vy, &P.vz, &P.wx, &P.wy, &P.wz, &P.radius, &P.mass};
    }
  } // namespace

  ParticleStore &Simulation::particles()
  {
    drop_ghosts();
    return store;
  }

  const Parallel &Simulation::parallel() const { return impl->parallel; }

  void Simulation::drop_ghosts()
  {
    if (store.n_ghost == 0)
      return;
    carry_pair_histories(); // the list still names the ghosts
    store.resize_arrays(store.size());
    impl->force_rebuild = true;
  }

  // Pair histories keyed by the partner's id, so that they survive the cell sort and a move to
  // another rank. A pair of two owned particles is recorded under both (with opposite signs), a
  // pair with a ghost under the owned particle only: the ghost's owner keeps its own copy.
  void Simulation::carry_pair_histories()
  {
    Impl &m = *impl;
    if (m.offsets.empty()) // no list, or already carried
      return;
    const std::size_t n = m.offsets.size() - 1, n_own = std::min(n, store.size());
    std::vector<std::size_t> count(n_own + 1, 0);
    const int H           = m.history;
    auto      has_history = [&m, H](std::size_t q) { // (the flag first: a slot not touching has no history)
      return m.touching[q] && std::any_of(&m.shear[H * q], &m.shear[H * q] + H, [](double x) { return x != 0; });
    };
    for (std::size_t i = 0; i < n_own; ++i)
      for (std::size_t q = m.offsets[i]; q < m.offsets[i + 1]; ++q)
        if (has_history(q))
          {
            ++count[i + 1];
            if (std::size_t(m.neighbours[q]) < n_own)
              ++count[m.neighbours[q] + 1];
          }
    std::partial_sum(count.begin(), count.end(), count.begin());
    m.carried_offsets = count;
    m.carried_partner.resize(count[n_own]);
    m.carried_shear.resize(H * count[n_own]);
    m.carried_owner.assign(store.id.begin(), store.id.begin() + n_own);
    std::vector<std::size_t> fill(count.begin(), count.end() - 1);
    for (std::size_t i = 0; i < n_own; ++i)
      for (std::size_t q = m.offsets[i]; q < m.offsets[i + 1]; ++q)
        if (has_history(q))
          {
            const std::size_t j = m.neighbours[q];
            std::size_t       a = fill[i]++;
            m.carried_partner[a] = store.id[j];
            for (int d = 0; d < H; ++d)
              m.carried_shear[H * a + d] = m.shear[H * q + d];
            if (j < n_own)
              {
                a = fill[j]++;
                m.carried_partner[a] = store.id[i];
                for (int d = 0; d < H; ++d) // (every history is antisymmetric: j's is minus i's)
                  m.carried_shear[H * a + d] = -m.shear[H * q + d];
              }
          }
    m.offsets.clear(); // the list is stale from here on
  }

  void Simulation::permute_wall_histories(const std::vector<std::size_t> &order)
  {
    Impl             &m = *impl;
    const std::size_t n = order.size();
    auto permute_slots = [&order, n](auto &v, int per) {
      std::remove_reference_t<decltype(v)> w(per * n);
      for (std::size_t k = 0; k < n; ++k)
        for (int s = 0; s < per; ++s)
          w[per * k + s] = v[per * order[k] + s];
      v.swap(w);
    };
    permute_slots(m.hist_wall, Impl::K);
    permute_slots(m.hist_tri, Impl::K);
    permute_slots(m.hist_shear, m.history * Impl::K);
    permute_slots(m.hist_used, Impl::K);
  }

  void Simulation::distribute_new_particles()
  {
    Impl &m = *impl;
    if (!m.parallel.distributed())
      {
        store.n_distributed = store.size();
        return;
      }
    drop_ghosts();
    const std::size_t first = std::min(store.n_distributed, store.size()), n = store.size();
    const double      added = double(n - first);
    double            id_sum = 0;
    for (std::size_t k = first; k < n; ++k)
      id_sum += double(store.id[k]);
    if (m.parallel.max(added) != m.parallel.min(added) || m.parallel.max(id_sum) != m.parallel.min(id_sum))
      throw RunError("under MPI every rank must add the same particles before Simulation::setup() (ranks added " +
                     std::to_string(long(m.parallel.min(added))) + " to " + std::to_string(long(m.parallel.max(added))) +
                     " particles, or different ones)");
    if (first == n)
      return;
    // keep every size-th new particle; the first build moves them to their owners
    std::vector<std::size_t> order(first);
    std::iota(order.begin(), order.end(), 0);
    for (std::size_t k = first; k < n; ++k)
      if (long(k - first) % m.parallel.size() == m.parallel.rank())
        order.push_back(k);
    m.resize_wall_histories(n);
    store.permute(order, m.team());
    permute_wall_histories(order);
    store.n_distributed = store.size();
    m.balanced          = false;
    m.force_rebuild     = true;
  }

  // Cuts the domains again if the counts are out of balance, then sends every particle outside
  // this rank's box to its owner with its wall and pair histories.
  void Simulation::rebalance_and_migrate()
  {
    Impl &m = *impl;
    if (!m.parallel.distributed())
      return;
    const std::size_t n = store.size();
    const double      largest = m.parallel.max(double(n)), mean = m.parallel.sum(double(n)) / m.parallel.size();
    const bool  cut = !m.balanced || largest > config.rebalance_threshold * mean; // (the same on all ranks)
    if (cut)
      {
        m.decomposition.balance(m.parallel, store.x.data(), store.y.data(), store.z.data(), n);
        m.balanced = true;
        ++stats.rebalances;
      }

    // who leaves for which rank (with its histories), who stays
    const int                        me = m.parallel.rank();
    std::vector<std::vector<double>> send(m.parallel.size());
    std::vector<std::size_t>         stay;
    stay.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
      if (const int r = m.decomposition.owner(store.x[i], store.y[i], store.z[i]); r == me)
        stay.push_back(i);
      else
        m.pack_migrant(store, i, send[r]);
    bool                      nearby = false;
    const std::vector<double> in     = m.exchange_migrants(send, cut, skin, nearby);
    stats.nearby_migrations += nearby;

    // the ones that stay, then the arrivals
    Impl::CarriedHistories carried = m.carried_histories_of(store, stay);
    stats.migrated += long(n - stay.size());
    store.permute(stay, m.team());
    permute_wall_histories(stay);
    stats.migrated += long(m.unpack_migrants(store, in, carried));
    m.carried_offsets.swap(carried.offsets);
    m.carried_partner.swap(carried.partner);
    m.carried_shear.swap(carried.shear);
    m.carried_owner.swap(carried.owner);
    store.n_distributed = store.size();
  }

  void Simulation::Impl::pack_migrant(const ParticleStore &P, std::size_t i, std::vector<double> &b) const
  {
    P.pack(i, b);
    for (int s = 0; s < K; ++s)
      {
        b.push_back(hist_wall[K * i + s]), b.push_back(hist_tri[K * i + s]), b.push_back(hist_used[K * i + s]);
        for (int d = 0; d < history; ++d)
          b.push_back(hist_shear[history * (K * i + s) + d]);
      }
    const bool        carried = carries(i, P.id[i]);
    const std::size_t c0 = carried ? carried_offsets[i] : 0, c1 = carried ? carried_offsets[i + 1] : 0;
    b.push_back(double(c1 - c0));
    for (std::size_t c = c0; c < c1; ++c)
      {
        b.push_back(pack_integer(carried_partner[c]));
        for (int d = 0; d < history; ++d)
          b.push_back(carried_shear[history * c + d]);
      }
  }

  std::vector<double> Simulation::Impl::exchange_migrants(const std::vector<std::vector<double>> &send, bool cut,
                                                          double skin, bool &nearby) const
  {
    // Between two cuts a particle moves less than a skin from one list build to the next (the
    // rebuild criterion), so it can only go to a neighbour of this box: then only the
    // neighbours exchange counts. Anything else (new cuts, particles placed by hand) is told
    // by one maximum over the ranks and falls back to the all-to-all.
    const std::vector<int> partners = decomposition.neighbours(parallel.rank(), skin);
    bool                   far      = false;
    for (int r = 0; r < parallel.size() && !far; ++r)
      far = !send[r].empty() && std::find(partners.begin(), partners.end(), r) == partners.end();
    nearby = !cut && !(parallel.max(far ? 1.0 : 0.0) > 0);
    return parallel.exchange(send, nullptr, nearby ? &partners : nullptr);
  }

  Simulation::Impl::CarriedHistories Simulation::Impl::carried_histories_of(const ParticleStore &P,
                                                                          const std::vector<std::size_t> &stay) const
  {
    CarriedHistories kept;
    kept.offsets.push_back(0);
    for (std::size_t i : stay)
      {
        kept.owner.push_back(P.id[i]);
        if (carries(i, P.id[i]))
          for (std::size_t c = carried_offsets[i]; c < carried_offsets[i + 1]; ++c)
            {
              kept.partner.push_back(carried_partner[c]);
              kept.shear.insert(kept.shear.end(), &carried_shear[history * c], &carried_shear[history * c] + history);
            }
        kept.offsets.push_back(kept.partner.size());
      }
    return kept;
  }

  std::size_t Simulation::Impl::unpack_migrants(ParticleStore &P, const std::vector<double> &in,
                                                CarriedHistories &carried)
  {
    std::size_t arrived = 0;
    for (std::size_t p = 0; p < in.size();)
      {
        const std::size_t i = P.unpack(&in[p]);
        p += ParticleStore::record_size;
        const int H = history;
        for (int s = 0; s < K; ++s, p += 3 + H)
          {
            hist_wall.push_back(int(in[p])), hist_tri.push_back(int(in[p + 1]));
            hist_used.push_back(static_cast<unsigned char>(in[p + 2]));
            hist_shear.insert(hist_shear.end(), &in[p + 3], &in[p + 3 + H]);
          }
        const std::size_t count = std::size_t(in[p++]);
        for (std::size_t c = 0; c < count; ++c, p += 1 + H)
          {
            carried.partner.push_back(unpack_integer(in[p]));
            carried.shear.insert(carried.shear.end(), &in[p + 1], &in[p + 1 + H]);
          }
        carried.owner.push_back(P.id[i]);
        carried.offsets.push_back(carried.partner.size());
        ++arrived;
      }
    return arrived;
  }

  // Ghosts: every owned particle within @p cutoff of another rank's box goes there (state,
  // radius, mass, material, id); what arrives is appended after the owned particles.
  void Simulation::exchange_ghosts(double cutoff)
  {
    Impl     &m  = *impl;
    const int me = m.parallel.rank(), P = m.parallel.size();
    m.ghost_send.assign(P, {});
    const Box        &mine = m.decomposition.box(me);
    const std::size_t n    = store.size();
    std::vector<int>  near;
    for (std::size_t i = 0; i < n; ++i)
      {
        const double x = store.x[i], y = store.y[i], z = store.z[i];
        if (mine.depth(x, y, z) >= cutoff) // deep inside: no other box is within reach
          continue;
        near.clear();
        m.decomposition.ranks_near(x, y, z, cutoff, me, near);
        for (int r : near)
          m.ghost_send[r].push_back(static_cast<int>(i));
      }
    const auto                       arrays = ghost_arrays(store);
    constexpr int                    record = std::tuple_size_v<decltype(arrays)> + 2; // + material, id
    std::vector<std::vector<double>> send(P);
    for (int r = 0; r < P; ++r)
      for (int i : m.ghost_send[r])
        {
          auto &b = send[r];
          for (const auto *a : arrays)
            b.push_back((*a)[i]);
          b.push_back(pack_integer(store.material[i]));
          b.push_back(pack_integer(store.id[i]));
        }
    // only ranks whose box is within the cutoff of this one can send ghosts here or get them
    std::vector<int>          counts;
    const std::vector<int>    near_boxes = m.decomposition.neighbours(me, cutoff);
    const std::vector<double> in         = m.parallel.exchange(send, &counts, &near_boxes);
    const std::size_t         ng = in.size() / record;
    m.ghost_receive_counts.resize(P);
    for (int r = 0; r < P; ++r)
      m.ghost_receive_counts[r] = counts[r] / record * Impl::ghost_state;
    store.resize_arrays(n + ng);
    store.n_ghost = ng;
    for (std::size_t k = 0; k < ng; ++k)
      {
        const double *g = &in[record * k];
        const std::size_t i = n + k;
        int               f = 0;
        for (auto *a : arrays)
          (*a)[i] = g[f++];
        store.material[i] = static_cast<int>(unpack_integer(g[f++]));
        store.id[i]       = unpack_integer(g[f++]);
      }
    m.ghost_slot.resize(ng);
    std::iota(m.ghost_slot.begin(), m.ghost_slot.end(), 0);
  }

  // Ghosts sorted by cell like the owned particles; ghost_slot remembers where each received
  // record went, for the updates.
  void Simulation::sort_ghosts()
  {
    Impl             &m = *impl;
    const std::size_t n = store.size(), ng = store.n_ghost;
    std::vector<std::size_t> order = m.sort_by_cell(store, n, ng, nullptr, m.ghost_cell_start);
    for (auto &s : m.ghost_cell_start)
      s += static_cast<int>(n);
    const std::size_t keep_ng = store.n_ghost;
    store.permute_range(n, order);
    store.n_ghost = keep_ng;
    m.ghost_slot = std::move(order);
  }

  // Every step between two builds: the ghosts' positions and velocities from their owners.
  void Simulation::update_ghosts()
  {
    Impl &m = *impl;
    if (!m.parallel.distributed())
      return;
    constexpr int S = Impl::ghost_state;
    const auto    arrays = ghost_arrays(store);
    const int     P = m.parallel.size();
    m.send_buffer.resize(P);
    for (int r = 0; r < P; ++r)
      {
        auto &b = m.send_buffer[r];
        b.resize(S * m.ghost_send[r].size());
        for (int a = 0; a < S; ++a)
          {
            const double *v = arrays[a]->data();
            for (std::size_t k = 0; k < m.ghost_send[r].size(); ++k)
              b[S * k + a] = v[m.ghost_send[r][k]];
          }
      }
    m.parallel.exchange_known(m.send_buffer, m.ghost_receive_counts, m.receive_buffer);
    const std::size_t n = store.size(), ng = store.n_ghost;
    const double     *in = m.receive_buffer.data();
    for (int a = 0; a < S; ++a)
      {
        double *v = arrays[a]->data() + n;
        for (std::size_t k = 0; k < ng; ++k)
          v[k] = in[S * m.ghost_slot[k] + a];
      }
  }

  // ---------------------------------------------------------------------------------------------
  // Global quantities
  // ---------------------------------------------------------------------------------------------

  std::size_t Simulation::n_particles() const { return std::size_t(impl->parallel.sum(long(store.size()))); }

  double Simulation::mass_above(double z) const { return impl->parallel.sum(store.mass_above(z)); }

  double Simulation::centre_of_mass_height() const
  {
    double mz = 0, m = 0;
    for (std::size_t i = 0; i < store.size(); ++i)
      mz += store.mass[i] * store.z[i], m += store.mass[i];
    std::vector<double> sums{mz, m};
    impl->parallel.sum(sums);
    return sums[1] > 0 ? sums[0] / sums[1] : 0.0;
  }

  double Simulation::largest_radius() const
  {
    double r = 0;
    for (std::size_t i = 0; i < store.size(); ++i)
      r = std::max(r, store.radius[i]);
    return impl->parallel.max(r);
  }

  double Simulation::throughput(const StepStatistics &before, const StepStatistics &after) const
  {
    return impl->parallel.sum(double(after.particle_steps - before.particle_steps)) /
           std::max(1e-12, impl->parallel.max(after.loop_seconds - before.loop_seconds));
  }

  ParticleStore Simulation::gather_particles() const
  {
    std::vector<double> local;
    local.reserve(ParticleStore::record_size * store.size());
    for (std::size_t i = 0; i < store.size(); ++i)
      store.pack(i, local);
    const std::vector<double> all = impl->parallel.gather(local);
    ParticleStore             out;
    for (std::size_t p = 0; p < all.size(); p += ParticleStore::record_size)
      out.unpack(&all[p]);
    if (impl->parallel.distributed())
      {
        std::vector<std::size_t> order(out.size());
        std::iota(order.begin(), order.end(), 0);
        std::sort(order.begin(), order.end(), [&out](std::size_t a, std::size_t b) { return out.id[a] < out.id[b]; });
        out.permute(order);
      }
    out.n_distributed = out.size();
    return out;
  }
} // namespace abrade::dem
