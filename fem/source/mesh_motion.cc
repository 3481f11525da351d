// The worn boundary's displacement carried into the part's interior: -div(k grad u_c) = f_c
// per component, solved with deal.II and PETSc (mesh_motion.h).
#include <abrade/common/error.h>
#include <abrade/fem/mesh_motion.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/petsc_precondition.h>
#include <deal.II/lac/petsc_solver.h>
#include <deal.II/lac/petsc_sparse_matrix.h>
#include <deal.II/lac/petsc_vector.h>
#include <deal.II/numerics/vector_tools.h>

namespace abrade::fem
{
  using namespace dealii;

  namespace
  {
    /// Component c of a vector-valued function, as a scalar function.
    class ComponentOf : public Function<3>
    {
    public:
      ComponentOf(const Function<3> &f, unsigned c) : f(f), c(c) {}
      double value(const Point<3> &p, unsigned = 0) const override { return f.value(p, c); }
      Tensor<1, 3> gradient(const Point<3> &p, unsigned = 0) const override { return f.gradient(p, c); }

    private:
      const Function<3> &f;
      unsigned           c;
    };
  } // namespace

  struct MeshMotion::Impl
  {
    const Triangulation<3>          &tria;
    std::unique_ptr<FiniteElement<3>> fe;
    std::unique_ptr<Mapping<3>>       mapping;
    std::unique_ptr<Quadrature<3>>    quadrature;
    DoFHandler<3>                     dofs;
    explicit Impl(const Triangulation<3> &t) : tria(t), dofs(t) {}

    // the steps of solve_with()
    /// The cells' volumes (by active cell index) and their mean: the reference of the cell-size
    /// stiffening.
    std::pair<std::vector<double>, double> cell_volumes() const;
    /// The constraints of displacement component @p c: hanging nodes, the @p boundary
    /// functions' component, the listed @p vertices' (if any; not where already constrained).
    AffineConstraints<double> constraints_of(unsigned c, const IndexSet &relevant,
                                             const std::map<unsigned, Tensor<1, 3>>                  *vertices,
                                             const std::map<types::boundary_id, const Function<3> *> &boundary) const;
    /// -div(k grad u_c) = f_c (@p rhs's component @p c, none: 0) on this process's cells, into
    /// @p matrix and @p rhs_vector; k = (mean volume / cell volume)^@p stiffening.
    void assemble(unsigned c, const AffineConstraints<double> &constraints, double stiffening,
                  const std::vector<double> &volume, double mean_volume, const Function<3> *rhs,
                  PETScWrappers::MPI::SparseMatrix &matrix, PETScWrappers::MPI::Vector &rhs_vector) const;
  };

  std::pair<std::vector<double>, double> MeshMotion::Impl::cell_volumes() const
  {
    std::vector<double> volume(tria.n_active_cells());
    double              mean = 0;
    FEValues<3>         fv(*mapping, *fe, *quadrature, update_JxW_values);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        fv.reinit(cell);
        double v = 0;
        for (unsigned q = 0; q < fv.n_quadrature_points; ++q)
          v += fv.JxW(q);
        volume[cell->active_cell_index()] = v;
        mean += v / volume.size();
      }
    return {volume, mean};
  }

  AffineConstraints<double>
  MeshMotion::Impl::constraints_of(unsigned c, const IndexSet &relevant, const std::map<unsigned, Tensor<1, 3>> *vertices,
                                   const std::map<types::boundary_id, const Function<3> *> &boundary) const
  {
    AffineConstraints<double> constraints(relevant);
    DoFTools::make_hanging_node_constraints(dofs, constraints);
    std::vector<std::unique_ptr<ComponentOf>>         parts;
    std::map<types::boundary_id, const Function<3> *> scalar;
    for (const auto &[id, f] : boundary)
      {
        parts.push_back(std::make_unique<ComponentOf>(*f, c));
        scalar[id] = parts.back().get();
      }
    VectorTools::interpolate_boundary_values(*mapping, dofs, scalar, constraints);
    if (vertices)
      for (const auto &cell : dofs.active_cell_iterators())
        for (const unsigned v : cell->vertex_indices())
          if (auto it = vertices->find(cell->vertex_index(v)); it != vertices->end())
            {
              const auto dof = cell->vertex_dof_index(v, 0);
              if (relevant.is_element(dof) && !constraints.is_constrained(dof))
                {
                  constraints.add_line(dof);
                  constraints.set_inhomogeneity(dof, it->second[c]);
                }
            }
    constraints.close();
    return constraints;
  }

  void MeshMotion::Impl::assemble(unsigned c, const AffineConstraints<double> &constraints, double stiffening,
                                  const std::vector<double> &volume, double mean_volume, const Function<3> *rhs,
                                  PETScWrappers::MPI::SparseMatrix &matrix, PETScWrappers::MPI::Vector &rhs_vector) const
  {
    FEValues<3> fv(*mapping, *fe, *quadrature,
                   update_values | update_gradients | update_JxW_values | update_quadrature_points);
    const unsigned                       n = fe->n_dofs_per_cell();
    FullMatrix<double>                   local_matrix(n, n);
    dealii::Vector<double>               local_rhs(n);
    std::vector<types::global_dof_index> indices(n);
    for (const auto &cell : dofs.active_cell_iterators())
      {
        if (!cell->is_locally_owned())
          continue;
        fv.reinit(cell);
        local_matrix = 0, local_rhs = 0;
        const double k = stiffening == 0 ? 1.0 : std::pow(mean_volume / volume[cell->active_cell_index()], stiffening);
        for (unsigned q = 0; q < fv.n_quadrature_points; ++q)
          {
            const double f = rhs ? rhs->value(fv.quadrature_point(q), c) : 0.0;
            for (unsigned i = 0; i < n; ++i)
              {
                for (unsigned j = 0; j < n; ++j)
                  local_matrix(i, j) += k * fv.shape_grad(i, q) * fv.shape_grad(j, q) * fv.JxW(q);
                local_rhs(i) += f * fv.shape_value(i, q) * fv.JxW(q);
              }
          }
        cell->get_dof_indices(indices);
        constraints.distribute_local_to_global(local_matrix, local_rhs, indices, matrix, rhs_vector);
      }
    matrix.compress(VectorOperation::add);
    rhs_vector.compress(VectorOperation::add);
  }

  MeshMotion::MeshMotion(const Triangulation<3> &tria, const Settings &s)
    : impl(std::make_unique<Impl>(tria)), settings(s)
  {
    if (tria.all_reference_cells_are_hyper_cube())
      {
        impl->fe         = std::make_unique<FE_Q<3>>(s.degree);
        impl->mapping    = std::make_unique<MappingQ<3>>(1);
        impl->quadrature = std::make_unique<QGauss<3>>(s.degree + 1);
      }
    else if (tria.all_reference_cells_are_simplex())
      {
        impl->fe         = std::make_unique<FE_SimplexP<3>>(s.degree);
        impl->mapping    = std::make_unique<MappingFE<3>>(FE_SimplexP<3>(1));
        impl->quadrature = std::make_unique<QGaussSimplex<3>>(s.degree + 1);
      }
    else
      throw InputError("part mesh", "mixed hexahedral/tetrahedral meshes are not supported");
    impl->dofs.distribute_dofs(*impl->fe);
  }

  MeshMotion::~MeshMotion() = default;

  unsigned MeshMotion::n_dofs() const { return impl->dofs.n_dofs(); }

  void MeshMotion::solve(const std::map<types::boundary_id, const Function<3> *> &boundary, const Function<3> *rhs)
  {
    solve_with(nullptr, boundary, rhs);
  }

  void MeshMotion::solve(const std::map<unsigned, Tensor<1, 3>>                  &vertices,
                         const std::map<types::boundary_id, const Function<3> *> &boundary)
  {
    if (settings.degree != 1)
      throw std::logic_error("vertex displacements need degree 1");
    solve_with(&vertices, boundary, nullptr);
  }

  void MeshMotion::solve_with(const std::map<unsigned, Tensor<1, 3>>                  *vertices,
                              const std::map<types::boundary_id, const Function<3> *> &boundary,
                              const Function<3>                                       *rhs)
  {
    const auto &dofs = impl->dofs;
    // a parallel::shared triangulation (METIS partitions) is solved by all its processes, each
    // assembling its own cells; a plain one alone
    const auto *parallel = dynamic_cast<const parallel::TriangulationBase<3> *>(&impl->tria);
    const MPI_Comm comm  = parallel ? parallel->get_communicator() : MPI_COMM_SELF;
    const IndexSet owned = dofs.locally_owned_dofs();
    IndexSet       relevant;
    DoFTools::extract_locally_relevant_dofs(dofs, relevant);
    const auto [cell_volume, mean_volume] = impl->cell_volumes();

    iterations = 0;
    for (unsigned c = 0; c < 3; ++c)
      {
        const AffineConstraints<double> constraints = impl->constraints_of(c, relevant, vertices, boundary);
        DynamicSparsityPattern          dsp(relevant);
        DoFTools::make_sparsity_pattern(dofs, dsp, constraints, false);
        SparsityTools::distribute_sparsity_pattern(dsp, owned, comm, relevant);
        PETScWrappers::MPI::SparseMatrix matrix;
        matrix.reinit(owned, owned, dsp, comm);
        PETScWrappers::MPI::Vector rhs_vector(owned, comm), x(owned, comm);
        impl->assemble(c, constraints, settings.stiffening, cell_volume, mean_volume, rhs, matrix, rhs_vector);

        // CG with an algebraic multigrid preconditioner (BoomerAMG), to a tolerance relative
        // to the right-hand side
        const double rhs_norm = rhs_vector.l2_norm();
        if (rhs_norm > 0)
          {
            SolverControl control(std::max<unsigned>(1000, dofs.n_dofs()), settings.tolerance * rhs_norm);
            PETScWrappers::SolverCG                 cg(control);
            PETScWrappers::PreconditionBoomerAMG::AdditionalData amg_data;
            amg_data.symmetric_operator = true;
            PETScWrappers::PreconditionBoomerAMG amg(matrix, amg_data);
            cg.solve(matrix, x, rhs_vector, amg);
            iterations = std::max(iterations, control.last_step());
          }
        constraints.distribute(x);
        // every process gets the whole field (the mesh is shared): a vector with every entry
        // as a ghost
        PETScWrappers::MPI::Vector all(owned, complete_index_set(dofs.n_dofs()), comm);
        all = x;
        solution[c].reinit(dofs.n_dofs());
        for (types::global_dof_index i = 0; i < dofs.n_dofs(); ++i)
          solution[c][i] = all[i];
      }
  }

  std::pair<double, double> MeshMotion::errors(const Function<3> &exact) const
  {
    double l2 = 0, h1 = 0;
    for (unsigned c = 0; c < 3; ++c)
      {
        ComponentOf            e(exact, c);
        dealii::Vector<float>  cellwise(impl->tria.n_active_cells());
        const auto             q = impl->tria.all_reference_cells_are_hyper_cube()
                                     ? std::unique_ptr<Quadrature<3>>(std::make_unique<QGauss<3>>(settings.degree + 3))
                                     : std::unique_ptr<Quadrature<3>>(std::make_unique<QGaussSimplex<3>>(settings.degree + 2));
        VectorTools::integrate_difference(*impl->mapping, impl->dofs, solution[c], e, cellwise, *q, VectorTools::L2_norm);
        l2 += std::pow(VectorTools::compute_global_error(impl->tria, cellwise, VectorTools::L2_norm), 2);
        VectorTools::integrate_difference(*impl->mapping, impl->dofs, solution[c], e, cellwise, *q,
                                          VectorTools::H1_seminorm);
        h1 += std::pow(VectorTools::compute_global_error(impl->tria, cellwise, VectorTools::H1_seminorm), 2);
      }
    return {std::sqrt(l2), std::sqrt(h1)};
  }

  std::vector<Tensor<1, 3>> MeshMotion::vertex_displacements() const
  {
    std::vector<Tensor<1, 3>> d(impl->tria.n_vertices());
    for (const auto &cell : impl->dofs.active_cell_iterators())
      for (const unsigned v : cell->vertex_indices())
        {
          const auto dof = cell->vertex_dof_index(v, 0);
          for (unsigned c = 0; c < 3; ++c)
            d[cell->vertex_index(v)][c] = solution[c][dof];
        }
    return d;
  }
} // namespace abrade::fem
