#include <abrade/common/error.h>
#include <abrade/fem/solid_output.h>

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_nothing.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_simplex_p.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_fe.h>
#include <deal.II/fe/mapping_q.h>
#include <deal.II/lac/vector.h>
#include <deal.II/numerics/data_out.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace abrade::fem
{
  SolidOutput::SolidOutput(std::string dir, std::string b) : directory(std::move(dir)), base(std::move(b))
  {
    std::filesystem::create_directories(directory);
  }

  std::string SolidOutput::write(const dealii::Triangulation<3> &tria, const std::vector<CellField> &fields,
                                 double time)
  {
    dealii::DataOut<3> data_out;
    data_out.attach_triangulation(tria);
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
    char tag[16];
    std::snprintf(tag, sizeof tag, "%05zu", records.size());
    const std::string file = base + "_" + tag + ".vtu";
    std::ofstream     out(directory + "/" + file);
    if (!out)
      throw RunError("cannot write " + directory + "/" + file);
    data_out.write_vtu(out);
    records.emplace_back(time, file);
    std::ofstream pvd(directory + "/" + base + ".pvd");
    dealii::DataOutBase::write_pvd_record(pvd, records);
    return directory + "/" + file;
  }

  double mesh_volume(const dealii::Triangulation<3> &tria)
  {
    double volume = 0;
    for (const auto &cell : tria.active_cell_iterators())
      {
        if (cell->reference_cell().is_hyper_cube())
          {
            static const dealii::MappingQ<3> mapping(1);
            static const dealii::FE_Q<3>     fe(1);
            dealii::FEValues<3> fv(mapping, fe, dealii::QGauss<3>(2), dealii::update_JxW_values);
            fv.reinit(cell);
            for (unsigned q = 0; q < fv.n_quadrature_points; ++q)
              volume += fv.JxW(q);
          }
        else
          {
            static const dealii::FE_SimplexP<3> fe(1);
            static const dealii::MappingFE<3>   mapping(fe);
            dealii::FEValues<3> fv(mapping, fe, dealii::QGaussSimplex<3>(2), dealii::update_JxW_values);
            fv.reinit(cell);
            for (unsigned q = 0; q < fv.n_quadrature_points; ++q)
              volume += fv.JxW(q);
          }
      }
    return volume;
  }
} // namespace abrade::fem
