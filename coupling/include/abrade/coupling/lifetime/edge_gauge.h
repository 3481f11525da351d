#pragma once
// What a fitter's gauges read on a worn edge, along its whole length (docs/lifetime.md,
// "Criteria a fitter gauges"). The part lies in its own frame: x along the edge, z up from it.
// At evenly spaced stations along x -- the two ends included, an inset inside the part's present
// ends (an end face wears back too): the corners as far as the mesh resolves them, one mesh size
// in (a worn corner vertex moves along its faces' mean normal and cuts the corner over the
// triangles beside it; closer in, a section would gauge that cut, not the part) -- the part's
// cross-section (the plane x = station cut through
// its surface triangles) gives:
//
//  - the edge height: the section's lowest z, what a height gauge set on the edge reads;
//    the edge recession at a station is its rise above the design's edge height there;
//  - the plate thickness at the gauge height h above the design's edge: the section's width
//    (largest minus smallest y where it crosses z = h), what calipers across the plate read.
//    A section that no longer reaches h has no plate there: thickness 0.
//
// The worst station is where the edge has receded most / the plate is thinnest: corners are
// stations like any other, so a rounded corner ends the life when it passes the limit (the
// three followed Recession points of the knife-bed case missed its corner: 20 mm there came at
// about 4 Mt, not 8.7).
#include <abrade/fem/solid_surface.h>

#include <vector>

namespace abrade::coupling::lifetime
{
  struct EdgeSections
  {
    std::vector<double> x;         ///< the stations
    std::vector<double> height;    ///< lowest z of the section (+infinity: no section there)
    std::vector<double> top;       ///< highest z of the section
    std::vector<double> thickness; ///< width at the gauge height (0 where the section does not reach it)
    std::vector<double> y_low, y_high; ///< where the section crosses the gauge height
    std::vector<dealii::Point<3>> lowest; ///< the lowest point of each section
  };

  /// The sections of @p s at @p stations stations from x0 + inset to x1 - inset, inset = @p inset
  /// (x1 - x0), the width taken at height @p h.
  EdgeSections edge_sections(const fem::SolidSurface &s, double x0, double x1, int stations, double h,
                             double inset = 0.01);

  /// The sections of the worn part @p worn and of its design @p design at the same stations,
  /// spread over the worn part's own length, @p inset [m] inside its ends.
  std::pair<EdgeSections, EdgeSections> worn_and_design_sections(const fem::SolidSurface &worn,
                                                                 const fem::SolidSurface &design, int stations, double h,
                                                                 double inset);

  /// The lowest height above the design's edge (z0), on a grid of 400 steps up to z1, where the
  /// design's middle section has its full width: just above a chisel's bevel, where the plate is
  /// whole.
  double full_thickness_height(const fem::SolidSurface &design, double x0, double x1, double z0, double z1);

  struct EdgeGauge
  {
    double      recession = 0; ///< the largest rise of the edge above the design's [m]
    double      thinnest  = 0; ///< the thinnest plate at the gauge height [m]
    std::size_t recession_station = 0, thinnest_station = 0;
  };

  /// The worn sections @p worn against the design's @p design.
  EdgeGauge gauge(const EdgeSections &worn, const EdgeSections &design);
} // namespace abrade::coupling::lifetime
