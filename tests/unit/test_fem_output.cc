// The FEM side's output: a deal.II mesh with cell fields as .vtu in a .pvd series, and mesh
// volumes by quadrature (correct for tetrahedra, where GridTools::volume is not in 9.4).
#include <abrade/fem/solid_output.h>

#include <deal.II/grid/grid_generator.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

using namespace abrade;

TEST(SolidOutput, VolumesOfHexAndTetMeshes)
{
  dealii::Triangulation<3> hex;
  dealii::GridGenerator::hyper_rectangle(hex, dealii::Point<3>(0, 0, 0), dealii::Point<3>(0.4, 0.03, 0.5));
  hex.refine_global(1);
  EXPECT_NEAR(fem::mesh_volume(hex), 0.4 * 0.03 * 0.5, 1e-15);

  dealii::Triangulation<3> tet;
  dealii::GridGenerator::subdivided_hyper_rectangle_with_simplices(tet, {2, 1, 2}, dealii::Point<3>(0, 0, 0),
                                                                   dealii::Point<3>(0.4, 0.03, 0.5));
  EXPECT_NEAR(fem::mesh_volume(tet), 0.4 * 0.03 * 0.5, 1e-15);
}

TEST(SolidOutput, WritesVtuSeries)
{
  const std::string dir = (std::filesystem::temp_directory_path() / "abrade_fem_out").string();
  std::filesystem::remove_all(dir);
  dealii::Triangulation<3> tria;
  dealii::GridGenerator::hyper_cube(tria);
  tria.refine_global(1);
  fem::SolidOutput out(dir, "knife");
  std::vector<double> depth(tria.n_active_cells());
  for (std::size_t c = 0; c < depth.size(); ++c)
    depth[c] = 0.001 * c;
  out.write(tria, {{"wear_depth", depth}}, 0.0);
  std::vector<double> d(3 * tria.n_vertices()), z(tria.n_vertices());
  for (unsigned v = 0; v < tria.n_vertices(); ++v)
    z[v] = tria.get_vertices()[v][2], d[3 * v + 2] = -0.001 * tria.get_vertices()[v][0];
  const std::string second =
    out.write(tria, {{"wear_depth", depth}}, 1.0, {{"depth", 1, z}, {"displacement", 3, d}});
  EXPECT_TRUE(std::filesystem::exists(second));
  std::ifstream      pvd(dir + "/knife.pvd");
  std::ostringstream s;
  s << pvd.rdbuf();
  EXPECT_NE(s.str().find("knife_00001.vtu"), std::string::npos);
  std::ifstream      vtu(second);
  std::ostringstream v;
  v << vtu.rdbuf();
  EXPECT_NE(v.str().find("wear_depth"), std::string::npos);
  EXPECT_NE(v.str().find("Name=\"displacement\" NumberOfComponents=\"3\""), std::string::npos);
  EXPECT_NE(v.str().find("Name=\"depth\""), std::string::npos);
  EXPECT_THROW(out.write(tria, {{"bad", {1.0}}}, 2.0), std::logic_error);
  std::filesystem::remove_all(dir);
}
