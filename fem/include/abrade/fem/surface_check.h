#pragma once
// Whether a closed triangle surface is one Gmsh can mesh inside: no two triangles may cross or
// overlap. Gmsh's own check ("Two facets intersect", "overlapping facets") comes after minutes of
// work and names no place; this one takes a second and says where.
#include <abrade/common/vtk_output.h>

#include <array>
#include <cstddef>
#include <limits>
#include <vector>

namespace abrade::fem
{
  /// Pairs of triangles of @p surface (indices into its triangles) that meet other than along
  /// the vertices and edge they share: crossing (beside a shared vertex too) or, across a shared
  /// edge, folded flat onto each other. A repeated triangle is a pair too. At most
  /// @p at_most pairs are returned. Triangles of no area (corners on one line) are skipped. Points closer than @p merge_distance count as one (the
  /// triangles they squash are skipped): a surface about to be cleaned of them is checked as
  /// it will be. Candidates come from VTK's static cell locator (the
  /// triangles within each one's bounds), pairs without a shared vertex are tested by
  /// vtkTriangle::TrianglesIntersect; pairs sharing a vertex by whether the edge opposite it in
  /// either triangle passes through the other.
  std::vector<std::array<std::size_t, 2>>
  intersecting_triangles(const io::PolyData &surface, std::size_t at_most = std::numeric_limits<std::size_t>::max(),
                         double merge_distance = 0);
} // namespace abrade::fem
