#pragma once
// Writing a solid (the part's volume mesh) for ParaView with deal.II's DataOut: one .vtu per
// update with named per-cell fields, strung into a .pvd series. Works for hexahedral and
// tetrahedral meshes.
#include <deal.II/grid/tria.h>

#include <string>
#include <utility>
#include <vector>

namespace abrade::fem
{
  struct CellField
  {
    std::string         name;
    std::vector<double> values; ///< one per active cell
  };

  /// A field at the vertices of the triangulation (indexed like tria.get_vertices()): scalar
  /// (n_components = 1) or a vector (3, interleaved), e.g. wear depth and displacement.
  struct VertexField
  {
    std::string         name;
    unsigned            n_components = 1;
    std::vector<double> values;
  };

  class SolidOutput
  {
  public:
    /// Files go to @p directory as BASE_NNNNN.vtu with BASE.pvd.
    SolidOutput(std::string directory, std::string base);
    /// Writes one update; returns the .vtu path.
    std::string write(const dealii::Triangulation<3> &tria, const std::vector<CellField> &fields, double time,
                      const std::vector<VertexField> &vertex_fields = {});
    /// A resumed run: files 0..n-1 already written, at these times.
    void adopt(const std::vector<double> &times);

  private:
    std::string                                 directory, base;
    std::vector<std::pair<double, std::string>> records;
  };

  /// Volume of a mesh (hex or tet) by quadrature; GridTools::volume is wrong for simplices in
  /// deal.II 9.4 (shared/reference/toolchain-notes.md).
  double mesh_volume(const dealii::Triangulation<3> &tria);
} // namespace abrade::fem
