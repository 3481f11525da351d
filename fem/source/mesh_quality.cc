// The volume mesh's quality while it moves: scaled Jacobians, inverted cells (mesh_quality.h).
#include <abrade/fem/mesh_quality.h>

#include <algorithm>
#include <cmath>

namespace abrade::fem
{
  using namespace dealii;

  namespace
  {
    double scaled(const Tensor<1, 3> &a, const Tensor<1, 3> &b, const Tensor<1, 3> &c)
    {
      const double n = a.norm() * b.norm() * c.norm();
      return n > 0 ? determinant(Tensor<2, 3>({{a[0], b[0], c[0]}, {a[1], b[1], c[1]}, {a[2], b[2], c[2]}})) / n : -1.0;
    }
  } // namespace

  namespace
  {
    double worst_scaled_jacobian(const Triangulation<3>::active_cell_iterator &cell)
    {
        double worst = std::numeric_limits<double>::infinity();
        if (cell->reference_cell().is_simplex())
          {
            // even permutations (k, a, b, c) of (0, 1, 2, 3) give +6 V; sqrt(2) makes a regular
            // tetrahedron 1
            static const unsigned perm[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}};
            for (const auto &p : perm)
              {
                const Point<3> &k = cell->vertex(p[0]);
                worst = std::min(worst, std::sqrt(2.0) * scaled(cell->vertex(p[1]) - k, cell->vertex(p[2]) - k,
                                                                cell->vertex(p[3]) - k));
              }
          }
        else
          {
            // hexahedron, deal.II vertex v has reference coordinates (v & 1, v >> 1 & 1, v >> 2 & 1)
            for (unsigned v = 0; v < 8; ++v)
              {
                Tensor<1, 3> e[3];
                for (unsigned d = 0; d < 3; ++d)
                  {
                    const unsigned w = v ^ (1u << d);
                    e[d]             = (v >> d & 1) ? cell->vertex(v) - cell->vertex(w) : cell->vertex(w) - cell->vertex(v);
                  }
                worst = std::min(worst, scaled(e[0], e[1], e[2]));
              }
          }
        return worst;
    }
  } // namespace

  std::vector<double> cell_scaled_jacobians(const Triangulation<3> &tria)
  {
    std::vector<double> out(tria.n_active_cells());
    for (const auto &cell : tria.active_cell_iterators())
      out[cell->active_cell_index()] = worst_scaled_jacobian(cell);
    return out;
  }

  MeshQuality mesh_quality(const Triangulation<3> &tria)
  {
    MeshQuality q;
    q.min_scaled_jacobian = std::numeric_limits<double>::infinity();
    for (const auto &cell : tria.active_cell_iterators())
      {
        const double worst = worst_scaled_jacobian(cell);
        if (worst <= 0)
          ++q.n_inverted;
        if (worst < q.min_scaled_jacobian)
          q.min_scaled_jacobian = worst, q.worst_cell = cell->active_cell_index();
        double lo = std::numeric_limits<double>::infinity(), hi = 0;
        for (const unsigned l : cell->line_indices())
          {
            const double len = cell->line(l)->diameter();
            lo = std::min(lo, len), hi = std::max(hi, len);
          }
        q.max_aspect_ratio = std::max(q.max_aspect_ratio, lo > 0 ? hi / lo : std::numeric_limits<double>::infinity());
      }
    return q;
  }

  void move_vertices(Triangulation<3> &tria, const std::vector<Tensor<1, 3>> &displacement)
  {
    std::vector<bool> moved(tria.n_vertices(), false);
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned v : cell->vertex_indices())
        if (!moved[cell->vertex_index(v)])
          {
            cell->vertex(v) += displacement[cell->vertex_index(v)];
            moved[cell->vertex_index(v)] = true;
          }
  }
} // namespace abrade::fem
