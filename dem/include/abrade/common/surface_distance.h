#pragma once
// Signed distance to a closed triangle surface, and the one definition of wear depth.
//
// What. SurfaceDistance holds a triangle surface (the knife as designed, say) and answers, for
// any point q, its signed distance to it: |q - p| with p the closest point of the surface,
// negative inside, positive outside. wear_depth() turns that into the wear depth of points of a
// worn surface: how far each lies inside the design surface, -signed_distance (> 0 where
// material is missing, < 0 where a point stands outside the design).
//
// Why. The lifetime loop (the knife's receding surface) and `abrade compare` (a field scan
// against the design) must measure the same quantity, or a calibration of one against the other
// compares two different things. The vertex displacement of the worn mesh is not that quantity:
// where two faces offset inward by d meet at a sharp edge of interior angle alpha, the edge moves
// d / sin(alpha / 2) along the bisector (2.86 d for the 41-degree chisel), but every point of the
// offset surface, the moved edge included, lies exactly d inside the design. The distance to the
// surface is the depth a gauge (or a scan) measures.
//
// How. The closest triangle comes from a bounding-volume hierarchy of the triangles (each node
// the box of its triangles, split at the median of their centres along the longest side, down
// to leaves of four), built once and walked nearer child first, nodes and triangles whose boxes
// lie farther than the closest one found passed over (exact: no triangle that could be closer
// is left out). The closest point p and the feature it lies on (the face, one of its three
// edges or one of its three vertices) come from closest_point_on_triangle (closest_point.h),
// which also measures every candidate. (VTK's vtkStaticCellLocator did this before, 1.1-4x
// slower near a surface and 100-500x inside a bulky part; a uniform grid, tried first, was
// faster near thin parts but 40x slower than VTK far from bulky ones. The answers differ from
// VTK's only where two triangles are equally close: by round-off, or on a medial axis, where
// either is right.) The sign is that of (q - p) . N, N the angle-weighted pseudonormal of the
// feature (Baerentzen and Aanaes, "Signed distance computation using the angle weighted
// pseudonormal", IEEE TVCG 11(3), 243-253, 2005):
//   face:   the face's unit normal;
//   edge:   the sum of the unit normals of the faces that share the edge;
//   vertex: the sum over the faces around the vertex of (the face's angle at the vertex) times
//           (its unit normal).
// For a closed, manifold, consistently oriented surface the sign so found is right for every
// point (their theorem), whatever feature p lies on. The face normal alone is not enough: just
// outside a sharp edge, q - p can make an obtuse angle with one of the two faces' normals, so a
// point outside the 41-degree chisel edge would count as inside when the locator happens to
// return that face's triangle. When q is equally far from several triangles (p on an edge or a
// vertex they share), each of them gives the same feature and so the same pseudonormal: the
// answer does not depend on which one the locator returns.
//
// Conventions.
//  - Triangles are oriented outward: counter-clockwise seen from outside.
//  - Vertices with identical coordinates are one vertex (an STL file's separate corners work).
//  - Degenerate triangles (twice the area at most 1e-10 times the longest edge squared: zero
//    area, repeated or collinear corners) are left out: they are not searched and give no normal
//    (no NaN). A sliver of such a mesh lies within 1e-10 of its length from its neighbours.
//  - An open or non-manifold surface is accepted: an edge's pseudonormal is the sum over the
//    faces that share it (one at a boundary, more at a non-manifold edge). The sign is then only
//    meaningful where the surface locally separates inside from outside.
//  - Throws std::invalid_argument for coordinates that are not x,y,z triples, a non-finite
//    coordinate, an index out of range, or no triangle of positive area.
//
// Threads. Concurrent calls of the const members (signed_distance, n_triangles) are safe: the
// hierarchy and the pseudonormals are built in the constructor and only read afterwards.
// wear_depth() runs on the calling thread (the callers own
// the thread count: OpenMP threads or MPI ranks); split the points among threads to go faster.
#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace abrade::geometry
{
  class SurfaceDistance
  {
  public:
    /// @p points: x,y,z per vertex; @p triangles: vertex indices, oriented outward (counter-clockwise seen from outside).
    SurfaceDistance(const std::vector<double> &points, const std::vector<std::array<long, 3>> &triangles);
    ~SurfaceDistance();
    SurfaceDistance(SurfaceDistance &&) noexcept;
    SurfaceDistance &operator=(SurfaceDistance &&) noexcept;

    /// Signed distance of q to the surface: < 0 inside, > 0 outside. NaN for a non-finite q.
    double signed_distance(const double q[3]) const;
    /// The same, and whether the closest point lies on the surface's rim (an open surface's
    /// boundary edge or a vertex on one: then @p q is beyond the surface's footprint), and, with
    /// @p closest, that point.
    double signed_distance(const double q[3], bool &on_rim, double closest[3] = nullptr) const;
    /// The triangles given (degenerate ones included).
    std::size_t n_triangles() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl;
    friend std::vector<double> wear_depth(const SurfaceDistance &, const std::vector<double> &, std::vector<double> *);
  };

  /// Wear depth of each point (x,y,z flat): its distance inside the design surface, = -signed_distance (> 0 where material is missing, < 0 outside). The single definition used by the lifetime loop and by compare.
  /// With @p feet, also the closest design point of each (x,y,z flat): the point of the fresh
  /// knife that the worn surface lies below, where `abrade calibrate` looks the depth up.
  std::vector<double> wear_depth(const SurfaceDistance &design, const std::vector<double> &points,
                                 std::vector<double> *feet = nullptr);
} // namespace abrade::geometry
