// Particle-wall forces (Simulation::wall_forces): per particle with wall candidates, the
// triangles it touches, one contact per touching region of a wall (wall_contacts.h), each with
// its tangential history slot and the same ContactLaw as the pairs (contact_law.h); the forces
// and torques onto the particle, the reactions onto the walls' loads, a record of each contact
// in the contact log. Before them, every thread adds the pair forces of the shares other than
// the first (their buffers) and gravity.
//
// (A batched version, queueing the contacts and evaluating the law in one vectorised loop as
// the pair forces do, was slower on the knife-bed: the law is a small part of a wall contact's
// cost, and the queue's extra loads and stores cost more than the vectorisation saved.)
#include "simulation_impl.h"
#include "wall_contacts.h"

#include <abrade/dem/contact_law.h>

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace abrade::dem
{
  namespace
  {
    /// Every particle: the pair forces of the shares other than the first (in their buffers:
    /// force, torque, rolling; n_local apart; each over the owned particles its pairs touch,
    /// @p spans: Impl::share_spans) added in share order, then gravity. Called by every thread
    /// of a parallel region: each adds into its own block of particles, in share order, and
    /// waits for the others.
    template <bool rotation, class Spans>
    void add_pair_buffers_and_gravity(ParticleStore &P, const std::vector<std::vector<double>> &buffers,
                                      const Spans &spans, int n_shares, std::size_t n, std::size_t nl,
                                      const Vec3 &g)
    {
      double *__restrict FX = P.fx.data(), *__restrict FY = P.fy.data(), *__restrict FZ = P.fz.data();
      double *__restrict TX = P.tx.data(), *__restrict TY = P.ty.data(), *__restrict TZ = P.tz.data();
      double *__restrict ROLL = P.rolling.data();
      const double *__restrict MASS = P.mass.data();
      const auto [mine_begin, mine_end] = share(n, omp_get_thread_num(), omp_get_num_threads());
      for (int b = 1; b < n_shares; ++b)
        {
          const double *__restrict buf = buffers[b].data();
          const std::size_t begin = std::max(mine_begin, spans[b].owned_begin);
          const std::size_t end   = std::min(mine_end, spans[b].owned_end);
#pragma omp simd
          for (std::size_t i = begin; i < end; ++i)
            {
              FX[i] += buf[i], FY[i] += buf[nl + i], FZ[i] += buf[2 * nl + i];
              if (rotation)
                TX[i] += buf[3 * nl + i], TY[i] += buf[4 * nl + i], TZ[i] += buf[5 * nl + i],
                  ROLL[i] += buf[6 * nl + i];
            }
        }
      const double gx = g[0], gy = g[1], gz = g[2];
#pragma omp simd
      for (std::size_t i = mine_begin; i < mine_end; ++i)
        FX[i] += MASS[i] * gx, FY[i] += MASS[i] * gy, FZ[i] += MASS[i] * gz;
#pragma omp barrier
    }

    /// What a particle's wall contacts add up to in a step: force, torque, rolling torque.
    struct ParticleSums
    {
      double fx, fy, fz, tx = 0, ty = 0, tz = 0, rolling = 0;
    };

    /// One particle-wall contact: particle @p i touching @p wall at hit @p h (accepted), with
    /// its tangential history @p history (@p began: new). Its force and torque are added to
    /// @p sums, the reaction (-F at the contact point, its torque about the wall's centre) to
    /// the wall's load @p L, and the contact is recorded in @p r. Returns the overlap over the
    /// radius.
    template <bool rotation, class Law>
    [[gnu::always_inline]] inline double wall_contact(const ParticleStore &P, std::size_t i,
                                                      const wall_contacts::Hit &h, const Wall &wall,
                                                      const PairCoefficients &c, double dt, double *history,
                                                      bool began, ParticleSums &sums, double *L,
                                                      WallContactRecord &r)
    {
      const double ri      = P.radius[i];
      const double q[3]    = {P.x[i], P.y[i], P.z[i]};
      const double d       = std::sqrt(h.d2);
      const double nv[3]   = {(q[0] - h.p[0]) / d, (q[1] - h.p[1]) / d, (q[2] - h.p[2]) / d};
      const double overlap = ri - d;
      const Vec3   vw      = wall.velocity_at(Vec3(h.p[0], h.p[1], h.p[2]));
      double       vrel[3] = {P.vx[i] - vw[0], P.vy[i] - vw[1], P.vz[i] - vw[2]};
      if (rotation)
        {
          // w x (-r n)
          vrel[0] -= ri * (P.wy[i] * nv[2] - P.wz[i] * nv[1]);
          vrel[1] -= ri * (P.wz[i] * nv[0] - P.wx[i] * nv[2]);
          vrel[2] -= ri * (P.wx[i] * nv[1] - P.wy[i] * nv[0]);
        }
      ContactState cs;
      cs.nx = nv[0], cs.ny = nv[1], cs.nz = nv[2], cs.overlap = overlap;
      cs.r_eff = ri, cs.m_eff = P.mass[i];
      cs.vx = vrel[0], cs.vy = vrel[1], cs.vz = vrel[2];
      if constexpr (Law::needs_rotation)
        {
          const Vec3 &ww = wall.angular_velocity;
          cs.wx = P.wx[i] - ww[0], cs.wy = P.wy[i] - ww[1], cs.wz = P.wz[i] - ww[2];
          cs.rolling_inertia = rolling_inertia_of_sphere(P.mass[i], ri);
        }
      if constexpr (Law::needs_area)
        cs.area = M_PI * (ri * ri - d * d);
      const ContactResponse f    = Law::evaluate(cs, c, dt, history);
      const double          ft[3] = {f.ftx, f.fty, f.ftz};
      const double F[3] = {f.normal * nv[0] + f.ftx, f.normal * nv[1] + f.fty, f.normal * nv[2] + f.ftz};
      sums.fx += F[0], sums.fy += F[1], sums.fz += F[2];
      if (rotation)
        {
          sums.tx -= ri * (nv[1] * ft[2] - nv[2] * ft[1]);
          sums.ty -= ri * (nv[2] * ft[0] - nv[0] * ft[2]);
          sums.tz -= ri * (nv[0] * ft[1] - nv[1] * ft[0]);
          if constexpr (Law::constant_torque)
            sums.rolling += f.rolling_limit * ri;
          else
            sums.tx += f.mx, sums.ty += f.my, sums.tz += f.mz;
        }
      const Vec3 arm = Vec3(h.p[0], h.p[1], h.p[2]) - wall.current_centre();
      L[0] -= F[0], L[1] -= F[1], L[2] -= F[2];
      L[3] -= arm[1] * F[2] - arm[2] * F[1];
      L[4] -= arm[2] * F[0] - arm[0] * F[2];
      L[5] -= arm[0] * F[1] - arm[1] * F[0];
      if constexpr (!Law::constant_torque) // a rolling torque on the particle acts back
        if (rotation)
          L[3] -= f.mx, L[4] -= f.my, L[5] -= f.mz;

      r.wall = h.wall, r.triangle = h.tri, r.feature = h.feature;
      r.particle = static_cast<int>(i), r.particle_id = P.id[i];
      const double vt[3] = {f.vtx, f.vty, f.vtz};
      for (int dd = 0; dd < 3; ++dd)
        {
          r.point[dd] = h.p[dd], r.normal[dd] = nv[dd];
          r.tangential_force[dd] = ft[dd], r.tangential_velocity[dd] = vt[dd];
        }
      r.normal_force = f.normal, r.normal_velocity = f.vn, r.overlap = overlap;
      r.centre_velocity[0] = P.vx[i] - vw[0], r.centre_velocity[1] = P.vy[i] - vw[1],
      r.centre_velocity[2] = P.vz[i] - vw[2];
      r.began = began;
      return overlap / ri;
    }

    /// The walls' loads summed over the shares (@p loads: 6 per wall, force and torque, per
    /// share) and the ranks into each wall's force and torque, and every rank's worst overlap
    /// ratio (@p own_worst: this rank's) in one sum over the ranks: the largest, @p worst_all,
    /// and its rank, @p worst_rank, are known everywhere.
    void sum_wall_loads(std::vector<std::vector<double>> &loads, const Parallel &parallel, std::vector<Wall> &walls,
                        double own_worst, int &worst_rank, double &worst_all)
    {
      const std::size_t    nw    = walls.size();
      std::vector<double> &total = loads[0];
      total.resize(6 * nw + parallel.size());
      for (std::size_t b = 1; b < loads.size(); ++b)
        for (std::size_t k = 0; k < 6 * nw; ++k)
          total[k] += loads[b][k];
      std::fill(total.begin() + 6 * nw, total.end(), 0.0);
      total[6 * nw + parallel.rank()] = own_worst;
      parallel.sum(total);
      for (std::size_t w = 0; w < nw; ++w)
        {
          walls[w].force  = Vec3(total[6 * w], total[6 * w + 1], total[6 * w + 2]);
          walls[w].torque = Vec3(total[6 * w + 3], total[6 * w + 4], total[6 * w + 5]);
        }
      worst_rank = static_cast<int>(std::max_element(total.begin() + 6 * nw, total.end()) - total.begin() - 6 * nw);
      worst_all  = total[6 * nw + worst_rank];
      total.resize(6 * nw);
    }
  } // namespace

  template <bool rotation, class Law>
  void Simulation::wall_forces_with()
  {
    Impl             &m  = *impl;
    constexpr int     H  = Law::history;
    constexpr int     K  = Impl::K;
    ParticleStore    &P  = store;
    const wall_contacts::Histories<K, H> histories{m.hist_wall.data(), m.hist_tri.data(), m.hist_used.data(),
                                                   m.hist_shear.data()};
    const std::size_t nm = mats.size();

    double worst = 0;
    long   worst_i = -1;
#pragma omp parallel num_threads(m.team())
    {
      const int tid  = omp_get_thread_num();
      const int team = omp_get_num_threads();
      double    my_worst = 0;
      long      my_i     = -1;
      wall_contacts::Hit hits[wall_contacts::max_hits];
      int                accepted[wall_contacts::max_hits];

      add_pair_buffers_and_gravity<rotation>(P, m.buffers, m.share_spans, m.n_threads, store.size(), store.n_local(),
                                             config.gravity);

      // the particles with wall candidates: particle-wall contacts, in m.n_threads shares
      // (each with its own loads and contact list), whatever the team
      const std::size_t n_wall = m.wall_particles.size();
      for (int range = tid; range < m.n_threads; range += team)
        {
          auto &loads = m.wall_loads[range];
          std::fill(loads.begin(), loads.end(), 0.0);
          auto &log = m.log.per_thread[range];
          log.clear();
          const auto [w_begin, w_end] = share(n_wall, range, m.n_threads);
          for (std::size_t w_i = w_begin; w_i < w_end; ++w_i)
            {
              const std::size_t i    = m.wall_particles[w_i];
              const double      ri   = P.radius[i];
              const double      q[3] = {P.x[i], P.y[i], P.z[i]};
              ParticleSums      sums{P.fx[i], P.fy[i], P.fz[i]};
              if (rotation)
                sums.tx = P.tx[i], sums.ty = P.ty[i], sums.tz = P.tz[i], sums.rolling = P.rolling[i];

              const int n_hits = wall_contacts::find_hits(q, ri, walls, m.candidate_wall.data(),
                                                          m.candidate_triangle.data(), m.wall_offsets[i],
                                                          m.wall_offsets[i + 1], hits);
              histories.start(i);
              const int n_acc = n_hits > 0 ? wall_contacts::accept_contacts(hits, n_hits, walls, ri, accepted) : 0;
              for (int a = 0; a < n_acc; ++a)
                {
                  const wall_contacts::Hit &h    = hits[accepted[a]];
                  const Wall               &wall = walls[h.wall];
                  bool                      began = false;
                  double                    scratch[H] = {}; // (the history of a contact not kept)
                  double                   *history    = histories.claim(i, h, wall, began);
                  const double ratio = wall_contact<rotation, Law>(
                    P, i, h, wall, coefficients[P.material[i] * nm + wall.material], time_step,
                    history ? history : scratch, began, sums, &loads[6 * h.wall], log.emplace_back());
                  if (ratio > my_worst)
                    my_worst = ratio, my_i = i;
                }
              histories.finish(i);

              P.fx[i] = sums.fx, P.fy[i] = sums.fy, P.fz[i] = sums.fz;
              if (rotation)
                P.tx[i] = sums.tx, P.ty[i] = sums.ty, P.tz[i] = sums.tz, P.rolling[i] = sums.rolling;
            }
        }
#pragma omp critical
      if (my_worst > worst || (my_worst == worst && my_i >= 0 && my_i < worst_i))
        worst = my_worst, worst_i = my_i;
    }
    if (worst > m.worst_overlap_ratio)
      {
        m.worst_overlap_ratio = worst;
        m.worst_overlap_i     = worst_i;
        m.worst_overlap_j     = -1;
      }
    sum_wall_loads(m.wall_loads, m.parallel, walls, m.worst_overlap_ratio, m.worst_overlap_rank, m.worst_overlap_all);
  }

  void Simulation::wall_forces()
  {
    with_contact_law(config.contact, [&](auto law) {
      using Law = decltype(law);
      if (any_rotation)
        wall_forces_with<true, Law>();
      else
        wall_forces_with<false, Law>();
    });
  }

} // namespace abrade::dem
