// Triangle meshes: the reference knife's volume, conforming refinement, welding, closedness,
// the closest-point features, and mesh files through VTK (STL written and read back).
#include <abrade/common/error.h>
#include <abrade/common/closest_point.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/dem/triangle_mesh.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace abrade;
using namespace abrade::dem;

TEST(Geometry, ChiselKnifeVolumeAndClosedness)
{
  // 0.4 x (0.46 x 0.03 + 0.04 x 0.03 / 2) = 0.00576 m^3 (toolchain-notes.md)
  const TriangleMesh k = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  EXPECT_NEAR(k.volume(), 0.00576, 1e-15);
  EXPECT_TRUE(k.is_closed());
  EXPECT_EQ(k.n_triangles(), 16u);
  for (std::size_t t = 0; t < k.n_triangles(); ++t) // outward
    EXPECT_GT(k.normal(t).dot(k.vertices[k.triangles[t][0]] - Vec3(0, 0, 0.27)), 0);
}

TEST(Geometry, RefinementIsConformingAndKeepsShape)
{
  TriangleMesh k = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  const double area = k.total_area();
  k.refine(0.02);
  EXPECT_NEAR(k.total_area(), area, 1e-12);
  EXPECT_NEAR(k.volume(), 0.00576, 1e-14);
  EXPECT_TRUE(k.is_closed()); // conforming: every edge still has exactly two triangles
  for (const auto &t : k.triangles)
    for (int e = 0; e < 3; ++e)
      EXPECT_LE((k.vertices[t[e]] - k.vertices[t[(e + 1) % 3]]).norm(), 0.02 + 1e-12);
}

TEST(Geometry, BoxContainerNormalsPointInward)
{
  const TriangleMesh box = primitives::box_container(Vec3(-1, -1, 0), Vec3(1, 1, 1));
  EXPECT_EQ(box.n_triangles(), 10u);
  EXPECT_FALSE(box.is_closed());
  for (std::size_t t = 0; t < box.n_triangles(); ++t)
    {
      const auto &tri = box.triangles[t];
      const Vec3  c   = (box.vertices[tri[0]] + box.vertices[tri[1]] + box.vertices[tri[2]]) / 3;
      EXPECT_GT(box.normal(t).dot(Vec3(0, 0, 0.5) - c), 0);
    }
  EXPECT_TRUE(primitives::box_container(Vec3::Zero(), Vec3::Ones(), true).is_closed());
  EXPECT_NEAR(primitives::box_container(Vec3::Zero(), Vec3(1, 2, 3), true).volume(), -6, 1e-12);
}

TEST(Geometry, ClosestPointFeatures)
{
  const double a[3] = {0, 0, 0}, b[3] = {1, 0, 0}, c[3] = {0, 1, 0};
  auto at = [&](double x, double y, double z) {
    const double q[3] = {x, y, z};
    return closest_point_on_triangle(q, a, b, c);
  };
  EXPECT_EQ(at(0.2, 0.2, 1).feature, face);
  EXPECT_EQ(at(0.5, -1, 1).feature, edge01);
  EXPECT_EQ(at(1, 1, 0).feature, edge12);
  EXPECT_EQ(at(-1, 0.5, 0).feature, edge20);
  EXPECT_EQ(at(-1, -1, 0).feature, vertex0);
  EXPECT_EQ(at(2, -0.1, 0).feature, vertex1);
  EXPECT_EQ(at(-0.1, 2, 0).feature, vertex2);
  const auto p = at(0.5, -1, 1);
  EXPECT_DOUBLE_EQ(p.p[0], 0.5);
  EXPECT_DOUBLE_EQ(p.p[1], 0);
}

TEST(Geometry, InsideClosedMesh)
{
  const TriangleMesh k = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  EXPECT_TRUE(inside_mesh(k, Vec3(0, 0, 0.25)));
  EXPECT_FALSE(inside_mesh(k, Vec3(0, 0.02, 0.25)));
  EXPECT_FALSE(inside_mesh(k, Vec3(0, 0.01, 0.005))); // beside the chisel edge
}

TEST(MeshFiles, StlRoundTripAndWelding)
{
  const auto   dir  = std::filesystem::temp_directory_path();
  const auto   path = (dir / "abrade_knife.stl").string();
  TriangleMesh k    = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  k.refine(0.1);
  write_stl(path, k);
  const TriangleMesh r = read_surface_mesh(path);
  EXPECT_EQ(r.n_triangles(), k.n_triangles());
  EXPECT_EQ(r.vertices.size(), k.vertices.size()); // welded back to shared vertices
  EXPECT_NEAR(r.volume(), 0.00576, 1e-9);
  EXPECT_TRUE(r.is_closed());
  // millimetres
  const TriangleMesh mm = read_surface_mesh(path, 1000);
  EXPECT_NEAR(mm.volume(), 0.00576e9, 1e3);
  std::filesystem::remove(path);
}

TEST(MeshFiles, BadFilesAreClearErrors)
{
  const auto dir = std::filesystem::temp_directory_path();
  EXPECT_THROW(read_surface_mesh((dir / "does_not_exist.stl").string()), InputError);
  const auto empty = (dir / "abrade_empty.stl").string();
  std::ofstream(empty) << "solid empty\nendsolid empty\n";
  try
    {
      read_surface_mesh(empty);
      FAIL();
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("abrade_empty.stl"), std::string::npos);
    }
  EXPECT_THROW(read_surface_mesh((dir / "mesh.xyz").string()), InputError);
  std::filesystem::remove(empty);
}

TEST(MeshFiles, ObjQuadsAreTriangulated)
{
  const auto path = (std::filesystem::temp_directory_path() / "abrade_quad.obj").string();
  std::ofstream(path) << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
  const TriangleMesh m = read_surface_mesh(path);
  EXPECT_EQ(m.n_triangles(), 2u);
  EXPECT_NEAR(m.total_area(), 1, 1e-12);
  std::filesystem::remove(path);
}
