#pragma once
// Helpers shared by the FEM tests.
#include <deal.II/grid/tria.h>

#include <filesystem>
#include <string>

namespace abrade::fem::testing
{
  inline std::string tmp(const std::string &name)
  {
    return (std::filesystem::temp_directory_path() / name).string();
  }

  /// Area of the boundary faces with id @p id.
  inline double boundary_area(const dealii::Triangulation<3> &tria, dealii::types::boundary_id id)
  {
    double a = 0;
    for (const auto &cell : tria.active_cell_iterators())
      for (const auto &f : cell->face_iterators())
        if (f->at_boundary() && f->boundary_id() == id)
          a += f->measure();
    return a;
  }
} // namespace abrade::fem::testing
