// The worn surface as the zero set of an implicit function on a grid (eroded_surface.h).
#include <abrade/common/error.h>
#include <abrade/common/surface_distance.h>
#include <abrade/common/vtk_input.h>
#include <abrade/fem/eroded_surface.h>
#include <abrade/fem/surface_repair.h>
#include <abrade/fem/triangle_folds.h>
#include <abrade/fem/worn_front.h>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkCleanPolyData.h>
#include <vtkFloatArray.h>
#include <vtkFlyingEdges3D.h>
#include <vtkIdList.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkQuadricDecimation.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <unordered_map>

namespace abrade::fem
{
  namespace
  {
    using folds::dot;
    using folds::normal_of;

    /// The signed volume of the tetrahedron (origin, a, b, c): a triangle's share of the volume
    /// its surface encloses (divergence theorem).
    double volume_share(const double *a, const double *b, const double *c)
    {
      return (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
              a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
    }

    /// Signed volume enclosed by the triangles: > 0 when outward.
    double enclosed_volume(const io::PolyData &s)
    {
      double v = 0;
      for (const auto &t : s.triangles)
        v += volume_share(&s.points[3 * t[0]], &s.points[3 * t[1]], &s.points[3 * t[2]]);
      return v;
    }

    /// The triangles of @p s that face against the surface they approximate, @p reference (their
    /// normal opposed to the one of the reference triangle closest to their centre, found by
    /// @p locator: turned over by a collapse), and the edges of @p s not shared by exactly two
    /// triangles. (A turned triangle of any size is one: Gmsh finds a sliver of 6e-8 m^2 turned
    /// along a chisel's edge intersecting its neighbour.)
    std::size_t turned_triangles(const io::PolyData &s, vtkPolyData *reference, vtkStaticCellLocator *locator,
                                 std::vector<std::size_t> *turned = nullptr)
    {
      std::size_t       bad = 0;
      vtkNew<vtkIdList> ids;
      for (std::size_t k = 0; k < s.triangles.size(); ++k)
        {
          const auto   &t = s.triangles[k];
          const double *a = &s.points[3 * t[0]], *b = &s.points[3 * t[1]], *c = &s.points[3 * t[2]];
          double        centre[3], closest[3], d2 = 0;
          for (int q = 0; q < 3; ++q)
            centre[q] = (a[q] + b[q] + c[q]) / 3;
          vtkIdType cell = -1;
          int       sub  = 0;
          locator->FindClosestPoint(centre, closest, cell, sub, d2);
          if (cell < 0)
            continue;
          reference->GetCellPoints(cell, ids);
          if (ids->GetNumberOfIds() != 3)
            continue;
          double p[3][3];
          for (int q = 0; q < 3; ++q)
            reference->GetPoint(ids->GetId(q), p[q]);
          if (dot(normal_of(a, b, c), normal_of(p[0], p[1], p[2])) < 0)
            {
              ++bad;
              if (turned)
                turned->push_back(k);
            }
        }
      std::map<std::pair<long, long>, int> edges;
      for (const auto &t : s.triangles)
        for (int e = 0; e < 3; ++e)
          {
            const long a = t[e], b = t[(e + 1) % 3];
            ++edges[{std::min(a, b), std::max(a, b)}];
          }
      for (const auto &[edge, n] : edges)
        bad += n != 2;
      return bad;
    }

    /// The unit normal of each triangle of @p s (zero for a triangle of no area).
    std::vector<std::array<double, 3>> unit_normals(const io::PolyData &s)
    {
      std::vector<std::array<double, 3>> n(s.triangles.size());
      for (std::size_t k = 0; k < n.size(); ++k)
        {
          const auto &t      = s.triangles[k];
          n[k]               = normal_of(&s.points[3 * t[0]], &s.points[3 * t[1]], &s.points[3 * t[2]]);
          const double length = std::sqrt(dot(n[k], n[k]));
          for (double &x : n[k])
            x = length > 0 ? x / length : 0;
        }
      return n;
    }

    /// The regular grid on which g is sampled: the surface's box and a margin of three
    /// spacings, offset by an irrational fraction of the spacing (no node on a flat face).
    struct Grid
    {
      Grid(const io::PolyData &surface, double h)
        : h(h)
      {
        std::array<double, 3> hi{};
        for (int c = 0; c < 3; ++c)
          lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
        for (std::size_t k = 0; k < surface.points.size(); ++k)
          lo[k % 3] = std::min(lo[k % 3], surface.points[k]), hi[k % 3] = std::max(hi[k % 3], surface.points[k]);
        for (int c = 0; c < 3; ++c)
          {
            lo[c] -= (3 + 0.31830988618) * h;
            n[c] = static_cast<long>(std::ceil((hi[c] + 3 * h - lo[c]) / h)) + 1;
          }
        extent = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
      }
      long   nodes() const { return n[0] * n[1] * n[2]; }
      long   node(long i, long j, long k) const { return i + n[0] * (j + n[1] * k); }
      double h;
      std::array<double, 3> lo{};
      std::array<long, 3>   n{};
      double                extent = 0; ///< [m] about the part's size
    };

    /// phi, > 0 inside: exact near the surface, the sign (and a lower bound) elsewhere. By
    /// blocks of 6^3 nodes: a block whose centre is farther from the surface than its
    /// half-diagonal and two spacings takes the centre's distance less the half-diagonal.
    std::vector<float> signed_distance_on(const Grid &grid, const geometry::SurfaceDistance &distance)
    {
      const auto        &n = grid.n;
      const auto        &lo = grid.lo;
      const double       h  = grid.h;
      std::vector<float> g(grid.nodes());
      constexpr long     B = 6;
      const long         nb[3] = {(n[0] + B - 1) / B, (n[1] + B - 1) / B, (n[2] + B - 1) / B};
      const double       half_diagonal = 0.5 * (B - 1) * h * std::sqrt(3.0);
#pragma omp parallel for schedule(dynamic)
      for (long b = 0; b < nb[0] * nb[1] * nb[2]; ++b)
        {
          const long   bi = b % nb[0], bj = (b / nb[0]) % nb[1], bk = b / (nb[0] * nb[1]);
          const double centre[3] = {lo[0] + (bi * B + 0.5 * (B - 1)) * h, lo[1] + (bj * B + 0.5 * (B - 1)) * h,
                                    lo[2] + (bk * B + 0.5 * (B - 1)) * h};
          const double phi_centre = -distance.signed_distance(centre);
          const bool   far        = std::abs(phi_centre) > half_diagonal + 2 * h;
          for (long k = bk * B; k < std::min(n[2], (bk + 1) * B); ++k)
            for (long j = bj * B; j < std::min(n[1], (bj + 1) * B); ++j)
              for (long i = bi * B; i < std::min(n[0], (bi + 1) * B); ++i)
                {
                  const double x[3] = {lo[0] + i * h, lo[1] + j * h, lo[2] + k * h};
                  g[grid.node(i, j, k)] = float(far ? std::copysign(std::abs(phi_centre) - half_diagonal, phi_centre)
                                                    : -distance.signed_distance(x));
                }
        }
      return g;
    }

    /// g = min(g, f_T) on the nodes within the reach of each worn triangle's deepest ball: the
    /// union of the balls of radius d(p) about every point of the worn triangles, continuous
    /// over each (worn_front.h: balls sampled at half a spacing left a layer thinner than that
    /// unworn between them).
    void carve_the_balls(const Grid &grid, const WornFront &worn, std::vector<float> &g)
    {
      const auto  &n = grid.n;
      const auto  &lo = grid.lo;
      const double h  = grid.h;
      for (const SweptTriangle &t : worn.triangles())
        {
          const auto   box   = t.box();
          const double reach = t.largest_depth() + 2 * h;
          long         from[3], to[3];
          for (int c = 0; c < 3; ++c)
            {
              from[c] = std::max(0L, static_cast<long>(std::floor((box[c] - reach - lo[c]) / h)));
              to[c]   = std::min(n[c] - 1, static_cast<long>(std::ceil((box[c + 3] + reach - lo[c]) / h)));
            }
          for (long k = from[2]; k <= to[2]; ++k)
            for (long j = from[1]; j <= to[1]; ++j)
              for (long i = from[0]; i <= to[0]; ++i)
                {
                  const double x[3] = {lo[0] + i * h, lo[1] + j * h, lo[2] + k * h};
                  double       foot[3];
                  float       &gn = g[grid.node(i, j, k)];
                  if (t.exceeds(x, gn, worn.round_off())) // (then it could not lower g)
                    continue;
                  const double ball = t.distance(x, foot);
                  if (ball < gn)
                    gn = float(ball);
                }
        }
    }

    /// The zero set of @p g (VTK's flying edges), its largest piece only: the others, cut off by
    /// the wear, are dropped, their volume added to @p volume_cut_off. The triangles face
    /// towards larger g: inward.
    vtkSmartPointer<vtkPolyData> largest_piece_of_the_zero_set(const Grid &grid, const std::vector<float> &g,
                                                               double &volume_cut_off)
    {
      vtkNew<vtkImageData> image;
      image->SetDimensions(int(grid.n[0]), int(grid.n[1]), int(grid.n[2]));
      image->SetOrigin(grid.lo[0], grid.lo[1], grid.lo[2]);
      image->SetSpacing(grid.h, grid.h, grid.h);
      vtkNew<vtkFloatArray> values;
      values->SetName("g");
      values->SetNumberOfTuples(grid.nodes());
      for (long k = 0; k < grid.nodes(); ++k)
        values->SetValue(k, g[k]);
      image->GetPointData()->SetScalars(values);
      vtkNew<vtkFlyingEdges3D> contour;
      contour->SetInputData(image);
      contour->SetValue(0, 0.0);
      contour->ComputeNormalsOff();
      contour->ComputeGradientsOff();
      contour->ComputeScalarsOff();
      contour->Update();
      if (contour->GetOutput()->GetNumberOfCells() == 0)
        throw RunError("the wear leaves nothing of the part (every point is worn away)");

      vtkNew<vtkPolyDataConnectivityFilter> regions;
      regions->SetInputConnection(contour->GetOutputPort());
      regions->SetExtractionModeToAllRegions();
      regions->ColorRegionsOn();
      regions->Update();
      vtkPolyData        *all = regions->GetOutput();
      vtkDataArray       *id  = all->GetPointData()->GetArray("RegionId"); // per point (VTK 9.1)
      std::vector<double> piece(regions->GetNumberOfExtractedRegions(), 0.0);
      vtkNew<vtkIdList>   ids;
      for (vtkIdType c = 0; id && c < all->GetNumberOfCells(); ++c)
        {
          all->GetCellPoints(c, ids);
          if (ids->GetNumberOfIds() != 3)
            continue;
          double a[3], b[3], q[3];
          all->GetPoint(ids->GetId(0), a), all->GetPoint(ids->GetId(1), b), all->GetPoint(ids->GetId(2), q);
          piece[static_cast<std::size_t>(id->GetTuple1(ids->GetId(0)))] += volume_share(a, b, q);
        }
      std::sort(piece.begin(), piece.end(), [](double x, double y) { return std::abs(x) > std::abs(y); });
      for (std::size_t k = 1; k < piece.size(); ++k)
        if (piece[k] * piece[0] > 0) // a solid piece (a void inside would have the other sign)
          volume_cut_off += std::abs(piece[k]);

      vtkNew<vtkPolyDataConnectivityFilter> largest;
      largest->SetInputConnection(contour->GetOutputPort());
      largest->SetExtractionModeToLargestRegion();
      vtkNew<vtkCleanPolyData> clean;
      clean->SetInputConnection(largest->GetOutputPort());
      clean->Update();
      if (clean->GetOutput()->GetNumberOfCells() == 0)
        throw RunError("the wear leaves nothing of the part (every point is worn away)");
      vtkSmartPointer<vtkPolyData> front = clean->GetOutput();
      return front;
    }

    /// The exact front: g and the nearest point of it, from the surface before the wear and
    /// the worn-away balls.
    class ExactFront
    {
    public:
      ExactFront(const geometry::SurfaceDistance &distance, const WornFront &worn, double h)
        : distance(distance), worn(worn), h(h)
      {}

      /// g(x) = min(phi, the balls' distance).
      double g(const double *x) const
      {
        double foot[3];
        return std::min(-distance.signed_distance(x), worn.distance(x, foot));
      }

      /// Each point to the nearest point of the piece of the front nearest to it (the old
      /// surface, or the sphere of the ball that removed the most there), four times at most.
      void project(vtkPoints *points) const
      {
#pragma omp parallel for schedule(dynamic, 256)
        for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
          {
            double x[3];
            points->GetPoint(k, x);
            for (int iteration = 0; iteration < 4; ++iteration)
              {
                bool         rim = false;
                double       on_surface[3], on_ball[3];
                const double phi  = -distance.signed_distance(x, rim, on_surface);
                const double ball = worn.distance(x, on_ball);
                const double gx   = std::min(phi, ball);
                std::copy_n(phi <= ball ? on_surface : on_ball, 3, x);
                if (std::abs(gx) < 1e-6 * h)
                  break;
              }
            points->SetPoint(k, x);
          }
        points->Modified();
      }

    private:
      const geometry::SurfaceDistance &distance;
      const WornFront                 &worn;
      double                           h;
    };

    /// Marching cubes' vertices onto the exact front, which puts the vertices beside a sharp
    /// edge onto its faces, so that the decimation's quadrics find the edge. Beside a sharp
    /// convex edge (a chisel's worn tip) the projection can put the corners of a triangle onto
    /// the edge's two faces in the wrong order: the triangle turns over and lies on a face
    /// against the triangles there (Gmsh: overlapping facets; seen on a 4 m blade from 3 mm of
    /// wear on). Marching cubes' own triangles are never turned, and on a face the projection
    /// turns a triangle by next to nothing: the triangles it turned by more than 10 degrees are
    /// judged against the worn solid's outward direction at their centre (-grad g by central
    /// differences over a quarter spacing: beside an edge they see both faces, so the direction
    /// lies between the faces' normals), and a turned one's corners go back to where marching
    /// cubes put them; again for the neighbours that this turns.
    void onto_the_front_unturned(vtkPolyData *front, const ExactFront &exact, double h)
    {
      vtkPoints        *points = front->GetPoints();
      vtkNew<vtkPoints> marched;
      marched->DeepCopy(points);
      const io::PolyData                       marched_front   = io::triangles_of(front);
      const std::vector<std::array<double, 3>> marched_normals = unit_normals(marched_front);
      // (flying edges orients the triangles towards larger g: inward)
      const double facing = enclosed_volume(marched_front) > 0 ? 1 : -1;
      exact.project(points);
      for (int round = 0; round < 8; ++round)
        {
          const io::PolyData                       now     = io::triangles_of(front);
          const std::vector<std::array<double, 3>> normals = unit_normals(now);
          std::vector<char>                        turned(now.triangles.size(), 0);
#pragma omp parallel for schedule(dynamic, 1024)
          for (std::size_t k = 0; k < turned.size(); ++k)
            {
              const auto &n = normals[k], &m = marched_normals[k];
              if (n[0] * m[0] + n[1] * m[1] + n[2] * m[2] > 0.985) // cos 10 degrees
                continue;
              double centre[3] = {0, 0, 0}, outward = 0;
              for (const long v : now.triangles[k])
                for (int c = 0; c < 3; ++c)
                  centre[c] += now.points[3 * v + c] / 3;
              for (int c = 0; c < 3; ++c)
                {
                  double plus[3] = {centre[0], centre[1], centre[2]}, minus[3] = {centre[0], centre[1], centre[2]};
                  plus[c] += h / 4, minus[c] -= h / 4;
                  outward += n[c] * (exact.g(minus) - exact.g(plus));
                }
              turned[k] = facing * outward < 0;
            }
          if (std::find(turned.begin(), turned.end(), 1) == turned.end())
            break;
          for (std::size_t k = 0; k < turned.size(); ++k)
            if (turned[k])
              for (const long v : now.triangles[k])
                points->SetPoint(v, marched->GetPoint(v));
          points->Modified();
        }
    }

    /// Vertices within @p tolerance of each other as one, the triangles they squash dropped: no
    /// zero-area or repeated facets for the decimation and Gmsh.
    vtkSmartPointer<vtkPolyData> merged_within(vtkPolyData *surface, double tolerance)
    {
      vtkNew<vtkPolyData> copy;
      copy->DeepCopy(surface);
      vtkNew<vtkCleanPolyData> merged;
      merged->SetInputData(copy);
      merged->ToleranceIsAbsoluteOn();
      merged->SetAbsoluteTolerance(tolerance);
      merged->ConvertLinesToPointsOff();
      merged->ConvertPolysToLinesOff();
      merged->ConvertStripsToPolysOff();
      vtkNew<vtkTriangleFilter> only_triangles;
      only_triangles->SetInputConnection(merged->GetOutputPort());
      only_triangles->PassLinesOff();
      only_triangles->PassVertsOff();
      only_triangles->Update();
      vtkSmartPointer<vtkPolyData> result = only_triangles->GetOutput();
      return result;
    }

    /// What the part's STL reader will accept (solid_file.cc): its corners in single precision
    /// as the STL has them, no triangle it would drop as a sliver (folds::is_sliver; checked
    /// here at ten times the reader's height), and no fold once they are welded within 1e-6 of
    /// the box's largest side.
    bool the_stl_reader_accepts(const io::PolyData &surface)
    {
      io::PolyData as_stl = surface;
      double       lo[3], hi[3];
      for (int c = 0; c < 3; ++c)
        lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
      for (std::size_t k = 0; k < as_stl.points.size(); ++k)
        {
          as_stl.points[k] = double(float(as_stl.points[k]));
          lo[k % 3] = std::min(lo[k % 3], as_stl.points[k]), hi[k % 3] = std::max(hi[k % 3], as_stl.points[k]);
        }
      const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
      for (const auto &t : as_stl.triangles)
        if (folds::is_sliver(&as_stl.points[3 * t[0]], &as_stl.points[3 * t[1]], &as_stl.points[3 * t[2]],
                             10 * folds::sliver_height_fraction * diagonal))
          return false;
      try
        {
          const double size = std::max({hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]});
          return repair_overlapping_facets(as_stl, 1e-6 * size).folds == 0;
        }
      catch (const std::runtime_error &)
        {
          return false;
        }
    }

    /// @p front decimated to about @p edge_length, its vertices back on the exact front,
    /// without folds. Quadric decimation does not check what its collapses do to the
    /// neighbours: a triangle can turn over onto its neighbour (Gmsh then finds overlapping
    /// facets). The projection can turn a small triangle beside a sharp edge, or put it through
    /// another one across the edge: its corners go back where the quadrics put them. One
    /// turned there already is most often a cap along the edge (its third corner within
    /// round-off of its longest edge, its normal round-off): it is flipped with its neighbour.
    /// Where the STL reader would not accept the surface (it welds corners within 1e-6 of the
    /// part's size, which turns a cap lower than that onto its neighbour, and drops slivers),
    /// the caps that are not turned are flipped too: those below 1e-5 of the part's size or
    /// 1e-4 of their length. (Not otherwise: HXT's fill of the 30 mm chisel's surface worn 3 mm
    /// stalled past the 120 s limit, in the run, once its caps were flipped.) A decimation with
    /// a fold left is done again with twice the triangles, while that is fewer than marching
    /// cubes made; then the surface stays as marching cubes made it (its vertices projected).
    io::PolyData decimated_without_folds(vtkPolyData *front, double edge_length, double extent,
                                         const ExactFront &exact)
    {
      const vtkIdType cells = front->GetNumberOfCells();
      vtkNew<vtkStaticCellLocator> locator; // (the nearest triangle of the front)
      locator->SetDataSet(front);
      locator->BuildLocator();

      // to about the target edge length (equilateral triangles of that edge over the area)
      double             area = 0;
      const io::PolyData kept = io::triangles_of(front);
      for (const auto &t : kept.triangles)
        {
          const double *a = &kept.points[3 * t[0]], *b = &kept.points[3 * t[1]], *c = &kept.points[3 * t[2]];
          const double  u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
          area += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
        }
      for (double wanted = area / (0.433 * edge_length * edge_length); wanted < 0.9 * cells; wanted *= 2)
        {
          vtkNew<vtkQuadricDecimation> decimate;
          decimate->SetInputData(front);
          decimate->SetTargetReduction(1.0 - wanted / double(cells));
          decimate->VolumePreservationOn();
          vtkNew<vtkTriangleFilter> triangles;
          triangles->SetInputConnection(decimate->GetOutputPort());
          triangles->Update();
          const io::PolyData placed = io::triangles_of(triangles->GetOutput()); // where the quadrics put them
          exact.project(triangles->GetOutput()->GetPoints());
          io::PolyData             decimated = io::triangles_of(triangles->GetOutput());
          std::vector<std::size_t> turned;
          bool                     accepted = false; // (clean when the loop left it)
          for (int round = 0; round < 12; ++round)
            {
              turned.clear();
              turned_triangles(decimated, front, locator.Get(), &turned);
              for (const std::size_t t : folds::crossing_triangles(decimated))
                if (std::find(turned.begin(), turned.end(), t) == turned.end())
                  turned.push_back(t);
              if (turned.empty())
                {
                  if ((accepted = the_stl_reader_accepts(decimated)) ||
                      folds::flip_with_a_neighbour(decimated, folds::caps(decimated, 1e-4, 1e-5 * extent)) == 0)
                    break;
                  continue; // (the flips are checked)
                }
              std::vector<std::size_t> placed_turned;
              for (const std::size_t t : turned)
                {
                  bool moved = false;
                  for (const long v : decimated.triangles[t])
                    if (!std::equal(&placed.points[3 * v], &placed.points[3 * v + 3], &decimated.points[3 * v]))
                      std::copy_n(&placed.points[3 * v], 3, &decimated.points[3 * v]), moved = true;
                  if (!moved)
                    placed_turned.push_back(t);
                }
              if (folds::flip_with_a_neighbour(decimated, placed_turned) == 0 && placed_turned.size() == turned.size())
                break; // (nothing changed)
            }
          if (accepted || (turned_triangles(decimated, front, locator.Get()) == 0 &&
                           folds::crossing_triangles(decimated).empty() && the_stl_reader_accepts(decimated)))
            return decimated;
        }
      return kept;
    }
  } // namespace

  ErodedSurface eroded_surface(const io::PolyData &surface, const std::vector<double> &depth, double h,
                               double edge_length, io::Timers *timers)
  {
    if (depth.size() != surface.points.size() / 3)
      throw std::logic_error("eroded_surface: one depth per point expected");
    if (!(h > 0))
      throw std::logic_error("eroded_surface: the grid spacing must be positive");
    io::Timers  unused;
    io::Timers &clock = timers ? *timers : unused;
    const auto  step  = [&](const char *name) { return io::ScopedTimer(clock, std::string("surface as a set: ") + name); };

    // g = min(phi, the balls) on the grid, and its zero set: W = { g > 0 }
    const Grid                      grid(surface, h);
    const geometry::SurfaceDistance distance(surface.points, surface.triangles);
    const WornFront                 worn(surface, depth, 2 * h);
    std::vector<float>              g;
    {
      const auto t = step("signed distance");
      g            = signed_distance_on(grid, distance);
    }
    {
      const auto t = step("balls");
      carve_the_balls(grid, worn, g);
    }
    ErodedSurface result;
    result.spacing = h;
    vtkSmartPointer<vtkPolyData> front;
    {
      const auto t = step("zero set");
      front        = largest_piece_of_the_zero_set(grid, g, result.volume_cut_off);
    }

    // onto the exact zero set (marching cubes cuts every edge and corner of the front), to the
    // target length, and without folds
    const ExactFront exact(distance, worn, h);
    {
      const auto t = step("onto the front");
      onto_the_front_unturned(front, exact, h);
    }
    {
      // (vertices projected onto one point beside a sharp edge are one vertex)
      const auto t = step("merge");
      front        = merged_within(front, 1e-4 * h);
    }
    io::PolyData out;
    {
      const auto t = step("decimation");
      out          = decimated_without_folds(front, edge_length, grid.extent, exact);
    }

    // the last projection can put two vertices onto one point (beside a sharp edge): one vertex,
    // the facets between them dropped (an STL of them has edges of no length, a hole for Gmsh)
    try
      {
        const auto t = step("repair");
        out          = repair_overlapping_facets(out, 1e-4 * h).surface;
      }
    catch (const std::runtime_error &)
      {
        // (a folded plane whose outline could not be triangulated: Gmsh will say what is wrong)
      }
    double volume = enclosed_volume(out);
    if (volume < 0) // flying edges orients towards larger values, here inward: turn the triangles
      {
        for (auto &t : out.triangles)
          std::swap(t[1], t[2]);
        volume = -volume;
      }
    result.surface = std::move(out);
    result.volume  = volume;
    return result;
  }
} // namespace abrade::fem
