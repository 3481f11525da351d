#pragma once
// Overlapping facets of a CAD export, repaired before Gmsh sees them.
//
// A planar face that an exporter tessellated badly (a fan from a point outside the face, a flap
// folded back onto its neighbour) is closed and consistent edge by edge, yet some of its facets
// lie on top of others with the opposite orientation: Gmsh's volume mesher then stops with
// "Invalid boundary mesh (overlapping facets)" (a public excavator bucket's STL did). The face
// itself is well defined: the facets of one plane, each with its orientation, add up to a
// 2-chain whose boundary (the directed edges left once the opposite pairs cancel) is the face's
// outline. The repair finds the planes that hold a fold (two coplanar facets across an edge,
// facing opposite ways), and replaces all their facets by a triangulation of that outline (VTK's
// vtkContourTriangulator), facing the way the face's net area faces. Points used by no facet any
// more (the fan's outside point) are dropped.
#include <abrade/common/vtk_output.h>

#include <array>
#include <cstddef>

namespace abrade::fem
{
  struct SurfaceRepair
  {
    io::PolyData          surface;     ///< the repaired triangles (points welded)
    std::size_t           folds  = 0;  ///< coplanar facet pairs facing opposite ways across an edge
    std::size_t           planes = 0;  ///< planar faces re-triangulated
    std::size_t           collapsed = 0; ///< facets dropped: two of their corners welded into one
    std::array<double, 3> first_fold{}; ///< the midpoint of the first fold's edge
  };

  /// Repairs the overlapping facets of @p surface (closed triangles, points possibly repeated per
  /// facet as an STL has them); @p tolerance [m]: points closer than it are one point, and a
  /// facet within it of a plane lies in that plane; a facet two of whose corners weld into one is
  /// dropped (its edge collapsed). Without folds the surface comes back with
  /// its points welded and folds = 0. Throws std::runtime_error where a folded
  /// plane's outline cannot be triangulated (the caller names the file).
  SurfaceRepair repair_overlapping_facets(const io::PolyData &surface, double tolerance);
} // namespace abrade::fem
