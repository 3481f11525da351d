#pragma once
// The wear filter: a per-vertex wear volume, smoothed over the part's surface.
//
// The DEM's wear is noisy at the scale of single contacts and, with coarse-grained particles,
// concentrated on lines narrower than any real contact patch (the chisel's edge). The loop
// smooths it over a length that stands for the particle's footprint (Lifetime/Smoothing radius,
// default the largest particle radius; docs/physics.md). The smoothing must
//  - keep a uniform wear depth uniform, also at corners and at the tip, where a vertex has less
//    surface around it within the filter's reach: each vertex's depth is a weighted mean of the
//    depths around it (weights normalised at the receiving vertex);
//  - conserve the volume exactly: the smoothed volumes are rescaled once, by the ratio of the
//    total before to the total after (a correction of the order of the boundary effects), so
//    the worn volume, and the swept volume, do not depend on the filter;
//  - stay on the surface: the weights fall off with the geodesic distance, the shortest path
//    along the surface's edges (Dijkstra), not the straight 3-D distance, which would carry wear
//    from one face of a 30 mm plate to the other through the steel. Paths along edges overshoot
//    the true geodesic by a few per cent on a triangle mesh; the filter's length is a model
//    parameter, not known to that precision;
//  - stay on the wearable surface: only triangles of the given boundary id carry wear and paths
//    (the bolted face's vertices never move; wear spread onto it would be lost).
// With V_u the volume at vertex u, A_u its area (a third of its wearable triangles') and
// G_uv = exp(-g_uv^2 / (2 r^2)) for g_uv < 3 r:
//     depth_v = sum_u G_uv V_u / sum_u G_uv A_u,   volume_v = c A_v depth_v,
// c such that sum_v volume_v = sum_u V_u over the vertices with wearable area.
#include <abrade/fem/solid_surface.h>

#include <vector>

namespace abrade::fem
{
  /// A third of the area of each vertex's triangles (of all triangles, or of those with
  /// @p only_boundary_id when it is not -1).
  std::vector<double> vertex_areas(const SolidSurface &surface, int only_boundary_id = -1);

  /// The geodesic distances (along the edges of triangles with boundary id @p boundary_id, or
  /// all for -1) from vertex @p source to every vertex within @p cutoff: (vertex, distance).
  std::vector<std::pair<unsigned, double>> geodesic_neighbourhood(const SolidSurface &surface, unsigned source,
                                                                  double cutoff, int boundary_id = -1);

  /// @p volume per vertex, smoothed over the triangles with boundary id @p boundary_id (all
  /// triangles for -1) with a Gaussian of geodesic length @p radius. Returns volumes per vertex
  /// (zero at vertices with no such triangle) that sum to the input's sum over the vertices
  /// that have one. radius <= 0: the volumes of those vertices, unchanged.
  std::vector<double> filter_on_surface(const SolidSurface &surface, const std::vector<double> &volume, double radius,
                                        int boundary_id = -1);
} // namespace abrade::fem
