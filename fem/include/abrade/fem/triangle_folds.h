#pragma once
// A closed triangle surface's folds, found and mended before Gmsh sees it.
//
// Gmsh's volume meshers refuse a surface with a triangle turned over onto its neighbours
// ("overlapping facets") or passing through another ("a segment and a facet intersect"), and
// the STL reader drops a triangle whose height is round-off, which leaves a crack. Beside a
// sharp edge narrower than the grid a worn surface built as a set (eroded_surface.h) has all
// three: caps along the edge (a triangle whose third corner lies within round-off of its longest
// edge: its normal is round-off) and triangles of one face put through the other. These find
// them and flip them with a neighbour.
#include <abrade/common/vtk_output.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace abrade::fem::folds
{
  inline double dot(const std::array<double, 3> &a, const std::array<double, 3> &b)
  {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  }

  /// A triangle's normal (its length twice the area).
  inline std::array<double, 3> normal_of(const double *a, const double *b, const double *c)
  {
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  }

  /// The part's STL reader (solid_file.cc) drops a triangle whose height over its longest edge
  /// is at most this fraction of the diagonal of the part's box: a sliver (Gmsh's surface mesher
  /// aborted on heights of 1e-12 to 1e-10 of it).
  constexpr double sliver_height_fraction = 1e-8;

  /// Whether the triangle (a, b, c) is a sliver at @p height [m]: its height over its longest
  /// edge at most @p height, or its corners one point. The STL reader's rule with @p height =
  /// sliver_height_fraction times the box's diagonal.
  inline bool is_sliver(const double *a, const double *b, const double *c, double height)
  {
    const double *p[3]     = {a, b, c};
    double        longest2 = 0;
    for (int e = 0; e < 3; ++e)
      {
        const double *u = p[e], *v = p[(e + 1) % 3];
        longest2 = std::max(longest2, (u[0] - v[0]) * (u[0] - v[0]) + (u[1] - v[1]) * (u[1] - v[1]) +
                                        (u[2] - v[2]) * (u[2] - v[2]));
      }
    const std::array<double, 3> n = normal_of(a, b, c); // (its length: the height times the longest edge)
    return longest2 == 0 || dot(n, n) <= height * height * longest2;
  }

  /// Whether the segment p -> q passes through the triangle (a, b, c) strictly inside both
  /// (Moeller and Trumbore's test; touching at an end or an edge is not counted).
  bool segment_crosses(const double *p, const double *q, const double *a, const double *b, const double *c);

  /// The triangles of @p s that cross another one, facing away from it, that is not their
  /// neighbour across an edge (an edge of one through the other): where one side of a thin
  /// feature passes through the other. Triangles facing the same way are not counted: a thin
  /// fan of slivers overlapping each other by round-off, which Gmsh fills. Candidates from a
  /// hash grid of the triangles' boxes, its cells twice the median box.
  std::vector<std::size_t> crossing_triangles(const io::PolyData &s);

  /// The caps of @p s: triangles whose third corner lies within @p ratio of their longest edge's
  /// length, or within @p height [m], from that edge.
  std::vector<std::size_t> caps(const io::PolyData &s, double ratio, double height);

  /// Each of @p triangles (turned ones, caps) is replaced, with its neighbour across one of its
  /// edges (the longest first), by the quadrilateral's other diagonal (an edge flip), where the
  /// neighbour is not one of them, both new triangles face as the neighbour does, and the new
  /// edge is not one already. Returns the number of flips.
  std::size_t flip_with_a_neighbour(io::PolyData &s, const std::vector<std::size_t> &triangles);
} // namespace abrade::fem::folds
