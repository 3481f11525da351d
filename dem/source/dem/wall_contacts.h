#pragma once
// A particle's contacts with the walls (wall_forces.cc; internal to the DEM): the
// triangles within its radius with the closest point on each, one contact per touching region
// of a wall, and the slots of the contacts' tangential histories. All inline: the wall-force
// loop calls them per particle and must not pay a call or an allocation for them.
#include <abrade/common/closest_point.h>
#include <abrade/dem/wall.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace abrade::dem::wall_contacts
{
  /// A wall triangle within a particle's radius: the closest point on it, the feature that
  /// point lies on, and its squared distance from the particle's centre.
  struct Hit
  {
    int     wall, tri;
    Feature feature;
    double  p[3], d2;
  };

  /// The most triangles a particle keeps in touch with in one step (more: the farthest are
  /// dropped; never seen in practice).
  constexpr int max_hits = 64;

  inline bool triangles_share_vertex(const std::array<int, 3> &a, const std::array<int, 3> &b)
  {
    for (int p : a)
      for (int q : b)
        if (p == q)
          return true;
    return false;
  }

  inline bool triangle_has(const std::array<int, 3> &t, int v) { return t[0] == v || t[1] == v || t[2] == v; }

  /// The candidate triangles (wall @p cand_wall[k], triangle @p cand_tri[k], for k = @p begin
  /// .. @p end - 1: the neighbour list's) whose closest point to the centre @p q lies closer
  /// than the radius @p r (and not at the centre), into @p hits; returns their number.
  inline int find_hits(const double q[3], double r, const std::vector<Wall> &walls, const int *cand_wall,
                       const int *cand_tri, std::size_t begin, std::size_t end, Hit *hits)
  {
    int n_hits = 0;
    for (std::size_t k = begin; k < end; ++k)
      {
        const Wall   &w   = walls[cand_wall[k]];
        const auto   &tri = w.mesh.triangles[cand_tri[k]];
        const double *V   = w.current.data();
        const auto    cp  = closest_point_on_triangle(q, V + 3 * tri[0], V + 3 * tri[1], V + 3 * tri[2]);
        const double  dx = q[0] - cp.p[0], dy = q[1] - cp.p[1], dz = q[2] - cp.p[2];
        const double  d2 = dx * dx + dy * dy + dz * dz;
        if (!(d2 < r * r && d2 > 0))
          continue;
        int slot = n_hits < max_hits ? n_hits++ : -1;
        if (slot < 0) // full: replace the farthest hit
          {
            slot = 0;
            for (int s = 1; s < max_hits; ++s)
              if (hits[s].d2 > hits[slot].d2)
                slot = s;
            if (hits[slot].d2 <= d2)
              continue;
          }
        Hit &h = hits[slot];
        h.wall = cand_wall[k], h.tri = cand_tri[k], h.feature = cp.feature;
        h.p[0] = cp.p[0], h.p[1] = cp.p[1], h.p[2] = cp.p[2], h.d2 = d2;
      }
    return n_hits;
  }

  /// One contact per touching region of a wall. The closest point on a triangle is a real
  /// contact only if it is a local minimum of the distance over the whole surface: a point on an
  /// edge (vertex) is dropped when a triangle that shares that edge (vertex) is at least as
  /// close, and a point already accepted from a neighbouring triangle (an edge or vertex seen
  /// from both sides) is not counted again. Round-off ties (a centre above a shared edge) are
  /// broken consistently. Sorts @p hits (by wall, distance, feature, triangle), writes the
  /// accepted ones' indices into @p accepted and returns their number; @p r: the radius.
  inline int accept_contacts(Hit *hits, int n_hits, const std::vector<Wall> &walls, double r, int *accepted)
  {
    if (n_hits == 1) // (most particles touch one triangle: nothing to sort or to compare)
      {
        accepted[0] = 0;
        return 1;
      }
    auto rank = [](Feature f) { return f == face ? 0 : f <= edge20 ? 1 : 2; };
    std::sort(hits, hits + n_hits, [&](const Hit &a, const Hit &b) {
      if (a.wall != b.wall) return a.wall < b.wall;
      if (a.d2 != b.d2) return a.d2 < b.d2;
      if (rank(a.feature) != rank(b.feature)) return rank(a.feature) < rank(b.feature);
      return a.tri < b.tri;
    });
    int n_acc = 0;
    for (int h = 0; h < n_hits; ++h)
      {
        const auto   &tris = walls[hits[h].wall].mesh.triangles;
        const auto   &t    = tris[hits[h].tri];
        const Feature f    = hits[h].feature;
        bool          keep = true;
        // the same point (within 1e-6 R) as an accepted contact of this wall
        for (int a = 0; a < n_acc && keep; ++a)
          {
            const Hit   &acc = hits[accepted[a]];
            const double dx = acc.p[0] - hits[h].p[0], dy = acc.p[1] - hits[h].p[1], dz = acc.p[2] - hits[h].p[2];
            keep = acc.wall != hits[h].wall || dx * dx + dy * dy + dz * dz >= 1e-12 * r * r;
          }
        // an edge (vertex) point with a triangle sharing that edge (vertex) at least as close;
        // ties go to faces, then to the hit sorted first
        if (keep && f != face)
          for (int o = 0; o < n_hits && keep; ++o)
            {
              if (o == h || hits[o].wall != hits[h].wall || !(hits[o].d2 <= hits[h].d2 * (1 + 1e-9)))
                continue;
              if (hits[o].feature != face && o > h)
                continue;
              const auto &to = tris[hits[o].tri];
              if (f <= edge20)
                keep = !(triangle_has(to, t[f - 1]) && triangle_has(to, t[f % 3]));
              else
                keep = !triangle_has(to, t[f - vertex0]);
            }
        if (keep)
          accepted[n_acc++] = h;
      }
    return n_acc;
  }

  /// The tangential histories of the particles' wall contacts: K slots per particle, each the
  /// wall and triangle of its contact (wall -1: free), whether this step used it, and its H
  /// history values (the simulation's arrays, viewed).
  template <int K, int H>
  struct Histories
  {
    int           *wall;
    int           *tri;
    unsigned char *used;
    double        *shear;

    /// Before particle @p i's contacts of this step: no slot used yet.
    void start(std::size_t i) const
    {
      for (int s = 0; s < K; ++s)
        used[K * i + s] = 0;
    }

    /// The history of particle @p i's contact @p h with @p w: the slot of the same wall and
    /// triangle, else of an adjacent triangle (two passes: in a concave fold a new contact on
    /// the next face must not take the history of the contact on this one), else a free slot,
    /// zeroed (@p began: an impact). With every slot taken none is kept (nullptr) and the
    /// contact is not counted as beginning, rather than as beginning every step.
    double *claim(std::size_t i, const Hit &h, const Wall &w, bool &began) const
    {
      int slot = -1, free_slot = -1;
      for (int pass = 0; pass < 2 && slot < 0; ++pass)
        for (int s = 0; s < K; ++s)
          {
            const int ws = wall[K * i + s];
            if (ws < 0)
              {
                if (free_slot < 0)
                  free_slot = s;
                continue;
              }
            if (ws == h.wall && !used[K * i + s] &&
                (pass == 0 ? tri[K * i + s] == h.tri
                           : triangles_share_vertex(w.mesh.triangles[tri[K * i + s]], w.mesh.triangles[h.tri])))
              {
                slot = s;
                break;
              }
          }
      began = slot < 0 && free_slot >= 0;
      if (began)
        {
          slot             = free_slot;
          wall[K * i + slot] = h.wall;
          for (int d = 0; d < H; ++d)
            shear[H * (K * i + slot) + d] = 0;
        }
      if (slot < 0)
        return nullptr;
      tri[K * i + slot]  = h.tri;
      used[K * i + slot] = 1;
      return &shear[H * (K * i + slot)];
    }

    /// After particle @p i's contacts: the histories of the contacts that ended are forgotten.
    void finish(std::size_t i) const
    {
      for (int s = 0; s < K; ++s)
        if (!used[K * i + s])
          wall[K * i + s] = -1;
    }
  };
} // namespace abrade::dem::wall_contacts
