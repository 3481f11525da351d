// The part's VTU/PVD output with cell and vertex fields, and its volume (solid_output.h).
#include <abrade/common/error.h>
#include <abrade/common/atomic_file.h>
#include <abrade/fem/solid_output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/numerics/data_component_interpretation.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace abrade::fem
{
  SolidOutput::SolidOutput(std::string dir, std::string b) : directory(std::move(dir)), base(std::move(b))
  {
    std::filesystem::create_directories(directory);
  }

  std::string SolidOutput::write(const dealii::Triangulation<3> &tria, const std::vector<CellField> &fields,
                                 double time, const std::vector<VertexField> &vertex_fields)
  {
    dealii::DataOut<3> data_out;
    data_out.attach_triangulation(tria);
    // vertex fields live on linear elements: one degree of freedom per vertex and component
    std::unique_ptr<dealii::FiniteElement<3>> p1;
    if (tria.all_reference_cells_are_hyper_cube())
      p1 = std::make_unique<dealii::FE_Q<3>>(1);
    else
      p1 = std::make_unique<dealii::FE_SimplexP<3>>(1);
    const dealii::FESystem<3> p1_vector(*p1, 3);
    dealii::DoFHandler<3>     scalar_dofs(tria), vector_dofs(tria);
    scalar_dofs.distribute_dofs(*p1);
    vector_dofs.distribute_dofs(p1_vector);
    std::vector<dealii::Vector<double>> vertex_vectors;
    vertex_vectors.reserve(vertex_fields.size());
    for (const auto &f : vertex_fields)
      {
        if (f.values.size() != f.n_components * tria.n_vertices() || (f.n_components != 1 && f.n_components != 3))
          throw std::logic_error("vertex field " + f.name + " has the wrong size");
        const auto &dofs = f.n_components == 1 ? scalar_dofs : vector_dofs;
        vertex_vectors.emplace_back(dofs.n_dofs());
        for (const auto &cell : dofs.active_cell_iterators())
          for (const unsigned v : cell->vertex_indices())
            for (unsigned c = 0; c < f.n_components; ++c)
              vertex_vectors.back()[cell->vertex_dof_index(v, c)] = f.values[f.n_components * cell->vertex_index(v) + c];
        if (f.n_components == 1)
          data_out.add_data_vector(scalar_dofs, vertex_vectors.back(), f.name);
        else
          data_out.add_data_vector(vector_dofs, vertex_vectors.back(), std::vector<std::string>(3, f.name),
                                   std::vector<dealii::DataComponentInterpretation::DataComponentInterpretation>(
                                     3, dealii::DataComponentInterpretation::component_is_part_of_vector));
      }
    std::vector<dealii::Vector<double>> vectors;
    vectors.reserve(fields.size());
    for (const auto &f : fields)
      {
        if (f.values.size() != tria.n_active_cells())
          throw std::logic_error("cell field " + f.name + " has the wrong size");
        vectors.emplace_back(f.values.begin(), f.values.end());
        data_out.add_data_vector(vectors.back(), f.name, dealii::DataOut<3>::type_cell_data);
      }
    data_out.build_patches();
    // zlib's fastest level: its best (deal.II's default) took 5 % of a 60k-cell part's
    // lifetime run for files 5 % smaller
    dealii::DataOutBase::VtkFlags flags;
    flags.compression_level = dealii::DataOutBase::VtkFlags::best_speed;
    data_out.set_flags(flags);
    char tag[32];
    std::snprintf(tag, sizeof tag, "%05zu", records.size());
    const std::string file = base + "_" + tag + ".vtu";
    std::ostringstream vtu, pvd; // each file replaced at once, its write checked
    data_out.write_vtu(vtu);
    io::write_file_atomically(directory + "/" + file, vtu.str());
    records.emplace_back(time, file);
    dealii::DataOutBase::write_pvd_record(pvd, records);
    io::write_file_atomically(directory + "/" + base + ".pvd", pvd.str());
    return directory + "/" + file;
  }

  void SolidOutput::adopt(const std::vector<double> &times)
  {
    records.clear();
    for (std::size_t k = 0; k < times.size(); ++k)
      {
        char tag[32];
        std::snprintf(tag, sizeof tag, "%05zu", k);
        records.emplace_back(times[k], base + "_" + tag + ".vtu");
      }
  }

  double mesh_volume(const dealii::Triangulation<3> &tria)
  {
    // one FEValues per kind of cell, built once (one built per cell cost more than the mesh
    // motion's solve on a 60k-cell part); each quadrature is exact for the volume of a cell
    // of its linear (tetrahedron) or trilinear (hexahedron) mapping
    static const dealii::MappingQ<3>    hex_mapping(1);
    static const dealii::FE_Q<3>        hex_fe(1);
    static const dealii::FE_SimplexP<3> tet_fe(1);
    static const dealii::MappingFE<3>   tet_mapping(tet_fe);
    dealii::FEValues<3> hex(hex_mapping, hex_fe, dealii::QGauss<3>(2), dealii::update_JxW_values);
    dealii::FEValues<3> tet(tet_mapping, tet_fe, dealii::QGaussSimplex<3>(2), dealii::update_JxW_values);
    double              volume = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (!cell->reference_cell().is_hyper_cube() && !cell->reference_cell().is_simplex())
          throw std::logic_error("mesh_volume: hexahedra and tetrahedra only (cell " +
                                 std::to_string(cell->active_cell_index()) + " is a wedge or a pyramid)");
        dealii::FEValues<3> &fv = cell->reference_cell().is_hyper_cube() ? hex : tet;
        fv.reinit(cell);
        for (unsigned q = 0; q < fv.n_quadrature_points; ++q)
          volume += fv.JxW(q);
      }
    return volume;
  }
} // namespace abrade::fem
