#pragma once
// Mesh motion: the displacement that a worn boundary prescribes is carried into the part's
// interior by solving, for each displacement component u_c,
//
//     -div( k grad u_c ) = f_c   in the part,   u_c = g_c on the moved / clamped boundaries,
//
// with natural (zero-flux) conditions elsewhere. k = (V_ref / V_cell)^s stiffens small cells
// (s = 0: plain Laplacian smoothing; s = 1 is the usual choice), so that small, distorted cells
// near the worn edge move nearly rigidly and keep their shape. f is zero in use; it is there for
// verification by manufactured solutions. Q1/Q2 on hexahedra or P1/P2 on tetrahedra (deal.II
// 9.4 simplex support); PETSc CG with hypre BoomerAMG.
#include <deal.II/base/function.h>
#include <deal.II/base/point.h>
#include <deal.II/grid/tria.h>
#include <deal.II/lac/vector.h>

#include <map>
#include <memory>
#include <vector>

namespace abrade::fem
{
  class MeshMotion
  {
  public:
    struct Settings
    {
      unsigned degree     = 1;     ///< polynomial degree
      double   stiffening = 0;     ///< exponent s of the cell-size stiffening
      double   tolerance  = 1e-12; ///< relative residual of the CG solve
    };

    MeshMotion(const dealii::Triangulation<3> &tria, const Settings &settings);
    ~MeshMotion();

    /// Solves for the displacement: @p boundary maps boundary ids to a 3-component function of
    /// the prescribed displacement; @p rhs (optional, 3 components) is a body source.
    void solve(const std::map<dealii::types::boundary_id, const dealii::Function<3> *> &boundary,
               const dealii::Function<3> *rhs = nullptr);

    /// Solves with the displacement prescribed at individual vertices (triangulation vertex
    /// index -> displacement; degree 1 only) and by functions on whole boundaries.
    void solve(const std::map<unsigned, dealii::Tensor<1, 3>>                        &vertices,
               const std::map<dealii::types::boundary_id, const dealii::Function<3> *> &boundary);

    /// L2 norm and H1 seminorm of (u_c - exact_c), summed over the three components.
    std::pair<double, double> errors(const dealii::Function<3> &exact) const;

    /// The displacement at every vertex of the triangulation (indexed like tria.get_vertices()).
    std::vector<dealii::Tensor<1, 3>> vertex_displacements() const;

    unsigned n_dofs() const;              ///< per component
    unsigned last_iterations() const { return iterations; }
    const dealii::Vector<double> &component(unsigned c) const { return solution[c]; }

  private:
    void solve_with(const std::map<unsigned, dealii::Tensor<1, 3>>                        *vertices,
                    const std::map<dealii::types::boundary_id, const dealii::Function<3> *> &boundary,
                    const dealii::Function<3>                                               *rhs);
    struct Impl;
    std::unique_ptr<Impl>                 impl;
    Settings                              settings;
    std::array<dealii::Vector<double>, 3> solution;
    unsigned                              iterations = 0;
  };
} // namespace abrade::fem
