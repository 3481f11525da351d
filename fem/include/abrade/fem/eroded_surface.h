#pragma once
// The worn surface as the solution of "every surface point recedes along its normal by its wear
// depth", computed so that it cannot fold.
//
// What. Given a closed surface S (outward triangles) and a depth d(p) >= 0 at every point p of
// it (linear over each triangle from the vertices' depths), the worn solid is
//
//     W = { x in the solid : |x - p| >= d(p) for every p on S },
//
// the solid less the union of the balls of radius d(p) about the surface points: Huygens'
// construction of the front that moves inward with the local speed, the viscosity solution of
// the eikonal front motion for one update (the rate held fixed over the update, as the lifetime
// loop holds it). With a constant d it is the inner parallel body: faces offset by d, convex
// edges and corners staying sharp and moving along their bisector, concave ones rounding off
// with radius d; fronts that meet merge; a face that shrinks to nothing disappears. Nothing can
// self-intersect, because W is a set, not a moved mesh.
//
// How. The implicit function g(x) = min( phi(x), min_p (|x - p| - d(p)) ), phi the signed
// distance to S (> 0 inside; SurfaceDistance, exact, by blocks of the grid: a block whose centre
// is farther from S than its half-diagonal and two spacings takes the sign without its nodes'
// distances), the balls continuous over each worn triangle (worn_front.h), is
// sampled on a regular grid of spacing h (offset by an irrational fraction of h, so that no
// node lies on a flat face), and its zero set extracted by VTK's flying edges (a marching-cubes
// variant). W is { g > 0 }. Flat faces, where g is the exact distance to a plane, are
// reproduced exactly; edges and corners are cut by at most about h / 2 (marching cubes does not
// keep sharp features). Quadric decimation (VTK, volume-preserving) then takes the triangles to
// about the target edge length and pulls edges back towards sharp; the largest piece is kept
// (pieces cut off by the wear are reported by volume). Beside a sharp edge narrower than the
// grid the projections and the decimation can turn a triangle over: its corners go back where
// marching cubes or the quadrics put them, or it is flipped with a neighbour; a decimation with
// a fold left (also once the STL reader welds corners within 1e-6 of the part's size) is done
// again finer.
#include <abrade/common/timer.h>
#include <abrade/common/vtk_output.h>

#include <vector>

namespace abrade::fem
{
  struct ErodedSurface
  {
    io::PolyData surface;            ///< outward triangles
    double       volume       = 0;   ///< [m^3] enclosed by surface
    double       volume_cut_off = 0; ///< [m^3] pieces separated from the largest one and dropped
    double       spacing      = 0;   ///< [m] the grid's
  };

  /// @p surface: a closed, outward-oriented triangle surface; @p depth: per point [m] (>= 0);
  /// @p spacing: the grid spacing [m]; @p edge_length: the decimated triangles' length [m].
  /// Throws RunError when nothing of the solid is left. @p timers, if given, gets the seconds of
  /// each step ("surface as a set: signed distance", ": balls", ": zero set", ": onto the front",
  /// ": merge", ": decimation", ": repair"), for the run's profile.
  ErodedSurface eroded_surface(const io::PolyData &surface, const std::vector<double> &depth, double spacing,
                               double edge_length, io::Timers *timers = nullptr);
} // namespace abrade::fem
