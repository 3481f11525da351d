#pragma once
// Better triangles where a surface is flat or nearly, without moving it (more than asked): a decimated worn surface has
// needles (angles of 0.001 degree on the unworn faces) on which Gmsh's tetrahedral meshers
// stall or fail to recover the boundary.
#include <abrade/common/vtk_output.h>

namespace abrade::fem
{
  struct TidyReport
  {
    std::size_t flips = 0, moves = 0;
    double      smallest_angle_before = 0, smallest_angle_after = 0; ///< [degree]
  };

  /// Where two triangles sharing an edge lie in one plane, or where flipping their edge moves
  /// the surface by at most @p max_move [m] on average over the pair (a needle lying across an
  /// edge of the part: marching cubes' chamfer strips along the unworn design's edges), the edge
  /// is flipped when that makes the pair's smallest angle larger (Delaunay's criterion) and
  /// neither new triangle turns; a vertex whose triangles all lie in one plane (normals within
  /// @p flat_degrees) moves, within it, to the mean of its neighbours when that makes its
  /// triangles' smallest angle larger. A few passes of each. The points and their number stay.
  TidyReport tidy_flat_regions(io::PolyData &surface, double flat_degrees = 0.05, double max_move = 0);
} // namespace abrade::fem
