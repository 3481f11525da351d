#pragma once
// Quality of the part's volume mesh while it moves with its wear: the scaled Jacobian at every
// corner of every cell (1 for a cube or a regular tetrahedron, <= 0 for an inverted cell), the
// aspect ratio (longest over shortest edge), and the number of inverted cells. The lifetime loop
// remeshes when the minimum scaled Jacobian falls below a threshold, and reports an inverted
// cell (never carries it on).
#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <vector>

namespace abrade::fem
{
  struct MeshQuality
  {
    double   min_scaled_jacobian = 1;
    double   max_aspect_ratio    = 1;
    unsigned n_inverted          = 0;
    unsigned worst_cell          = 0; ///< active cell index of the smallest scaled Jacobian
  };

  MeshQuality mesh_quality(const dealii::Triangulation<3> &tria);

  /// The smallest scaled Jacobian of each active cell (for output).
  std::vector<double> cell_scaled_jacobians(const dealii::Triangulation<3> &tria);

  /// Moves every vertex by @p displacement (indexed like tria.get_vertices()).
  void move_vertices(dealii::Triangulation<3> &tria, const std::vector<dealii::Tensor<1, 3>> &displacement);
} // namespace abrade::fem
