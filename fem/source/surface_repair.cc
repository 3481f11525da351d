// Overlapping facets repaired plane by plane (fem/surface_repair.h).
#include <abrade/fem/surface_repair.h>

#include <vtkCellArray.h>
#include <vtkContourTriangulator.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace abrade::fem
{
  namespace
  {
    using Vec = std::array<double, 3>;

    Vec sub(const Vec &a, const Vec &b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    Vec cross(const Vec &a, const Vec &b)
    {
      return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    double dot(const Vec &a, const Vec &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    double norm(const Vec &a) { return std::sqrt(dot(a, a)); }

    /// Union-find over the facets.
    struct Groups
    {
      std::vector<std::size_t> parent;
      explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
      std::size_t find(std::size_t i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }
      void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
    };

    /// The surface's points welded (points within the tolerance's grid cell are one) and its
    /// facets on them; a facet two of whose corners weld into one is dropped (counted in
    /// @p r.collapsed).
    struct Welded
    {
      Welded(const io::PolyData &surface, double tolerance, SurfaceRepair &r)
      {
        std::map<std::array<long long, 3>, long> index;
        auto weld = [&](long p) {
          const Vec x = {surface.points[3 * p], surface.points[3 * p + 1], surface.points[3 * p + 2]};
          const std::array<long long, 3> key = {std::llround(x[0] / tolerance), std::llround(x[1] / tolerance),
                                                std::llround(x[2] / tolerance)};
          const auto [it, added] = index.emplace(key, long(points.size()));
          if (added)
            points.push_back(x);
          return it->second;
        };
        for (const auto &t : surface.triangles)
          {
            const std::array<long, 3> w = {weld(t[0]), weld(t[1]), weld(t[2])};
            if (w[0] == w[1] || w[1] == w[2] || w[2] == w[0])
              ++r.collapsed; // two corners welded: an edge collapsed, no facet
            else
              triangles.push_back(w);
          }
        area.resize(triangles.size());
        for (std::size_t k = 0; k < triangles.size(); ++k)
          {
            const auto &t = triangles[k];
            const Vec   n = cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]));
            area[k]       = {0.5 * n[0], 0.5 * n[1], 0.5 * n[2]};
          }
      }
      std::vector<Vec>                 points;
      std::vector<std::array<long, 3>> triangles;
      std::vector<Vec>                 area; ///< each facet's area vector
    };

    /// Coplanar neighbours (within 0.5 degrees, the other's far corner within the tolerance of
    /// the plane) joined into planes; a pair facing opposite ways whose far corners lie on the
    /// same side of their edge overlaps: both are marked folded (counted in @p r.folds).
    void find_folds(const Welded &w, double tolerance, Groups &planes, std::vector<bool> &folded, SurfaceRepair &r)
    {
      const auto &points = w.points;
      const auto &triangles = w.triangles;
      const auto &area = w.area;
      std::map<std::pair<long, long>, std::vector<std::size_t>> sides; // the facets on either side of each edge
      for (std::size_t k = 0; k < triangles.size(); ++k)
        for (int e = 0; e < 3; ++e)
          {
            const long a = triangles[k][e], b = triangles[k][(e + 1) % 3];
            sides[{std::min(a, b), std::max(a, b)}].push_back(k);
          }
      const double parallel = std::cos(0.5 * M_PI / 180);
      for (const auto &[edge, facets] : sides)
        {
          if (facets.size() != 2)
            continue;
          const std::size_t i = facets[0], j = facets[1];
          const double      ai = norm(area[i]), aj = norm(area[j]);
          if (ai == 0 || aj == 0)
            continue;
          const double c = dot(area[i], area[j]) / (ai * aj);
          if (std::abs(c) < parallel)
            continue;
          // a facet's corner off the shared edge
          auto far_corner = [&, e = edge](std::size_t k) {
            for (long p : triangles[k])
              if (p != e.first && p != e.second)
                return p;
            return triangles[k][0];
          };
          // the other facet's far corner within the tolerance of this facet's plane
          const long far = far_corner(j);
          const Vec  u   = {area[i][0] / ai, area[i][1] / ai, area[i][2] / ai};
          if (std::abs(dot(sub(points[far], points[edge.first]), u)) > tolerance)
            continue;
          planes.join(i, j);
          // facing opposite ways: a fold when both far corners lie on the same side of the edge
          // (the facets overlap); on opposite sides it is one facet turned the wrong way round,
          // which overlaps nothing (left to the closed-surface check)
          const long far_i     = far_corner(i);
          const Vec  along     = sub(points[edge.second], points[edge.first]);
          const bool same_side = dot(cross(along, sub(points[far_i], points[edge.first])), u) *
                                   dot(cross(along, sub(points[far], points[edge.first])), u) >
                                 0;
          if (c < 0 && same_side)
            {
              if (r.folds++ == 0)
                for (int d = 0; d < 3; ++d)
                  r.first_fold[d] = 0.5 * (points[edge.first][d] + points[edge.second][d]);
              folded[i] = folded[j] = true;
            }
        }
    }

    /// One plane's @p facets replaced by a triangulation of its outline (the directed edges
    /// left once opposite pairs cancel), into @p added, facing as the plane's net area; a flap
    /// folded back onto itself (no outline, no net area) adds nothing. Throws where the
    /// outline does not bound the net area.
    void retriangulate_plane(const Welded &w, const std::vector<std::size_t> &facets, double tolerance,
                             std::vector<std::array<long, 3>> &added)
    {
      const auto &points = w.points;
      const auto &triangles = w.triangles;
      Vec         net = {0, 0, 0};
      std::map<std::pair<long, long>, int> outline; // directed edge -> how many times, opposite pairs cancelled
      for (std::size_t k : facets)
        {
          for (int d = 0; d < 3; ++d)
            net[d] += w.area[k][d];
          for (int e = 0; e < 3; ++e)
            {
              const long a = triangles[k][e], b = triangles[k][(e + 1) % 3];
              if (auto back = outline.find({b, a}); back != outline.end())
                {
                  if (--back->second == 0)
                    outline.erase(back);
                }
              else
                ++outline[{a, b}];
            }
        }
      const double net_area = norm(net);
      const auto  &p0       = points[triangles[facets.front()][0]];
      if (outline.empty() && net_area <= tolerance * tolerance)
        return; // a flap folded back onto itself: nothing of it is the part's surface
      vtkNew<vtkPoints>         vp;
      vtkNew<vtkCellArray>      lines;
      std::map<long, vtkIdType> local;
      std::vector<long>         global;
      auto id = [&](long p) {
        const auto [it, fresh] = local.emplace(p, vtkIdType(global.size()));
        if (fresh)
          global.push_back(p), vp->InsertNextPoint(points[p].data());
        return it->second;
      };
      for (const auto &[edge, times] : outline)
        {
          if (times != 1)
            throw std::runtime_error("the face near (" + std::to_string(p0[0]) + ", " + std::to_string(p0[1]) + ", " +
                                     std::to_string(p0[2]) + ") is covered more than once by its facets");
          const vtkIdType ends[2] = {id(edge.first), id(edge.second)};
          lines->InsertNextCell(2, ends);
        }
      vtkNew<vtkPolyData> contours;
      contours->SetPoints(vp);
      contours->SetLines(lines);
      vtkNew<vtkCellArray> polys;
      const double         normal[3] = {net[0] / net_area, net[1] / net_area, net[2] / net_area};
      const int ok = vtkContourTriangulator::TriangulateContours(contours, 0, lines->GetNumberOfCells(), polys, normal);
      double            filled = 0;
      vtkNew<vtkIdList> cell;
      for (polys->InitTraversal(); polys->GetNextCell(cell);)
        {
          if (cell->GetNumberOfIds() != 3)
            continue;
          std::array<long, 3> t = {global[cell->GetId(0)], global[cell->GetId(1)], global[cell->GetId(2)]};
          const Vec           n = cross(sub(points[t[1]], points[t[0]]), sub(points[t[2]], points[t[0]]));
          if (dot(n, net) < 0)
            std::swap(t[1], t[2]);
          filled += 0.5 * norm(n);
          added.push_back(t);
        }
      // the triangulation must cover the face's net area (an outline that crosses itself does not)
      if (!ok || std::abs(filled - net_area) > 1e-6 * net_area + tolerance * tolerance)
        throw std::runtime_error("the overlapping facets of the face near (" + std::to_string(p0[0]) + ", " +
                                 std::to_string(p0[1]) + ", " + std::to_string(p0[2]) +
                                 ") could not be replaced: its outline does not bound its area");
    }
  } // namespace

  SurfaceRepair repair_overlapping_facets(const io::PolyData &surface, double tolerance)
  {
    SurfaceRepair     r;
    const Welded      w(surface, tolerance, r);
    Groups            planes(w.triangles.size());
    std::vector<bool> folded(w.triangles.size(), false);
    find_folds(w, tolerance, planes, folded, r);

    // every plane with a fold: its facets replaced by a triangulation of its outline
    std::map<std::size_t, std::vector<std::size_t>> members;
    for (std::size_t k = 0; k < w.triangles.size(); ++k)
      if (folded[k])
        members[planes.find(k)];
    for (std::size_t k = 0; k < w.triangles.size(); ++k)
      if (auto it = members.find(planes.find(k)); it != members.end())
        it->second.push_back(k);
    std::vector<bool>                replaced(w.triangles.size(), false);
    std::vector<std::array<long, 3>> added;
    for (const auto &[root, facets] : members)
      {
        ++r.planes;
        for (std::size_t k : facets)
          replaced[k] = true;
        retriangulate_plane(w, facets, tolerance, added);
      }

    // the repaired surface: the kept facets and the new ones, on the points they use
    std::vector<long> renumber(w.points.size(), -1);
    auto use = [&](long p) {
      if (renumber[p] < 0)
        {
          renumber[p] = long(r.surface.points.size() / 3);
          r.surface.points.insert(r.surface.points.end(), w.points[p].begin(), w.points[p].end());
        }
      return renumber[p];
    };
    for (std::size_t k = 0; k < w.triangles.size(); ++k)
      if (!replaced[k])
        r.surface.triangles.push_back({use(w.triangles[k][0]), use(w.triangles[k][1]), use(w.triangles[k][2])});
    for (const auto &t : added)
      r.surface.triangles.push_back({use(t[0]), use(t[1]), use(t[2])});
    return r;
  }
} // namespace abrade::fem
