#pragma once
// The front of one update's wear: the boundary of the union of the balls of radius d(p) about
// every point p of the worn triangles, d linear over each triangle from its vertices' depths.
//
// For one triangle T the function
//
//     f_T(x) = min over p in T of ( |x - p| - d(p) )
//
// is < 0 where x is worn away, > 0 beyond the wear. It is the minimum of a convex function of p
// (a norm less a linear function) over a convex set, found in closed form: with h the height of
// x over T's plane, x' its foot and g the in-plane gradient of d (|g| < 1), the stationary
// point is p = x' + g |h| / sqrt(1 - |g|^2), where f_T = |h| sqrt(1 - |g|^2) - d(x'); where that
// point lies outside T (or |g| >= 1) the minimum is on an edge, where the same construction in
// one dimension gives it. The front of all the worn triangles is min_T f_T: a continuous union of
// balls, not a sampled one (balls at a fixed spacing leave scallops between them, and none at all
// where the depth is smaller than their spacing). f is 1-Lipschitz with |grad f| = 1, grad f =
// (x - p*) / |x - p*| at the minimiser p*, so x - f grad f is the point of the front nearest x
// where the minimiser does not change (on a flat face's offset: exactly).
#include <abrade/common/closest_point.h>
#include <abrade/common/vtk_output.h>

#include <array>
#include <unordered_map>
#include <vector>

namespace abrade::fem
{
  /// One worn triangle: f_T(x) and its minimiser.
  class SweptTriangle
  {
  public:
    /// The triangle a, b, c with the depths da, db, dc [m] at its corners.
    SweptTriangle(const double *a, const double *b, const double *c, double da, double db, double dc);

    /// f_T(x) = min over p in T of |x - p| - d(p); @p foot: that p.
    double distance(const double *x, double *foot) const;

    /// The largest corner depth, and the triangle's box.
    double                largest_depth() const { return d_max; }
    std::array<double, 6> box() const;

    /// Whether f_T(x) > @p value is certain without computing it: the distance from x to the
    /// triangle's box less the largest depth exceeds @p value (by a round-off guard, @p guard
    /// [m]), as f_T(x) >= |x - box| - d_max. Exact for a search of the minimum: a triangle so
    /// ruled out could not have changed it.
    bool exceeds(const double *x, double value, double guard) const
    {
      const double bound = value + guard + d_max;
      if (bound < 0)
        return true;
      const double gap2 = geometry::box_distance2(x, bounds);
      return gap2 > bound * bound;
    }

  private:
    double corner[3][3], depth[3], e1[3], e2[3], normal[3] = {0, 0, 0};
    double bounds[6]; ///< the box: lo x, y, z, hi x, y, z
    double d00 = 0, d01 = 0, d11 = 0, det = 0; ///< Gram matrix of e1, e2
    double alpha = 0, beta = 0, gg = 0;        ///< g = alpha e1 + beta e2, |g|^2
    double d_max = 0;
    bool   flat  = false; ///< no area: its edges only
  };

  /// The front of all the worn triangles of a surface (those with a positive corner depth), in a
  /// hash grid for the nearest ones.
  class WornFront
  {
  public:
    /// @p depth per point of @p surface [m]; @p margin: how far beyond the deepest ball the
    /// front is asked for [m].
    WornFront(const io::PolyData &surface, const std::vector<double> &depth, double margin);

    /// min_T f_T(x) (infinity farther than the largest depth and the margin from every worn
    /// triangle); @p on_front: x - f grad f; @p gradient (if given): grad f, the front's
    /// normal, outward from the worn-away balls.
    double distance(const double *x, double *on_front, double *gradient = nullptr) const;

    const std::vector<SweptTriangle> &triangles() const { return worn; }
    /// [m] a bound on the round-off of f_T, for SweptTriangle::exceeds
    double round_off() const { return guard; }

  private:
    std::vector<SweptTriangle>                             worn;
    double                                                 cell = 1;
    double                                                 guard = 0; ///< [m] round-off of f_T
    std::unordered_map<long long, std::vector<unsigned>> cells;
    long long key(long i, long j, long k) const { return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL); }
  };
} // namespace abrade::fem
