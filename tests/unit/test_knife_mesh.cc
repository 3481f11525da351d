// The parametric knife (Gmsh, tetrahedra) has its analytic volume, the clamped top face its
// area, and cells of good quality; the quality measure gives 1 for ideal cells and flags
// inverted ones; moving the knife with a mesh-motion solve keeps the mesh valid.
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/part_model.h>
#include <abrade/fem/mesh_motion.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include "fem_test_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace dealii;
using namespace abrade::fem;
using namespace abrade::fem::testing;


TEST(PartMesh, ReferenceKnifeVolumeAreaAndQuality)
{
  ParametricKnife    k; // the reference knife: 0.4 x 0.5 x 0.03, 40 mm chisel bevel
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_knife.msh"));
  EXPECT_NEAR(k.volume(), 0.00576, 1e-15);
  EXPECT_NEAR(mesh_volume(tria), 0.00576, 1e-12);

  EXPECT_NEAR(boundary_area(tria, clamped_boundary), 0.4 * 0.03, 1e-12);
  const MeshQuality q = mesh_quality(tria);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_scaled_jacobian, 0.1);
  std::printf("reference knife: %u tets, min scaled Jacobian %.3f, max aspect ratio %.2f\n", tria.n_active_cells(),
              q.min_scaled_jacobian, q.max_aspect_ratio);
}

TEST(PartMesh, ConceptShapes)
{
  // one-sided bevel with a lip: a polygon, so the mesh volume is exact
  ParametricKnife k;
  k.bevel_side = ParametricKnife::BevelSide::plus;
  k.lip_height = 0.02, k.lip_width = 0.01, k.lip_offset = 0.03;
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_knife_lip.msh"));
  EXPECT_NEAR(k.volume(), 0.4 * (0.03 * 0.46 + 0.03 * 0.04 / 2 + 0.02 * 0.01), 1e-15);
  EXPECT_NEAR(mesh_volume(tria), k.volume(), 1e-12);
  EXPECT_EQ(mesh_quality(tria).n_inverted, 0u);

  // a rounded edge removes a little material at the tip
  ParametricKnife r;
  r.tip_radius = 0.004;
  Triangulation<3> rounded;
  r.mesh(rounded, 0.03, tmp("abrade_knife_round.msh"));
  EXPECT_LT(mesh_volume(rounded), r.volume());
  EXPECT_GT(mesh_volume(rounded), r.volume() - 0.4 * 0.004 * 0.02);
}

TEST(PartMesh, BadParametersAreClearErrors)
{
  ParametricKnife k;
  k.bevel = 0.6;
  EXPECT_THROW(k.check(), std::exception);
  k       = ParametricKnife();
  k.tip_radius = 0.02;
  EXPECT_THROW(k.check(), std::exception);
}

TEST(MeshQualityMeasure, IdealAndInvertedCells)
{
  Triangulation<3> cube;
  GridGenerator::hyper_cube(cube);
  EXPECT_NEAR(mesh_quality(cube).min_scaled_jacobian, 1, 1e-14);
  EXPECT_NEAR(mesh_quality(cube).max_aspect_ratio, 1, 1e-14);

  Triangulation<3> tet;
  GridGenerator::reference_cell(tet, ReferenceCells::Tetrahedron);
  // move the reference tetrahedron to a regular one
  const double s = 1 / std::sqrt(2.0);
  std::vector<Tensor<1, 3>> d(4);
  const Point<3> regular[4] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const Point<3> ref[4]     = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  // pick an orientation-preserving assignment: det of the regular set in this order
  const Tensor<2, 3> J({{regular[1][0] - regular[0][0], regular[2][0] - regular[0][0], regular[3][0] - regular[0][0]},
                        {regular[1][1] - regular[0][1], regular[2][1] - regular[0][1], regular[3][1] - regular[0][1]},
                        {regular[1][2] - regular[0][2], regular[2][2] - regular[0][2], regular[3][2] - regular[0][2]}});
  const bool flip = determinant(J) < 0;
  for (unsigned v = 0; v < 4; ++v)
    {
      const unsigned w = flip && v >= 2 ? 5 - v : v; // swap vertices 2 and 3 to fix the orientation
      for (unsigned c = 0; c < 3; ++c)
        d[tet.begin_active()->vertex_index(v)][c] = s * regular[w][c] - ref[v][c];
    }
  move_vertices(tet, d);
  EXPECT_NEAR(mesh_quality(tet).min_scaled_jacobian, 1, 1e-12);

  // push a vertex through the opposite face: inverted
  std::vector<Tensor<1, 3>> push(tet.n_vertices());
  push[tet.begin_active()->vertex_index(0)] = 3 * (tet.begin_active()->center() - tet.begin_active()->vertex(0));
  move_vertices(tet, push);
  EXPECT_EQ(mesh_quality(tet).n_inverted, 1u);
  EXPECT_LT(mesh_quality(tet).min_scaled_jacobian, 0);
}

TEST(PartMesh, WornEdgeCarriedIntoTheInteriorKeepsTheMeshValid)
{
  // the edge recedes by 8 mm, fading linearly to nothing 0.1 m above it; the top is clamped
  ParametricKnife    k;
  Triangulation<3> tria;
  k.mesh(tria, 0.02, tmp("abrade_knife_worn.msh"));
  const double v0 = mesh_volume(tria);
  class Wear : public Function<3>
  {
  public:
    Wear() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override
    {
      return c == 2 ? 0.008 * std::max(0.0, 1 - p[2] / 0.1) : 0.0;
    }
  } wear;
  Functions::ZeroFunction<3> zero(3);
  MeshMotion motion(tria, {1, 1.0, 1e-10});
  motion.solve({{wearable_boundary, &wear}, {clamped_boundary, &zero}});
  move_vertices(tria, motion.vertex_displacements());
  const MeshQuality q = mesh_quality(tria);
  EXPECT_EQ(q.n_inverted, 0u);
  EXPECT_GT(q.min_scaled_jacobian, 0.02);
  // the displacement is linear in z: the lowest 0.1 m of the profile (area 0.03 x 0.06 +
  // 0.03 x 0.04 / 2 = 0.0024 m^2) is compressed by 8 % over the knife's 0.4 m, exactly
  EXPECT_NEAR(v0 - mesh_volume(tria), 0.08 * 0.0024 * 0.4, 1e-12);
  std::printf("worn knife: volume %.6g -> %.6g m^3, min scaled Jacobian %.3f, CG iterations %u\n", v0,
              mesh_volume(tria), q.min_scaled_jacobian, motion.last_iterations());
}

TEST(PartMesh, HundredWearUpdatesWithRemeshing)
{
  // 100 updates, each receding the knife's lowest 0.1 m by up to 0.8 mm (the edge most); the
  // mesh is moved every time and remeshed when its quality falls below 95 % of the fresh mesh's
  // (strict, to exercise remeshing: with stiffening the quality stays above half of it for all
  // 100 updates): it never inverts, and the knife keeps losing material
  ParametricKnife    k;
  auto             tria = std::make_unique<Triangulation<3>>();
  k.mesh(*tria, 0.02, tmp("abrade_knife_updates.msh"));
  class Wear : public Function<3>
  {
  public:
    double bottom = 0;
    Wear() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override
    {
      return c == 2 ? 0.0008 * std::max(0.0, 1 - (p[2] - bottom) / 0.1) : 0.0;
    }
  } wear;
  Functions::ZeroFunction<3> zero(3);
  double       volume    = mesh_volume(*tria);
  int          remeshes  = 0;
  const double threshold = 0.95 * mesh_quality(*tria).min_scaled_jacobian;
  for (int update = 0; update < 100; ++update)
    {
      MeshMotion motion(*tria, {1, 1.0, 1e-10});
      motion.solve({{wearable_boundary, &wear}, {clamped_boundary, &zero}});
      move_vertices(*tria, motion.vertex_displacements());
      wear.bottom += 0.0008;
      MeshQuality q = mesh_quality(*tria);
      ASSERT_EQ(q.n_inverted, 0u) << "update " << update;
      if (q.min_scaled_jacobian < threshold)
        {
          auto fresh = std::make_unique<Triangulation<3>>();
          remesh(*tria, 0.02, *fresh, tmp("abrade_updates_remesh"));
          tria = std::move(fresh);
          ++remeshes;
          ASSERT_EQ(mesh_quality(*tria).n_inverted, 0u);
        }
      const double v = mesh_volume(*tria);
      ASSERT_LT(v, volume);
      volume = v;
    }
  // the bottom 0.1 m shrank by 8 % a hundred times (a linear squeeze each time)
  std::printf("100 updates: %d remeshes, volume 0.00576 -> %.6g m^3\n", remeshes, volume);
  EXPECT_GT(remeshes, 0);
  EXPECT_LT(remeshes, 100);
  EXPECT_LT(volume, 0.00576 - 0.0003);
}

TEST(PartModel, ApplyWearMovesAccumulatesReportsAndRemeshes)
{
  PartModel::Settings settings;
  settings.mesh_size      = 0.03;
  settings.work_directory = tmp("abrade_knife_model");
  PartModel knife(ParametricKnife(), settings);
  const double v0 = knife.volume();

  // 1 mm off the flat -y face (away from its edges)
  auto side_depth = [](const SolidSurface &s, double d) {
    std::vector<double> depth(s.vertices.size(), 0.0);
    for (std::size_t v = 0; v < depth.size(); ++v)
      {
        const auto &p = s.vertices[v];
        if (std::abs(p[1] + 0.015) < 0.0015 && p[2] > 0.06 && p[2] < 0.48 && p[0] > 0.02 && p[0] < 0.38)
          depth[v] = d;
      }
    return depth;
  };
  const SolidSurface before = knife.surface();
  const auto         depth  = side_depth(before, 0.001);
  const auto         r      = knife.apply_wear(depth);
  EXPECT_TRUE(r.worn_through.empty());
  EXPECT_EQ(r.quality.n_inverted, 0u);
  EXPECT_LT(r.volume, v0);
  int moved = 0;
  for (std::size_t v = 0; v < depth.size(); ++v)
    if (depth[v] > 0)
      {
        EXPECT_NEAR(knife.surface().vertices[v][1] - before.vertices[v][1], 0.001, 1e-12); // inward = +y
        EXPECT_NEAR(knife.vertex_displacement()[v], 0.001, 1e-15);
        EXPECT_NEAR(knife.wear_depth()[v], 0.001, 1e-12);
        ++moved;
      }
  EXPECT_GT(moved, 3);

  // deeper than the 30 mm plate: worn through, reported, the mesh untouched
  const double v1 = knife.volume();
  const auto   through = knife.apply_wear(side_depth(knife.surface(), 0.05));
  EXPECT_FALSE(through.worn_through.empty());
  EXPECT_DOUBLE_EQ(knife.volume(), v1);

  // a threshold above the fresh mesh's quality forces a remesh; the accumulated depth comes along
  PartModel::Settings strict = settings;
  strict.remesh_quality       = 10;
  PartModel   remeshing(ParametricKnife(), strict);
  const auto   rr = remeshing.apply_wear(side_depth(remeshing.surface(), 0.002));
  EXPECT_TRUE(rr.remeshed);
  EXPECT_EQ(remeshing.n_remeshes(), 1u);
  double total = 0;
  for (double d : remeshing.vertex_displacement())
    total += d;
  EXPECT_GT(total, 0);
  SolidOutput out(tmp("abrade_knife_model_out"), "knife");
  remeshing.write(out, 1.0);
}

// The wear depth is the distance below the design, not the vertex displacement: a uniform depth
// d on the whole wearable surface moves the chisel tip's vertices by d / sin(half edge angle)
// (2.85 d on the 40 mm bevel of a 30 mm plate) and the corners where the end faces meet the
// faces by up to 3 d, but the worn surface lies d below the design everywhere on it, and the
// largest wear depth is d (to the mesh's round-off), also after a remesh.
TEST(PartModel, WearDepthIsTheDistanceBelowTheDesign)
{
  PartModel::Settings settings;
  settings.mesh_size      = 0.03;
  settings.work_directory = tmp("abrade_knife_gauge");
  PartModel   knife(ParametricKnife(), settings);
  const double d = 0.002;
  for (int update = 0; update < 2; ++update)
    {
      const SolidSurface &s = knife.surface();
      std::vector<double> depth(s.vertices.size(), d);
      knife.apply_wear(depth);
      const auto   gauge    = knife.wear_depth();
      const auto  &travel   = knife.vertex_displacement();
      const double deepest  = *std::max_element(gauge.begin(), gauge.end());
      const double furthest = *std::max_element(travel.begin(), travel.end());
      // (1e-4: after the first update the ring of triangles at the clamped top is tilted, and the
      // least-squares offset of the vertices next to it is no longer exact to round-off)
      EXPECT_NEAR(deepest, (update + 1) * d, 1e-4 * d) << "update " << update + 1;
      EXPECT_GT(furthest, 2.8 * (update + 1) * d) << "the tip moves further than the surface recedes";
    }
  // the followed point at the middle of the edge: its recession is the tip's, d / sin(half angle)
  const double sin_half = 0.015 / std::hypot(0.015, 0.04);
  EXPECT_NEAR(knife.recession_at({Point<3>(0.2, 0, 0)})[0], 2 * d / sin_half, 1e-6 * d);
}

TEST(PartModel, CheckpointContinuesBitForBit)
{
  PartModel::Settings settings;
  settings.mesh_size      = 0.03;
  settings.work_directory = tmp("abrade_knife_checkpoint");
  auto wear = [](const SolidSurface &s) {
    std::vector<double> d(s.vertices.size());
    for (std::size_t v = 0; v < d.size(); ++v)
      d[v] = s.vertices[v][2] < 0.1 ? 0.0005 * (1 - s.vertices[v][2] / 0.1) : 0.0;
    return d;
  };
  PartModel a(ParametricKnife(), settings);
  a.apply_wear(wear(a.surface()));
  a.save(tmp("abrade_knife.ckpt"));
  PartModel b(ParametricKnife(), settings);
  b.load(tmp("abrade_knife.ckpt"));
  ASSERT_EQ(a.surface().vertices.size(), b.surface().vertices.size());
  for (int update = 0; update < 2; ++update)
    {
      a.apply_wear(wear(a.surface()));
      b.apply_wear(wear(b.surface()));
    }
  for (std::size_t v = 0; v < a.surface().vertices.size(); ++v)
    for (unsigned c = 0; c < 3; ++c)
      ASSERT_EQ(a.surface().vertices[v][c], b.surface().vertices[v][c]);
  EXPECT_EQ(a.vertex_displacement(), b.vertex_displacement());
  EXPECT_EQ(a.wear_depth(), b.wear_depth());
  EXPECT_EQ(a.volume(), b.volume());
}

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
