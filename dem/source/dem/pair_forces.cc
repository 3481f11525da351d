// Particle-particle Hertz-Mindlin forces over the half neighbour list, in three passes per batch
// of pairs so that the arithmetic vectorises:
//
//  1. scan the list (scalar, one stream over its pairs): distance test, queue the pairs in
//     contact (i, j, list slot: three integers), and forget the history of a pair whose contact
//     ended (told by the slot's one-byte 'touching' flag, so a history is read only for pairs in
//     contact);
//  2. contact forces of the whole batch in one SIMD loop (gathers of the particles' position,
//     radius, mass, velocities and the pair's history; no branches: selects; the pair
//     coefficients are loop constants when all particles share one material);
//  3. add the forces, torques and rolling resistances to both particles and the histories to
//     their slots (scalar: two pairs may share a particle).
//
// The arithmetic is that of hertz_mindlin() (hertz_mindlin.h, used for the wall contacts),
// written out for the batch with its branches as selects; the particle-particle verification
// tests (Hertz impact, Chung & Ooi oblique impacts, rolling) run through this kernel.
#include "simulation_impl.h"

#include <abrade/dem/hertz_mindlin.h>

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
      static constexpr int capacity = 256;
      int                  n = 0;
      int                  i[capacity], j[capacity];
      unsigned             slot[capacity];
      double               s0[capacity], s1[capacity], s2[capacity]; // the pair's history, out
      // results: force on i (j gets the opposite), n x ft for the torques, rolling-resistance
      // torques mu_r |F_n| r of i and j, overlap / smaller radius
      double fx[capacity], fy[capacity], fz[capacity];
      double cx[capacity], cy[capacity], cz[capacity];
      double roll_i[capacity], roll_j[capacity];
      double ratio[capacity];
    };

    /// The particles' arrays the force pass reads.
    struct ParticleArrays
    {
      const double *X, *Y, *Z, *R, *M, *VX, *VY, *VZ, *WX, *WY, *WZ;
      const int    *MAT;
      const double *SHEAR; // 3 per list slot
    };

    /// The neighbour list as the scan reads it: per pair (list slot) its row and column
    /// particle, and the contact flags and histories it updates.
    struct ListArrays
    {
      const int *__restrict ROW, *__restrict NEIGHBOURS;
      unsigned char *__restrict TOUCHING;
      double *__restrict SHEAR;

      /// Slot @p k's contact began or ended: flag it; an ended contact forgets its history.
      void contact_changed(std::size_t k, bool touching) const
      {
        TOUCHING[k] = touching;
        if (!touching)
          SHEAR[3 * k] = SHEAR[3 * k + 1] = SHEAR[3 * k + 2] = 0;
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
          const double sr = R[i] + R[j];
          const bool   touching = dx * dx + dy * dy + dz * dz < sr * sr;
          B.i[nb] = i, B.j[nb] = j, B.slot[nb] = static_cast<unsigned>(k);
          nb += touching;
          if (touching != bool(L.TOUCHING[k]))
            L.contact_changed(k, touching);
        }
      B.n = nb;
      return k;
    }

    // 2. the batch's contact forces (uniform: all pairs have the coefficients *COEF)
    template <bool rotation, bool uniform>
    void batch_forces(PairBatch &B, const ParticleArrays &in, const PairCoefficients *__restrict COEF,
                      std::size_t nm, double dt)
    {
      const PairCoefficients c0 = COEF[0];
      const double *__restrict X = in.X, *__restrict Y = in.Y, *__restrict Z = in.Z, *__restrict S = in.SHEAR;
      const double *__restrict R = in.R, *__restrict M = in.M, *__restrict VX = in.VX, *__restrict VY = in.VY,
                               *__restrict VZ = in.VZ, *__restrict WX = in.WX, *__restrict WY = in.WY,
                               *__restrict WZ = in.WZ;
      const int *__restrict MAT = in.MAT;
        const int nb = B.n;
#pragma omp simd
      for (int b = 0; b < nb; ++b)
        {
          const int    i = B.i[b], j = B.j[b];
          const double ri = R[i], rj = R[j], mi = M[i], mj = M[j];
          // one division for 1/d, R* = ri rj / sr and m* = mi mj / (mi + mj)
          const double dx = X[i] - X[j], dy = Y[i] - Y[j], dz = Z[i] - Z[j];
          const double d       = std::sqrt(dx * dx + dy * dy + dz * dz);
          const double sr      = ri + rj;
          // (the scan's contact test summed r2 in scalar code: a pair at the edge of contact may
          // come out a rounding error apart here)
          const double overlap = std::max(sr - d, 0.0);
          const double msum    = mi + mj;
          const double q       = 1 / (d * sr * msum);
          const double inv_d   = sr * msum * q;
          const double nx = dx * inv_d, ny = dy * inv_d, nz = dz * inv_d;
          const double r_eff = ri * rj * (d * msum * q);
          const double m_eff = mi * mj * (d * sr * q);
          double       vx = VX[i] - VX[j], vy = VY[i] - VY[j], vz = VZ[i] - VZ[j];
          if (rotation)
            {
              // - (ri w_i + rj w_j) x n
              const double ax = ri * WX[i] + rj * WX[j], ay = ri * WY[i] + rj * WY[j], az = ri * WZ[i] + rj * WZ[j];
              vx -= ay * nz - az * ny;
              vy -= az * nx - ax * nz;
              vz -= ax * ny - ay * nx;
            }
          const PairCoefficients &c = uniform ? c0 : COEF[MAT[i] * nm + MAT[j]];

          // hertz_mindlin(), branch-free
          const double vn  = vx * nx + vy * ny + vz * nz;
          const double vtx = vx - vn * nx, vty = vy - vn * ny, vtz = vz - vn * nz;
          const double sqrt_rd = std::sqrt(r_eff * overlap);
          const double s_t     = 8 * c.g_star * sqrt_rd;
          const double f_el    = (4.0 / 3.0) * c.e_star * sqrt_rd * overlap;
          const double w       = c.damping > 0 ? c.damping * std::sqrt(sqrt_rd * m_eff) : 0.0;
          const double normal  = f_el - w * c.sqrt_2e * vn;

          const unsigned k  = B.slot[b];
          double         s0 = S[3 * k], s1 = S[3 * k + 1], s2 = S[3 * k + 2];
          const double sn = s0 * nx + s1 * ny + s2 * nz;
          const double m0 = s0 * s0 + s1 * s1 + s2 * s2;
          const double m1 = m0 - sn * sn;
          const double rr = m1 > 0 ? sn * sn / m1 : 0.0;
          const double scale = rr < 1e-5 ? 1 + rr * (0.5 - 0.125 * rr) : std::sqrt(1 + rr);
          const bool   lost  = sn != 0 && !(m1 > 0);
          s0 = lost ? 0.0 : (s0 - sn * nx) * scale;
          s1 = lost ? 0.0 : (s1 - sn * ny) * scale;
          s2 = lost ? 0.0 : (s2 - sn * nz) * scale;
          s0 += vtx * dt, s1 += vty * dt, s2 += vtz * dt;

          const double fs0 = -s_t * s0, fs1 = -s_t * s1, fs2 = -s_t * s2;
          const double fsq       = fs0 * fs0 + fs1 * fs1 + fs2 * fs2;
          const double f_coulomb = c.friction * std::abs(normal);
          const bool   sliding   = fsq > f_coulomb * f_coulomb;
          const double ratio     = sliding ? f_coulomb / std::sqrt(fsq) : 1.0;
          const double ct        = w * c.sqrt_8g;
          const double ftx = sliding ? fs0 * ratio : fs0 - ct * vtx;
          const double fty = sliding ? fs1 * ratio : fs1 - ct * vty;
          const double ftz = sliding ? fs2 * ratio : fs2 - ct * vtz;
          B.s0[b] = sliding ? s0 * ratio : s0;
          B.s1[b] = sliding ? s1 * ratio : s1;
          B.s2[b] = sliding ? s2 * ratio : s2;

          B.fx[b] = normal * nx + ftx, B.fy[b] = normal * ny + fty, B.fz[b] = normal * nz + ftz;
          if (rotation)
            {
              B.cx[b] = ny * ftz - nz * fty, B.cy[b] = nz * ftx - nx * ftz, B.cz[b] = nx * fty - ny * ftx;
              const double fr = c.rolling_friction * std::abs(normal);
              B.roll_i[b] = fr * ri, B.roll_j[b] = fr * rj;
            }
          B.ratio[b] = overlap / (ri < rj ? ri : rj);
        }
    }
  } // namespace

  template <bool rotation>
  void Simulation::pair_forces()
  {
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
    const ListArrays        list{m.row_of.data(), NEIGHBOURS, TOUCHING, SHEAR};

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
        if (range == 0)
          fx = P.fx.data(), fy = P.fy.data(), fz = P.fz.data(), tx = P.tx.data(), ty = P.ty.data(),
          tz = P.tz.data(), rl = P.rolling.data();
        else
          {
            double *b = m.buffers[range].data();
            fx = b, fy = b + n, fz = b + 2 * n, tx = b + 3 * n, ty = b + 4 * n, tz = b + 5 * n, rl = b + 6 * n;
          }
        std::fill(fx, fx + n, 0.0), std::fill(fy, fy + n, 0.0), std::fill(fz, fz + n, 0.0);
        if (rotation)
          std::fill(tx, tx + n, 0.0), std::fill(ty, ty + n, 0.0), std::fill(tz, tz + n, 0.0),
            std::fill(rl, rl + n, 0.0);
      };
      double my_worst = 0;
      long   my_i = -1, my_j = -1;

      PairBatch B;

      // 2. the batch's forces, 3. onto both particles and the histories back to their slots
      auto flush = [&]() {
        if (m.one_material >= 0)
          batch_forces<rotation, true>(B, in, COEF + m.one_material * (nm + 1), nm, dt);
        else
          batch_forces<rotation, false>(B, in, COEF, nm, dt);
        for (int b = 0; b < B.n; ++b)
          {
            const int i = B.i[b], j = B.j[b];
            double   *s = SHEAR + 3 * std::size_t(B.slot[b]);
            s[0] = B.s0[b], s[1] = B.s1[b], s[2] = B.s2[b];
            fx[i] += B.fx[b], fy[i] += B.fy[b], fz[i] += B.fz[b];
            fx[j] -= B.fx[b], fy[j] -= B.fy[b], fz[j] -= B.fz[b];
            if (rotation)
              {
                // torque on i: (-ri n) x ft, on j: (rj n) x (-ft); rolling resistance
                const double ri = R[i], rj = R[j];
                tx[i] -= ri * B.cx[b], ty[i] -= ri * B.cy[b], tz[i] -= ri * B.cz[b];
                tx[j] -= rj * B.cx[b], ty[j] -= rj * B.cy[b], tz[j] -= rj * B.cz[b];
                rl[i] += B.roll_i[b], rl[j] += B.roll_j[b];
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

  template void Simulation::pair_forces<true>();
  template void Simulation::pair_forces<false>();
} // namespace abrade::dem
