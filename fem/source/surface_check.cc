// Self-intersections of a triangle surface (surface_check.h).
#include <abrade/fem/surface_check.h>

#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticCellLocator.h>
#include <vtkTriangle.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace abrade::fem
{
  namespace
  {
    using Vec = std::array<double, 3>;

    Vec sub(const double *a, const double *b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
    Vec cross(const Vec &a, const Vec &b)
    {
      return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
    double dot(const Vec &a, const Vec &b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
    double norm(const Vec &a) { return std::sqrt(dot(a, a)); }

    /// Whether the segment p q meets the triangle a b c (Moeller-Trumbore), ends and rim included.
    bool segment_meets_triangle(const double *p, const double *q, const double *a, const double *b, const double *c)
    {
      const Vec    d = sub(q, p), e1 = sub(b, a), e2 = sub(c, a);
      const Vec    s   = cross(d, e2);
      const double det = dot(e1, s);
      const double scale = norm(d) * norm(e1) * norm(e2);
      if (std::abs(det) <= 1e-12 * scale)
        return false; // parallel to the plane: the pair's other edge or the fold test decides
      const double eps = 1e-10;
      const Vec    tv  = sub(p, a);
      const double u   = dot(tv, s) / det;
      if (u < -eps || u > 1 + eps)
        return false;
      const Vec    r = cross(tv, e1);
      const double v = dot(d, r) / det;
      if (v < -eps || u + v > 1 + eps)
        return false;
      const double t = dot(e2, r) / det;
      return t >= -eps && t <= 1 + eps;
    }
  } // namespace

  std::vector<std::array<std::size_t, 2>> intersecting_triangles(const io::PolyData &surface, std::size_t at_most,
                                                                 double merge_distance)
  {
    std::vector<std::array<std::size_t, 2>> out;
    if (surface.triangles.empty() || at_most == 0)
      return out;
    // points closer than merge_distance: one (the first of them), by a hash of cells of that size
    io::PolyData merged;
    const io::PolyData &s = merge_distance > 0 ? merged : surface;
    if (merge_distance > 0)
      {
        const std::size_t n = surface.points.size() / 3;
        std::vector<long> same(n);
        std::unordered_map<long long, std::vector<long>> cells;
        auto key = [&](const double *x, int di, int dj, int dk) {
          return (static_cast<long long>(std::floor(x[0] / merge_distance) + di) * 73856093LL) ^
                 (static_cast<long long>(std::floor(x[1] / merge_distance) + dj) * 19349663LL) ^
                 (static_cast<long long>(std::floor(x[2] / merge_distance) + dk) * 83492791LL);
        };
        for (std::size_t v = 0; v < n; ++v)
          {
            const double *x = &surface.points[3 * v];
            same[v]         = long(v);
            for (int di = -1; di <= 1 && same[v] == long(v); ++di)
              for (int dj = -1; dj <= 1 && same[v] == long(v); ++dj)
                for (int dk = -1; dk <= 1 && same[v] == long(v); ++dk)
                  if (const auto it = cells.find(key(x, di, dj, dk)); it != cells.end())
                    for (const long w : it->second)
                      if (std::hypot(x[0] - surface.points[3 * w], x[1] - surface.points[3 * w + 1],
                                     x[2] - surface.points[3 * w + 2]) <= merge_distance)
                        {
                          same[v] = w;
                          break;
                        }
            if (same[v] == long(v))
              cells[key(x, 0, 0, 0)].push_back(long(v));
          }
        merged.points = surface.points;
        // a squashed triangle keeps its place in the list (the pairs name the surface's
        // triangles), skipped below
        for (const auto &t : surface.triangles)
          merged.triangles.push_back({same[t[0]], same[t[1]], same[t[2]]});
      }
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (std::size_t k = 0; k < s.points.size() / 3; ++k)
      points->InsertNextPoint(&s.points[3 * k]);
    vtkNew<vtkCellArray> cells;
    for (const auto &t : s.triangles)
      {
        const vtkIdType ids[3] = {t[0], t[1], t[2]};
        cells->InsertNextCell(3, ids);
      }
    vtkNew<vtkPolyData> polydata;
    polydata->SetPoints(points);
    polydata->SetPolys(cells);
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(polydata);
    locator->BuildLocator();

    auto at = [&](long v) { return &s.points[3 * v]; };
    // a triangle of no area (its corners on one line) has no inside to cross: skipped, as a
    // squashed one is (an edge flip takes it away, surface_tidy.h)
    auto flat = [&](const std::array<long, 3> &t) {
      const Vec    u = sub(at(t[1]), at(t[0])), w = sub(at(t[2]), at(t[0]));
      const Vec    e = {w[0] - u[0], w[1] - u[1], w[2] - u[2]};
      const double longest = std::max({dot(u, u), dot(w, w), dot(e, e)});
      return norm(cross(u, w)) <= 1e-12 * longest;
    };
    vtkNew<vtkIdList> near;
    for (std::size_t i = 0; i < s.triangles.size(); ++i)
      {
        const auto &a = s.triangles[i];
        if (a[0] == a[1] || a[1] == a[2] || a[2] == a[0] || flat(a))
          continue; // squashed by the merge, or of no area
        double      box[6];
        for (int c = 0; c < 3; ++c)
          {
            box[2 * c]     = std::min({at(a[0])[c], at(a[1])[c], at(a[2])[c]});
            box[2 * c + 1] = std::max({at(a[0])[c], at(a[1])[c], at(a[2])[c]});
          }
        const double pad = 1e-9 * std::max({box[1] - box[0], box[3] - box[2], box[5] - box[4]});
        for (int c = 0; c < 3; ++c)
          box[2 * c] -= pad, box[2 * c + 1] += pad;
        locator->FindCellsWithinBounds(box, near);
        for (vtkIdType k = 0; k < near->GetNumberOfIds(); ++k)
          {
            const auto j = static_cast<std::size_t>(near->GetId(k));
            if (j <= i)
              continue;
            const auto &b = s.triangles[j];
            if (b[0] == b[1] || b[1] == b[2] || b[2] == b[0] || flat(b))
              continue;
            // the vertices they share, and each one's others
            std::vector<long> shared, only_a, only_b;
            for (const long v : a)
              (std::find(b.begin(), b.end(), v) != b.end() ? shared : only_a).push_back(v);
            for (const long v : b)
              if (std::find(a.begin(), a.end(), v) == a.end())
                only_b.push_back(v);
            bool meet = false;
            if (shared.empty())
              meet = vtkTriangle::TrianglesIntersect(at(a[0]), at(a[1]), at(a[2]), at(b[0]), at(b[1]), at(b[2])) == 1;
            else if (shared.size() == 1)
              // the planes meet in a line through the shared vertex; the triangles overlap along
              // it beyond the vertex exactly when the edge opposite it in one passes through
              // the other
              meet = segment_meets_triangle(at(only_a[0]), at(only_a[1]), at(b[0]), at(b[1]), at(b[2])) ||
                     segment_meets_triangle(at(only_b[0]), at(only_b[1]), at(a[0]), at(a[1]), at(a[2]));
            else if (shared.size() == 2)
              {
                // an edge's two triangles fold onto each other when their normals are opposite
                const Vec na = cross(sub(at(a[1]), at(a[0])), sub(at(a[2]), at(a[0])));
                const Vec nb = cross(sub(at(b[1]), at(b[0])), sub(at(b[2]), at(b[0])));
                const double n = norm(na) * norm(nb);
                meet = n > 0 && dot(na, nb) < -0.9999 * n;
              }
            else
              meet = true; // the same triangle twice
            if (meet)
              {
                out.push_back({i, j});
                if (out.size() >= at_most)
                  return out;
              }
          }
      }
    return out;
  }
} // namespace abrade::fem
