#pragma once
// The wear filter: a per-vertex wear volume, smoothed over the knife's surface.
//
// The DEM's wear is noisy at the scale of single contacts and, with coarse-grained particles,
// concentrated on lines narrower than any real contact patch (the chisel's edge). The loop
// smooths it over a length that stands for the particle's footprint (Lifetime/Smoothing radius,
// default the largest particle radius; docs/lifetime.md). The smoothing must
//  - conserve the volume exactly: each vertex's volume is spread over its neighbours with weights
//    that sum to one (so the worn volume, and the swept volume, do not depend on the filter);
//  - stay on the surface: the weights fall off with the geodesic distance, the shortest path
//    along the surface's edges (Dijkstra), not the straight 3-D distance, which would carry wear
//    from one face of a 30 mm plate to the other through the steel. Paths along edges overshoot
//    the true geodesic by a few per cent on a triangle mesh; the filter's length is a model
//    parameter, not known to that precision.
// Weights: w_uv = exp(-g_uv^2 / (2 r^2)) A_v for g_uv < 3 r (A_v: a third of the area of the
// vertex's triangles), normalised over v.
#include <abrade/fem/solid_surface.h>

#include <vector>

namespace abrade::fem
{
  /// A third of the area of each vertex's triangles (of all triangles, or of those with
  /// @p only_boundary_id when it is not -1).
  std::vector<double> vertex_areas(const SolidSurface &surface, int only_boundary_id = -1);

  /// The geodesic distances (along the surface's edges) from vertex @p source to every vertex
  /// within @p cutoff: (vertex, distance) pairs.
  std::vector<std::pair<unsigned, double>> geodesic_neighbourhood(const SolidSurface &surface, unsigned source,
                                                                  double cutoff);

  /// @p volume per vertex, smoothed over the surface with a Gaussian of geodesic length
  /// @p radius (no smoothing for radius <= 0). Sums to the same total.
  std::vector<double> filter_on_surface(const SolidSurface &surface, const std::vector<double> &volume, double radius);
} // namespace abrade::fem
