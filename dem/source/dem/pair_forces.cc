// Particle-particle Hertz-Mindlin forces over the half neighbour list, in three passes per batch
// of pairs so that the arithmetic vectorises:
//
//  1. scan the list (scalar, one stream over its pairs): distance test, queue the pairs in
//     contact (i, j, list slot, and the centres' difference and radii the test computed), and
//     forget the history of a pair whose contact ended (told by the slot's one-byte 'touching'
//     flag, so a history is read only for pairs in contact);
//  2. contact forces of the whole batch in one SIMD loop (gathers of the particles' mass and
//     velocities and the pair's history: the loop is bound by its gathers, and the scan's
//     values save eight of nineteen; no branches: selects; the pair coefficients are loop
//     constants when all particles share one material);
//  3. add the forces, torques and rolling resistances to both particles and the histories to
//     their slots (scalar: two pairs may share a particle).
//
// The contact law is the one the wall contacts use (ContactLaw::evaluate, contact_law.h), with
// the sub-models chosen at run time compiled in (one instantiation per combination); it is
// branch-free, so the batch loop vectorises. The particle-particle verification tests (Hertz
// impact, Chung & Ooi oblique impacts, rolling, cohesion) run through this kernel.
#include "simulation_impl.h"

#include <abrade/dem/contact_law.h>

#include <omp.h>

#include <algorithm>
#include <cmath>

namespace abrade::dem
{
  namespace
  {
    /// Pairs in contact, queued for the vectorised force pass: only their indices (the scan
    /// stores three integers per listed pair; the force pass gathers the rest).
    struct PairBatch
    {
      static constexpr int capacity    = 256;
      static constexpr int max_history = 6;
      int                  n = 0;
      int                  i[capacity], j[capacity];
      unsigned             slot[capacity];
      // what the scan computed for its contact test: the centres' difference and the radii
      // (the force pass would otherwise gather them again: it is bound by its gathers)
      double               dx[capacity], dy[capacity], dz[capacity], ri[capacity], rj[capacity];
      double               h[max_history][capacity]; // the pair's history, out
      // results: force on i (j gets the opposite), n x ft for the torques, constant-torque
      // rolling resistances mu_r |F_n| r of i and j or the rolling model's torque on i (j gets
      // the opposite), overlap / smaller radius
      double fx[capacity], fy[capacity], fz[capacity];
      double cx[capacity], cy[capacity], cz[capacity];
      double roll_i[capacity], roll_j[capacity];
      double mx[capacity], my[capacity], mz[capacity];
      double ratio[capacity];
    };

    /// The particles' arrays the force pass reads.
    struct ParticleArrays
    {
      const double *X, *Y, *Z, *R, *M, *VX, *VY, *VZ, *WX, *WY, *WZ;
      const int    *MAT;
      const double *SHEAR; // history per list slot
    };

    /// The neighbour list as the scan reads it: per pair (list slot) its row and column
    /// particle, and the contact flags and histories it updates.
    struct ListArrays
    {
      const int *__restrict ROW, *__restrict NEIGHBOURS;
      unsigned char *__restrict TOUCHING;
      double *__restrict SHEAR;
      int H; ///< history doubles per slot

      /// Slot @p k's contact began or ended: flag it; an ended contact forgets its history.
      void contact_changed(std::size_t k, bool touching) const
      {
        TOUCHING[k] = touching;
        if (!touching)
          std::fill(SHEAR + H * k, SHEAR + H * (k + 1), 0.0);
      }
    };

    // 1. Queue the pairs in contact among list slots k .. k_end - 1 until the batch is full;
    //    returns the first slot not scanned. One stream over the list (each slot's row is
    //    stored with it), not row by row: rows are short (about five pairs) and a loop per row
    //    costs more than its pairs. Branch-free: every pair goes to the next free batch entry,
    //    which is kept only if the pair is in contact (a branch would be mispredicted about
    //    half the time in a dense bed). (An AVX-512 version with gathers and compression was
    //    slower than this loop on the AMD EPYC of docs/benchmarks.md.)
    inline std::size_t scan_pairs(PairBatch &B, const ParticleArrays &in, const ListArrays &L, std::size_t k,
                                  std::size_t k_end)
    {
      const double *__restrict X = in.X, *__restrict Y = in.Y, *__restrict Z = in.Z, *__restrict R = in.R;
      const int *__restrict ROW = L.ROW, *__restrict NEIGHBOURS = L.NEIGHBOURS;
      int nb = B.n;
      for (; k < k_end && nb < PairBatch::capacity; ++k)
        {
          const int    i = ROW[k], j = NEIGHBOURS[k];
          const double dx = X[i] - X[j], dy = Y[i] - Y[j], dz = Z[i] - Z[j];
          const double ri = R[i], rj = R[j];
          const double sr = ri + rj;
          const bool   touching = dx * dx + dy * dy + dz * dz < sr * sr;
          B.i[nb] = i, B.j[nb] = j, B.slot[nb] = static_cast<unsigned>(k);
          B.dx[nb] = dx, B.dy[nb] = dy, B.dz[nb] = dz, B.ri[nb] = ri, B.rj[nb] = rj;
          nb += touching;
          if (touching != bool(L.TOUCHING[k]))
            L.contact_changed(k, touching);
        }
      B.n = nb;
      return k;
    }

    // 2. the batch's contact forces (uniform: all pairs have the coefficients *COEF)
    template <bool rotation, bool uniform, class Law>
    void batch_forces(PairBatch &B, const ParticleArrays &in, const PairCoefficients *__restrict COEF,
                      std::size_t nm, double dt)
    {
      constexpr int          H  = Law::history;
      const PairCoefficients c0 = COEF[0];
      const double *__restrict S = in.SHEAR;
      const double *__restrict M = in.M, *__restrict VX = in.VX, *__restrict VY = in.VY,
                               *__restrict VZ = in.VZ, *__restrict WX = in.WX, *__restrict WY = in.WY,
                               *__restrict WZ = in.WZ;
      const int *__restrict MAT = in.MAT;
      const int nb = B.n;
      // (ivdep, not 'omp simd': OpenMP's simd lowering runs before inlining and turns the
      // contact law's history and state, whose addresses evaluate() takes, into per-lane arrays
      // with scatter stores, which defeats the vectoriser; after inlining GCC vectorises the
      // loop on its own, 8 pairs at a time with AVX-512)
#pragma GCC ivdep
      for (int b = 0; b < nb; ++b)
        {
          const int    i = B.i[b], j = B.j[b];
          const double ri = B.ri[b], rj = B.rj[b], mi = M[i], mj = M[j];
          // one division for 1/d, R* = ri rj / sr and m* = mi mj / (mi + mj)
          const double dx = B.dx[b], dy = B.dy[b], dz = B.dz[b];
          const double d  = std::sqrt(dx * dx + dy * dy + dz * dz);
          const double sr = ri + rj;
          // (the scan's contact test summed r2 in scalar code: a pair at the edge of contact may
          // come out a rounding error apart here)
          const double msum  = mi + mj;
          const double q     = 1 / (d * sr * msum);
          const double inv_d = sr * msum * q;
          ContactState cs;
          cs.overlap = std::max(sr - d, 0.0);
          cs.nx = dx * inv_d, cs.ny = dy * inv_d, cs.nz = dz * inv_d;
          cs.r_eff = ri * rj * (d * msum * q);
          cs.m_eff = mi * mj * (d * sr * q);
          double vx = VX[i] - VX[j], vy = VY[i] - VY[j], vz = VZ[i] - VZ[j];
          if (rotation)
            {
              // - (ri w_i + rj w_j) x n
              const double ax = ri * WX[i] + rj * WX[j], ay = ri * WY[i] + rj * WY[j], az = ri * WZ[i] + rj * WZ[j];
              vx -= ay * cs.nz - az * cs.ny;
              vy -= az * cs.nx - ax * cs.nz;
              vz -= ax * cs.ny - ay * cs.nx;
            }
          cs.vx = vx, cs.vy = vy, cs.vz = vz;
          if constexpr (Law::needs_rotation)
            {
              cs.wx = WX[i] - WX[j], cs.wy = WY[i] - WY[j], cs.wz = WZ[i] - WZ[j];
              const double ii = rolling_inertia_of_sphere(mi, ri), ij = rolling_inertia_of_sphere(mj, rj);
              cs.rolling_inertia = ii * ij / (ii + ij);
            }
          if constexpr (Law::needs_area) // the circle the two spheres intersect in
            cs.area = -M_PI / 4 * (d - ri - rj) * (d + ri - rj) * (d - ri + rj) * (d + ri + rj) / (d * d);
          const PairCoefficients &c = uniform ? c0 : COEF[MAT[i] * nm + MAT[j]];

          const unsigned k = B.slot[b];
          double         h[H];
#pragma GCC unroll 6
          for (int e = 0; e < H; ++e)
            h[e] = S[H * k + e];
          const ContactResponse f = Law::evaluate(cs, c, dt, h);
#pragma GCC unroll 6
          for (int e = 0; e < H; ++e)
            B.h[e][b] = h[e];

          B.fx[b] = f.normal * cs.nx + f.ftx, B.fy[b] = f.normal * cs.ny + f.fty, B.fz[b] = f.normal * cs.nz + f.ftz;
          if (rotation)
            {
              B.cx[b] = cs.ny * f.ftz - cs.nz * f.fty, B.cy[b] = cs.nz * f.ftx - cs.nx * f.ftz,
              B.cz[b] = cs.nx * f.fty - cs.ny * f.ftx;
              B.roll_i[b] = f.rolling_limit * ri, B.roll_j[b] = f.rolling_limit * rj;
              B.mx[b] = f.mx, B.my[b] = f.my, B.mz[b] = f.mz;
            }
          B.ratio[b] = cs.overlap / (ri < rj ? ri : rj);
        }
    }
  } // namespace

  void Simulation::pair_forces()
  {
    with_contact_law(config.contact, [&](auto law) {
      using Law = decltype(law);
      if (any_rotation)
        pair_forces_with<true, Law>();
      else
        pair_forces_with<false, Law>();
    });
  }

  // The pair kernel, one function of about a hundred lines on purpose: the scan of the
  // neighbour list, the batched contact law and the scatter of the forces share one parallel
  // region and its restrict-qualified pointers, in one body for the compiler to see whole. A
  // split is a change to the engine's hottest loop, to be made with its own interleaved
  // benchmark (bench/knife_bed.sh with ABRADE_BASELINE), not as a tidy-up.
  template <bool rotation, class Law>
  void Simulation::pair_forces_with()
  {
    static_assert(Law::history <= PairBatch::max_history);
    constexpr int     H  = Law::history;
    Impl             &m  = *impl;
    const std::size_t n  = store.n_local(); // owned and ghosts (forces on ghosts are dropped)
    const std::size_t nm = mats.size();
    const double      dt = time_step;
    ParticleStore    &P  = store;
    const double *__restrict X = P.x.data(), *__restrict Y = P.y.data(), *__restrict Z = P.z.data(),
                             *__restrict R = P.radius.data(), *__restrict WX = P.wx.data(),
                             *__restrict WY = P.wy.data(), *__restrict WZ = P.wz.data();
    double *__restrict SHEAR = m.shear.data();
    unsigned char *__restrict TOUCHING = m.touching.data();
    const std::size_t *__restrict OFFSETS    = m.offsets.data();
    const int *__restrict NEIGHBOURS         = m.neighbours.data();
    const ParticleArrays    in{X, Y, Z, R, P.mass.data(), P.vx.data(), P.vy.data(), P.vz.data(), WX, WY, WZ,
                            P.material.data(), SHEAR};
    const PairCoefficients *COEF = coefficients.data();
    const ListArrays        list{m.row_of.data(), NEIGHBOURS, TOUCHING, SHEAR, H};

    double worst = 0;
    long   wi = -1, wj = -1;
#pragma omp parallel num_threads(m.team())
    {
      // Each share of the pairs adds its forces into its own buffer (share 0: the particle
      // arrays), whichever thread works on it, so the sums do not depend on the team.
      const int tid  = omp_get_thread_num();
      const int team = omp_get_num_threads();
      double   *fx, *fy, *fz, *tx, *ty, *tz, *rl;
      auto      use_buffer_of = [&](int range) {
        // share 0's are every particle's sums, zeroed whole; another share's buffer only where
        // its pairs add (Impl::share_spans: the rest is never read)
        auto zero = [&](std::size_t begin, std::size_t end) {
          for (double *a : {fx, fy, fz})
            std::fill(a + begin, a + end, 0.0);
          if (rotation)
            for (double *a : {tx, ty, tz, rl})
              std::fill(a + begin, a + end, 0.0);
        };
        if (range == 0)
          {
            fx = P.fx.data(), fy = P.fy.data(), fz = P.fz.data(), tx = P.tx.data(), ty = P.ty.data(),
            tz = P.tz.data(), rl = P.rolling.data();
            zero(0, n);
          }
        else
          {
            double *b = m.buffers[range].data();
            fx = b, fy = b + n, fz = b + 2 * n, tx = b + 3 * n, ty = b + 4 * n, tz = b + 5 * n, rl = b + 6 * n;
            const auto &span = m.share_spans[range];
            zero(span.owned_begin, span.owned_end);
            zero(span.ghost_begin, span.ghost_end);
          }
      };
      double my_worst = 0;
      long   my_i = -1, my_j = -1;

      PairBatch B;

      // 2. the batch's forces, 3. onto both particles and the histories back to their slots
      auto flush = [&]() {
        if (m.one_material >= 0)
          batch_forces<rotation, true, Law>(B, in, COEF + m.one_material * (nm + 1), nm, dt);
        else
          batch_forces<rotation, false, Law>(B, in, COEF, nm, dt);
        for (int b = 0; b < B.n; ++b)
          {
            const int i = B.i[b], j = B.j[b];
            double   *s = SHEAR + H * std::size_t(B.slot[b]);
            for (int e = 0; e < H; ++e)
              s[e] = B.h[e][b];
            fx[i] += B.fx[b], fy[i] += B.fy[b], fz[i] += B.fz[b];
            fx[j] -= B.fx[b], fy[j] -= B.fy[b], fz[j] -= B.fz[b];
            if (rotation)
              {
                // torque on i: (-ri n) x ft, on j: (rj n) x (-ft); rolling resistance
                const double ri = R[i], rj = R[j];
                tx[i] -= ri * B.cx[b], ty[i] -= ri * B.cy[b], tz[i] -= ri * B.cz[b];
                tx[j] -= rj * B.cx[b], ty[j] -= rj * B.cy[b], tz[j] -= rj * B.cz[b];
                if constexpr (Law::constant_torque)
                  rl[i] += B.roll_i[b], rl[j] += B.roll_j[b];
                else
                  tx[i] += B.mx[b], ty[i] += B.my[b], tz[i] += B.mz[b], tx[j] -= B.mx[b], ty[j] -= B.my[b],
                    tz[j] -= B.mz[b];
              }
            if (B.ratio[b] > my_worst)
              my_worst = B.ratio[b], my_i = i, my_j = j;
          }
        B.n = 0;
      };

      // every share is done, whatever the size of the team OpenMP gave us
      for (int range = tid; range < m.n_threads; range += team)
        {
          use_buffer_of(range);
          std::size_t       k     = OFFSETS[m.thread_begin[range]];
          const std::size_t k_end = OFFSETS[m.thread_begin[range + 1]];
          while ((k = scan_pairs(B, in, list, k, k_end)) < k_end)
            flush();
          flush();
        }
#pragma omp critical
      if (my_worst > worst || (my_worst == worst && my_i >= 0 && (wi < 0 || my_i < wi)))
        worst = my_worst, wi = my_i, wj = my_j;
    }
    m.worst_overlap_ratio = worst;
    m.worst_overlap_i     = wi;
    m.worst_overlap_j     = wj;
  }

} // namespace abrade::dem
