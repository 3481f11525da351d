#pragma once
// The worn volume between a design and a worn surface that may be open (a field scan covers part
// of a knife): the volume inside the design and outside the worn surface, counted only where the
// scan covers the knife (its footprint).
//
// Integrating the depth below the design over the scanned area misses most of the wear at an
// edge: a tip cut 10 mm flat is 10 mm of recession but its surface lies only a few millimetres
// below the bevels; and clipping each depth at zero turns the scanner's noise into volume.
// Instead the volume is integrated over space:
//
//   V = integral over the footprint of [inside(design) - inside(worn)] dx
//
// on a grid of cell h, with the indicator smeared over one cell, inside = clamp(1/2 - d/h, 0, 1)
// (d the signed distance to the surface), which is exact to second order in h. The difference
// is signed, so noise that puts the scan now above, now below an unworn surface adds up to
// nothing on average. A point outside the design but "inside" the worn surface counts only where
// the worn surface does stand out of the design there (its closest point on the worn surface
// lies outside the design) and within four cells of it: a scan of one side of the knife has the
// whole half-space behind it "inside", beyond the design's other faces too. A grid point is in the footprint unless its closest point on the scan lies
// on the scan's rim (its open boundary): then it is beyond what was scanned. Only a band around
// the surfaces is visited: coarse cells of 4 h whose centre lies farther than a cell from both
// surfaces, on the same side, hold no difference and are skipped.
#include <abrade/common/surface_distance.h>

#include <array>
#include <cstddef>

namespace abrade::field
{
  struct WornVolume
  {
    double      volume = 0;  ///< [m^3]
    double      cell   = 0;  ///< the grid's h [m]
    std::size_t points = 0;  ///< grid points evaluated
  };

  /// The volume inside @p design and outside @p worn within @p footprint's coverage, in the box
  /// @p box (xmin, ymin, zmin, xmax, ymax, zmax) on a grid of @p cell. All surfaces outward.
  WornVolume worn_volume(const geometry::SurfaceDistance &design, const geometry::SurfaceDistance &worn,
                         const geometry::SurfaceDistance &footprint, const std::array<double, 6> &box, double cell);
} // namespace abrade::field
