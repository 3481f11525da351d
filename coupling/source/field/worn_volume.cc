// The worn volume between a design and a worn surface that may be open (field/worn_volume.h).
#include <abrade/field/worn_volume.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace abrade::field
{
  namespace
  {
    /// The fraction of a cell of size h around a point at signed distance d that is inside.
    double inside(double d, double h) { return std::clamp(0.5 - d / h, 0.0, 1.0); }
  } // namespace

  WornVolume worn_volume(const geometry::SurfaceDistance &design, const geometry::SurfaceDistance &worn,
                         const geometry::SurfaceDistance &footprint, const std::array<double, 6> &box, double h)
  {
    WornVolume   r;
    r.cell       = h;
    const int    fine = 4;          // fine points per coarse cell and axis
    const double H    = fine * h;   // the coarse cell
    const double reach = 0.5 * std::sqrt(3.0) * H + h;
    const double band  = 4 * h;
    long         n[3];
    for (int k = 0; k < 3; ++k)
      n[k] = std::max(1L, long(std::ceil((box[k + 3] - box[k]) / H)));
    const long total  = n[0] * n[1] * n[2];
    // each coarse cell's volume apart, summed in cell order after the loop: the same bits on
    // any number of threads (a reduction under a dynamic schedule sums in a varying order)
    std::vector<double> cell_volume(total, 0.0);
    long                points = 0;
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : points)
    for (long c = 0; c < total; ++c)
      {
        double &volume = cell_volume[c];
        const long   i = c % n[0], j = (c / n[0]) % n[1], k = c / (n[0] * n[1]);
        const double corner[3] = {box[0] + i * H, box[1] + j * H, box[2] + k * H};
        const double centre[3] = {corner[0] + 0.5 * H, corner[1] + 0.5 * H, corner[2] + 0.5 * H};
        const double dd = design.signed_distance(centre), dw = worn.signed_distance(centre);
        if (std::abs(dd) > reach && std::abs(dw) > reach && (dd > 0) == (dw > 0))
          continue; // both surfaces far, on the same side: no difference in this cell
        for (int a = 0; a < fine; ++a)
          for (int b = 0; b < fine; ++b)
            for (int e = 0; e < fine; ++e)
              {
                const double p[3] = {corner[0] + (a + 0.5) * h, corner[1] + (b + 0.5) * h, corner[2] + (e + 0.5) * h};
                ++points;
                const double in_design = inside(design.signed_distance(p), h);
                bool         on_rim    = false;
                double       foot[3];
                const double d_worn    = worn.signed_distance(p, on_rim, foot);
                const double in_worn   = inside(d_worn, h);
                if (in_design == in_worn)
                  continue;
                // the worn surface standing out of the design (noise, a bump) counts where it
                // does stand out, near it: behind a scan that sees one side of the knife lies the
                // whole half-space, beyond the design's other faces too
                if (in_worn > in_design && (d_worn < -band || !(design.signed_distance(foot) > 1e-3 * h)))
                  continue;
                bool rim = on_rim; // the worn surface is the footprint (a scan): asked already
                if (&footprint != &worn)
                  footprint.signed_distance(p, rim);
                if (!rim)
                  volume += (in_design - in_worn) * h * h * h;
              }
      }
    r.volume = 0;
    for (const double v : cell_volume)
      r.volume += v;
    r.points = std::size_t(points);
    return r;
  }
} // namespace abrade::field
