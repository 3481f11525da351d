// The worn surface as the zero set of an implicit function on a grid (eroded_surface.h).
#include <abrade/common/error.h>
#include <abrade/common/surface_distance.h>
#include <abrade/fem/eroded_surface.h>
#include <abrade/fem/surface_check.h>
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
#include <vtkSmartPointer.h>
#include <vtkQuadricDecimation.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangleFilter.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <map>
#include <unordered_map>

namespace abrade::fem
{
  namespace
  {
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
    /// normal more than 120 degrees from the one of the reference triangle closest to their
    /// centre: turned over by a collapse; a triangle across a sharp edge of the front is up to
    /// half the edge's turn from either face, and its closest reference triangle may lie on
    /// the other face), the edges of @p s not shared by exactly two triangles, and the pairs
    /// of triangles that cross (surface_check.h).
    std::size_t turned_triangles(const io::PolyData &s, vtkPolyData *reference, std::vector<std::size_t> *turned = nullptr)
    {
      vtkNew<vtkStaticCellLocator> locator;
      locator->SetDataSet(reference);
      locator->BuildLocator();
      auto normal = [](const double *a, const double *b, const double *c) {
        const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        return std::array<double, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
      };
      std::size_t       bad = 0;
      vtkNew<vtkIdList> ids;
      // whether the normal m is opposed to the one of the reference triangle closest to x
      auto opposed = [&](const double *x, const std::array<double, 3> &m) {
        double    closest[3], d2 = 0;
        vtkIdType cell = -1;
        int       sub  = 0;
        locator->FindClosestPoint(x, closest, cell, sub, d2);
        if (cell < 0)
          return false;
        reference->GetCellPoints(cell, ids);
        if (ids->GetNumberOfIds() != 3)
          return false;
        double p[3][3];
        for (int q = 0; q < 3; ++q)
          reference->GetPoint(ids->GetId(q), p[q]);
        const auto   n  = normal(p[0], p[1], p[2]);
        const double mn = std::sqrt((m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) * (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]));
        return m[0] * n[0] + m[1] * n[1] + m[2] * n[2] < -0.5 * mn;
      };
      for (std::size_t k = 0; k < s.triangles.size(); ++k)
        {
          const auto   &t = s.triangles[k];
          const double *a = &s.points[3 * t[0]], *b = &s.points[3 * t[1]], *c = &s.points[3 * t[2]];
          double        centre[3];
          for (int q = 0; q < 3; ++q)
            centre[q] = (a[q] + b[q] + c[q]) / 3;
          // against the reference closest to its centre and to each corner: beside a sharp
          // edge one of them can lie on the other face, a turned triangle is turned against all
          const auto m = normal(a, b, c);
          if (opposed(centre, m) && opposed(a, m) && opposed(b, m) && opposed(c, m))
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
      if (bad == 0)
        for (const auto &pair : intersecting_triangles(s))
          {
            ++bad;
            if (turned)
              turned->insert(turned->end(), pair.begin(), pair.end());
          }
      return bad;
    }

    io::PolyData from_vtk(vtkPolyData *p)
    {
      io::PolyData out;
      out.points.resize(3 * p->GetNumberOfPoints());
      for (vtkIdType k = 0; k < p->GetNumberOfPoints(); ++k)
        p->GetPoint(k, &out.points[3 * k]);
      vtkNew<vtkIdList> ids;
      for (vtkIdType c = 0; c < p->GetNumberOfCells(); ++c)
        {
          p->GetCellPoints(c, ids);
          if (ids->GetNumberOfIds() == 3)
            out.triangles.push_back({long(ids->GetId(0)), long(ids->GetId(1)), long(ids->GetId(2))});
        }
      return out;
    }


    /// The sharp edges of a surface (its two triangles' normals more than 20 degrees apart), in
    /// a hash grid of cells of a given size, for the closest point on them.
    struct SharpEdges
    {
      std::vector<std::array<double, 6>>                   segment;
      double                                               cell = 1;
      std::unordered_map<long long, std::vector<unsigned>> cells;

      SharpEdges(const io::PolyData &s, double cell_size) : cell(cell_size)
      {
        // points at one place are one (a surface may repeat them face by face), to a
        // millionth of the cell
        std::map<std::array<long long, 3>, long> first;
        std::vector<long>                         same(s.points.size() / 3);
        for (std::size_t v = 0; v < same.size(); ++v)
          {
            const std::array<long long, 3> at = {std::llround(s.points[3 * v] / (1e-6 * cell)),
                                                 std::llround(s.points[3 * v + 1] / (1e-6 * cell)),
                                                 std::llround(s.points[3 * v + 2] / (1e-6 * cell))};
            same[v] = first.emplace(at, long(v)).first->second;
          }
        std::map<std::pair<long, long>, std::vector<std::size_t>> edges;
        for (std::size_t k = 0; k < s.triangles.size(); ++k)
          for (int e = 0; e < 3; ++e)
            {
              const long a = same[s.triangles[k][e]], b = same[s.triangles[k][(e + 1) % 3]];
              edges[{std::min(a, b), std::max(a, b)}].push_back(k);
            }
        auto unit_normal = [&](std::size_t k) {
          const double *a = &s.points[3 * s.triangles[k][0]], *b = &s.points[3 * s.triangles[k][1]],
                       *c = &s.points[3 * s.triangles[k][2]];
          const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
          std::array<double, 3> n = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
          const double          l = std::hypot(n[0], n[1], n[2]);
          for (double &x : n)
            x = l > 0 ? x / l : 0;
          return n;
        };
        for (const auto &[edge, pair] : edges)
          {
            if (pair.size() != 2)
              continue;
            const auto n1 = unit_normal(pair[0]), n2 = unit_normal(pair[1]);
            if (n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2] > std::cos(20 * M_PI / 180))
              continue;
            const double *a = &s.points[3 * edge.first], *b = &s.points[3 * edge.second];
            const auto    id = static_cast<unsigned>(segment.size());
            segment.push_back({a[0], a[1], a[2], b[0], b[1], b[2]});
            long lo[3], hi[3];
            for (int c = 0; c < 3; ++c)
              lo[c] = long(std::floor(std::min(a[c], b[c]) / cell)), hi[c] = long(std::floor(std::max(a[c], b[c]) / cell));
            for (long i = lo[0]; i <= hi[0]; ++i)
              for (long j = lo[1]; j <= hi[1]; ++j)
                for (long k = lo[2]; k <= hi[2]; ++k)
                  cells[key(i, j, k)].push_back(id);
          }
      }

      static long long key(long i, long j, long k) { return (i * 73856093LL) ^ (j * 19349663LL) ^ (k * 83492791LL); }

      /// The closest point on a sharp edge within one cell of @p x, and its distance (infinity
      /// where there is none).
      double closest(const double *x, double *on_edge) const
      {
        double best = std::numeric_limits<double>::infinity();
        const long i0 = long(std::floor(x[0] / cell)), j0 = long(std::floor(x[1] / cell)), k0 = long(std::floor(x[2] / cell));
        for (long i = i0 - 1; i <= i0 + 1; ++i)
          for (long j = j0 - 1; j <= j0 + 1; ++j)
            for (long k = k0 - 1; k <= k0 + 1; ++k)
              if (const auto it = cells.find(key(i, j, k)); it != cells.end())
                for (const unsigned q : it->second)
                  {
                    const auto  &g = segment[q];
                    const double d[3] = {g[3] - g[0], g[4] - g[1], g[5] - g[2]};
                    const double dd   = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    const double t    = dd > 0 ? std::clamp(((x[0] - g[0]) * d[0] + (x[1] - g[1]) * d[1] + (x[2] - g[2]) * d[2]) / dd, 0.0, 1.0) : 0.0;
                    const double p[3] = {g[0] + t * d[0], g[1] + t * d[1], g[2] + t * d[2]};
                    const double r    = std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]);
                    if (r < best)
                      best = r, std::copy_n(p, 3, on_edge);
                  }
        return best;
      }
    };

    /// The corners of the triangles @p bad names (it returns how many are bad and lists them)
    /// go back from where @p s has them (the projection's points) towards @p from, half the
    /// way each time, all the way after eight times: whether none is left bad.
    template <typename Bad>
    bool step_back(io::PolyData &s, const io::PolyData &from, Bad bad)
    {
      const std::vector<double> to = s.points;
      std::vector<double>       share(s.points.size() / 3, 1.0);
      for (int round = 0; round <= 8; ++round)
        {
          std::vector<std::size_t> listed;
          if (bad(s, listed) == 0)
            return true;
          if (listed.empty() || round == 8)
            return false; // not the projection's doing, or not undone by it
          const double keep = round == 7 ? 0.0 : std::ldexp(1.0, -(round + 1)); // of the step
          for (const std::size_t t : listed)
            for (const long v : s.triangles[t])
              share[v] = std::min(share[v], keep);
          for (std::size_t k = 0; k < s.points.size(); ++k)
            s.points[k] = from.points[k] + share[k / 3] * (to[k] - from.points[k]);
        }
      return false;
    }
  } // namespace

  ErodedSurface eroded_surface(const io::PolyData &surface, const std::vector<double> &depth, double h,
                               double edge_length)
  {
    if (depth.size() != surface.points.size() / 3)
      throw std::logic_error("eroded_surface: one depth per point expected");
    if (!(h > 0))
      throw std::logic_error("eroded_surface: the grid spacing must be positive");

    // the grid: the surface's box and a margin, offset by an irrational fraction of h
    std::array<double, 3> lo{}, hi{};
    for (int c = 0; c < 3; ++c)
      lo[c] = std::numeric_limits<double>::infinity(), hi[c] = -lo[c];
    for (std::size_t k = 0; k < surface.points.size(); ++k)
      lo[k % 3] = std::min(lo[k % 3], surface.points[k]), hi[k % 3] = std::max(hi[k % 3], surface.points[k]);
    std::array<long, 3> n{};
    for (int c = 0; c < 3; ++c)
      {
        lo[c] -= (3 + 0.31830988618) * h;
        n[c] = static_cast<long>(std::ceil((hi[c] + 3 * h - lo[c]) / h)) + 1;
      }
    const long          n_nodes = n[0] * n[1] * n[2];
    std::vector<float> g(n_nodes);
    auto node = [&](long i, long j, long k) { return i + n[0] * (j + n[1] * k); };

    // phi, > 0 inside: exact near the surface, the sign (and a lower bound) elsewhere
    const geometry::SurfaceDistance distance(surface.points, surface.triangles);
    constexpr long                  B = 6;
    const long                      nb[3] = {(n[0] + B - 1) / B, (n[1] + B - 1) / B, (n[2] + B - 1) / B};
    const double                    half_diagonal = 0.5 * (B - 1) * h * std::sqrt(3.0);
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
                g[node(i, j, k)] = float(far ? std::copysign(std::abs(phi_centre) - half_diagonal, phi_centre)
                                             : -distance.signed_distance(x));
              }
      }

    // the wear: the union of the balls of radius d(p) about every point of the worn triangles
    // (worn_front.h), on the nodes within the reach of each triangle's deepest ball
    const WornFront worn(surface, depth, 2 * h);
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
                float       &gn   = g[node(i, j, k)];
                const double ball = t.distance(x, foot);
                if (ball < gn)
                  gn = float(ball);
              }
      }

    // the zero set
    vtkNew<vtkImageData> image;
    image->SetDimensions(int(n[0]), int(n[1]), int(n[2]));
    image->SetOrigin(lo[0], lo[1], lo[2]);
    image->SetSpacing(h, h, h);
    vtkNew<vtkFloatArray> values;
    values->SetName("g");
    values->SetNumberOfTuples(n_nodes);
    for (long k = 0; k < n_nodes; ++k)
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

    ErodedSurface result;
    result.spacing = h;
    // the pieces: the largest is the part; the others, cut off by the wear, are dropped
    {
      vtkNew<vtkPolyDataConnectivityFilter> regions;
      regions->SetInputConnection(contour->GetOutputPort());
      regions->SetExtractionModeToAllRegions();
      regions->ColorRegionsOn();
      regions->Update();
      vtkPolyData       *all = regions->GetOutput();
      vtkDataArray      *id  = all->GetPointData()->GetArray("RegionId"); // per point (VTK 9.1)
      std::vector<double> piece(regions->GetNumberOfExtractedRegions(), 0.0);
      vtkNew<vtkIdList>  ids;
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
          result.volume_cut_off += std::abs(piece[k]);
    }

    vtkNew<vtkPolyDataConnectivityFilter> largest;
    largest->SetInputConnection(contour->GetOutputPort());
    largest->SetExtractionModeToLargestRegion();
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(largest->GetOutputPort());
    clean->Update();
    vtkIdType cells = clean->GetOutput()->GetNumberOfCells();
    if (cells == 0)
      throw RunError("the wear leaves nothing of the part (every point is worn away)");

    // onto the exact zero set: marching cubes cuts every edge and corner of the front; each of
    // its vertices goes to the nearest point of the piece of the front nearest to it (the old
    // surface, or the sphere of the ball that removed the most there), which puts the vertices
    // beside a sharp edge onto its faces, so that the decimation's quadrics find the edge; the
    // decimated vertices, which the quadrics place off the front by up to a spacing, go back
    // onto it the same way
    auto project = [&](vtkPoints *points) {
#pragma omp parallel for schedule(dynamic, 256)
      for (vtkIdType k = 0; k < points->GetNumberOfPoints(); ++k)
        {
          double x[3];
          points->GetPoint(k, x);
          for (int iteration = 0; iteration < 64; ++iteration)
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
    };
    project(clean->GetOutput()->GetPoints());
    // marching cubes chamfers the unworn surface's sharp edges (a strip of needles a quarter
    // to a spacing wide, which the decimation widens): vertices within a spacing of one, on
    // the unworn surface and in no ball there, go onto it, which makes the strip's triangles
    // flat (undone where that makes triangles cross); before the decimation and after it. The
    // lifetime loop's knife flips the flat triangles away (surface_tidy.h).
    const SharpEdges sharp(surface, h);
    auto snap_to_sharp_edges = [&](io::PolyData &s, double within) {
      const io::PolyData unsnapped = s;
      for (std::size_t v = 0; v < s.points.size() / 3; ++v)
        {
          double *x = &s.points[3 * v], on_edge[3], on_ball[3], on_surface[3];
          bool    rim = false;
          if (std::abs(distance.signed_distance(x, rim, on_surface)) > 1e-6 * h ||
              sharp.closest(x, on_edge) > within || worn.distance(on_edge, on_ball) < 1e-6 * h)
            continue;
          std::copy_n(on_edge, 3, x);
        }
      // the corners of crossing triangles go back, in rounds (a corner put back can make its
      // neighbour cross); if crossings remain, nothing is snapped
      for (int round = 0;; ++round)
        {
          const auto pairs = intersecting_triangles(s, std::numeric_limits<std::size_t>::max(), 1e-4 * h);
          if (pairs.empty())
            break;
          if (round == 32)
            {
              s = unsnapped;
              break;
            }
          for (const auto &pair : pairs)
            for (const std::size_t t : pair)
              for (const long v : s.triangles[t])
                std::copy_n(&unsnapped.points[3 * v], 3, &s.points[3 * v]);
        }
    };
    // the front's own sharp edges (a chisel's worn tip, the rim of a worn face): marching
    // cubes cuts them by up to a spacing across (at the 41-degree chisel's tip the cut raised the
    // tip by 0.8 of a spacing), and the decimation keeps the cut; each vertex of the worn front
    // whose neighbours' normals there turn by more than 20 degrees goes to the point nearest
    // to it of their tangent planes (dual contouring's placement: onto the edge where two
    // faces meet, onto the corner where three), where that point lies within a spacing and on
    // the front (within 0.005 of a spacing); undone where a triangle turns or crosses that did not
    // before (against @p reference). After the
    // decimation only: a vertex a decimated triangle's width from the edge cannot reach it
    // (the decimation keeps marching cubes' chamfer there), but placed on the marching-cubes
    // surface before it, the decimated surface of the STEP knife of lifetime/file_part had a
    // segment through a facet at its fourth update (Gmsh refused it; the check did not find it)
    auto place_front_edges = [&](io::PolyData &s, vtkPolyData *reference) {
      const io::PolyData unsharpened = s;
      const std::size_t  nv          = s.points.size() / 3;
      std::vector<std::array<double, 3>> normal(nv, {0, 0, 0});
      std::vector<char>                  on_worn(nv, 0);
      auto front_value = [&](const double *x, double *n) {
        bool         rim = false;
        double       on_surface[3], on_front[3];
        const double phi = -distance.signed_distance(x, rim, on_surface);
        const double f   = worn.distance(x, on_front, n);
        return std::pair<double, bool>{std::min(phi, f), f < phi};
      };
      for (std::size_t v = 0; v < nv; ++v)
        {
          const auto [value, worn_piece] = front_value(&s.points[3 * v], normal[v].data());
          on_worn[v] = worn_piece && std::abs(value) < 1e-3 * h;
        }
      std::vector<std::vector<long>> ring(nv);
      for (const auto &t : s.triangles)
        for (int e = 0; e < 3; ++e)
          ring[t[e]].push_back(t[(e + 1) % 3]), ring[t[e]].push_back(t[(e + 2) % 3]);
      std::vector<double> moved = s.points;
      for (std::size_t v = 0; v < nv; ++v)
        {
          if (!on_worn[v])
            continue;
          std::vector<long> planes = ring[v];
          std::sort(planes.begin(), planes.end());
          planes.erase(std::unique(planes.begin(), planes.end()), planes.end());
          planes.push_back(long(v));
          double turn = 1;
          for (const long p : planes)
            if (on_worn[p])
              turn = std::min(turn, normal[v][0] * normal[p][0] + normal[v][1] * normal[p][1] + normal[v][2] * normal[p][2]);
          if (turn > std::cos(20 * M_PI / 180))
            continue;
          // min sum (n . (x - y))^2 + lambda |x - v|^2: lambda fixes the position along the
          // edge, where the planes leave it free, and is small beside the planes' weight across
          // a shallow edge (2 sin^2(10 degrees) per pair of planes at a 20-degree one): with
          // 1e-3 the point was pulled into the part there by a few hundredths of a millimetre
          double       A[3][3] = {}, b[3] = {};
          const double lambda  = 1e-6;
          const double *xv     = &s.points[3 * v];
          for (const long p : planes)
            {
              if (!on_worn[p])
                continue;
              const auto   &n = normal[p];
              const double *y = &s.points[3 * p];
              const double  ny = n[0] * y[0] + n[1] * y[1] + n[2] * y[2];
              for (int i = 0; i < 3; ++i)
                {
                  for (int j = 0; j < 3; ++j)
                    A[i][j] += n[i] * n[j];
                  b[i] += n[i] * ny;
                }
            }
          for (int i = 0; i < 3; ++i)
            A[i][i] += lambda, b[i] += lambda * xv[i];
          const double det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
                             A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
                             A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
          if (!(std::abs(det) > 0))
            continue;
          double x[3];
          for (int c = 0; c < 3; ++c)
            {
              double M[3][3];
              for (int i = 0; i < 3; ++i)
                for (int j = 0; j < 3; ++j)
                  M[i][j] = j == c ? b[i] : A[i][j];
              x[c] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                      M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) / det;
            }
          double unused[3];
          if (std::hypot(x[0] - xv[0], x[1] - xv[1], x[2] - xv[2]) < h && std::abs(front_value(x, unused).first) < 0.005 * h)
            std::copy_n(x, 3, &moved[3 * v]);
        }
      // the corners of a turned or crossing triangle go back, until none is left that was not
      // there before (a corner put back can make its neighbour cross: rounds; the marching
      // cubes' needle strips flattened onto an unworn sharp edge touch their neighbours)
      std::vector<std::size_t> before;
      const std::size_t        bad_before = turned_triangles(s, reference, &before);
      std::sort(before.begin(), before.end());
      s.points           = moved;
      bool clean_surface = false;
      for (int round = 0; round < 32 && !clean_surface; ++round)
        {
          std::vector<std::size_t> listed;
          const std::size_t        bad = turned_triangles(s, reference, &listed);
          std::vector<std::size_t> added;
          std::sort(listed.begin(), listed.end());
          std::set_difference(listed.begin(), listed.end(), before.begin(), before.end(), std::back_inserter(added));
          if (bad <= bad_before && added.empty())
            clean_surface = true;
          else if (added.empty())
            break; // not the placement's doing
          for (const std::size_t t : added)
            for (const long v : s.triangles[t])
              std::copy_n(&unsharpened.points[3 * v], 3, &s.points[3 * v]);
        }
      if (!clean_surface)
        s = unsharpened;
    };
    vtkNew<vtkPolyData> unplaced;
    {
      io::PolyData mc = from_vtk(clean->GetOutput());
      snap_to_sharp_edges(mc, h); // its vertices nearest an edge lie up to a spacing from it
      vtkPoints *points = clean->GetOutput()->GetPoints();
      for (vtkIdType v = 0; v < points->GetNumberOfPoints(); ++v)
        points->SetPoint(v, &mc.points[3 * v]);
      points->Modified();
      unplaced->DeepCopy(clean->GetOutput());
    }
    // vertices projected onto one point (beside a sharp edge) are one vertex, and the triangles
    // they squash are dropped: no zero-area or repeated facets for the decimation and Gmsh
    auto merged_points = [h](vtkPolyData *surface) {
      vtkNew<vtkCleanPolyData> merged;
      merged->SetInputData(surface);
      merged->ToleranceIsAbsoluteOn();
      merged->SetAbsoluteTolerance(1e-4 * h);
      merged->ConvertLinesToPointsOff();
      merged->ConvertPolysToLinesOff();
      merged->ConvertStripsToPolysOff();
      vtkNew<vtkTriangleFilter> only_triangles;
      only_triangles->SetInputConnection(merged->GetOutputPort());
      only_triangles->PassLinesOff();
      only_triangles->PassVertsOff();
      only_triangles->Update();
      vtkSmartPointer<vtkPolyData> out = only_triangles->GetOutput();
      return out;
    };
    const vtkSmartPointer<vtkPolyData> front = merged_points(unplaced);
    cells                                    = front->GetNumberOfCells();

    // to about the target edge length (equilateral triangles of that edge over the area)
    double area = 0;
    const io::PolyData kept = from_vtk(front);
    for (const auto &t : kept.triangles)
      {
        const double *a = &kept.points[3 * t[0]], *b = &kept.points[3 * t[1]], *c = &kept.points[3 * t[2]];
        const double  u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        area += 0.5 * std::hypot(u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]);
      }
    // Quadric decimation does not check what its collapses do to the neighbours: a triangle
    // can turn over onto its neighbour (Gmsh then finds overlapping facets). A decimation with a
    // turned triangle is done again with twice the triangles, while that is fewer than
    // marching cubes made; then the
    // surface stays as marching cubes made it (its vertices projected).
    io::PolyData out = kept;
    for (double wanted = area / (0.433 * edge_length * edge_length); wanted < 0.9 * cells; wanted *= 2)
      {
        vtkNew<vtkQuadricDecimation> decimate;
        decimate->SetInputData(front);
        decimate->SetTargetReduction(1.0 - wanted / double(cells));
        decimate->VolumePreservationOn();
        vtkNew<vtkTriangleFilter> triangles;
        triangles->SetInputConnection(decimate->GetOutputPort());
        triangles->Update();
        const io::PolyData placed = from_vtk(triangles->GetOutput()); // where the quadrics put them
        project(triangles->GetOutput()->GetPoints());
        io::PolyData             decimated = from_vtk(triangles->GetOutput());
        // the projection can turn or cross a small triangle beside a sharp edge: its corners
        // go back towards where the quadrics put them
        const bool clean_surface = step_back(decimated, placed, [&](const io::PolyData &x, std::vector<std::size_t> &listed) {
          return turned_triangles(x, front, &listed);
        });
        if (clean_surface)
          {
            out = std::move(decimated);
            break;
          }
      }
    place_front_edges(out, front);
    snap_to_sharp_edges(out, h / 2);
    double volume = enclosed_volume(out);
    if (volume < 0) // flying edges orients towards larger values, here inward: turn the triangles
      {
        for (auto &t : out.triangles)
          std::swap(t[1], t[2]);
        volume = -volume;
      }
    result.surface        = std::move(out);
    result.volume         = volume;
    return result;
  }
} // namespace abrade::fem
