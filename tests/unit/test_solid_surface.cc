// The knife's boundary surface (outward, closed, the solid's volume by the divergence theorem),
// solids read from STL and .msh files, and remeshing from the current boundary.
#include <abrade/common/error.h>
#include <abrade/common/vtk_input.h>

#include <vtkPolyData.h>
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/manifold_lib.h>

#include "fem_test_helpers.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

using namespace dealii;
using namespace abrade::fem;
using namespace abrade::fem::testing;

namespace
{
  double signed_volume(const SolidSurface &s)
  {
    double v = 0;
    for (const auto &t : s.triangles)
      v += s.vertices[t[0]] * cross_product_3d(s.vertices[t[1]], s.vertices[t[2]]) / 6;
    return v;
  }
} // namespace

TEST(SolidSurface, OutwardClosedSurfaceOfTheKnife)
{
  ParametricKnife    k;
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_surface.msh"));
  const SolidSurface s = extract_surface(tria);
  EXPECT_NEAR(signed_volume(s), 0.00576, 1e-12); // outward orientation everywhere
  // every edge is shared by exactly two triangles
  std::map<std::pair<unsigned, unsigned>, int> edges;
  for (const auto &t : s.triangles)
    for (int e = 0; e < 3; ++e)
      ++edges[std::minmax(t[e], t[(e + 1) % 3])];
  for (const auto &[e, n] : edges)
    ASSERT_EQ(n, 2);
  const SolidSurface top = extract_surface(tria, {clamped_boundary});
  EXPECT_NEAR(top.area(), 0.4 * 0.03, 1e-12);
  for (const auto &n : top.vertex_normals())
    EXPECT_NEAR(n[2], 1, 1e-12);
}

TEST(SolidSurface, StlAndMshFilesRoundTrip)
{
  ParametricKnife    k;
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_roundtrip.msh"));
  abrade::io::write_stl(tmp("abrade_knife_surface.stl"), extract_surface(tria).as_polydata());
  Triangulation<3> from_stl;
  read_solid(tmp("abrade_knife_surface.stl"), 0.02, from_stl);
  EXPECT_NEAR(mesh_volume(from_stl), 0.00576, 1e-9);
  EXPECT_EQ(mesh_quality(from_stl).n_inverted, 0u);
  Triangulation<3> from_msh;
  read_solid(tmp("abrade_roundtrip.msh"), 0, from_msh);
  EXPECT_EQ(from_msh.n_active_cells(), tria.n_active_cells());
  EXPECT_NEAR(boundary_area(from_msh, clamped_boundary), 0.012, 1e-12);
}

TEST(SolidSurface, StepRoundTrip)
{
  ParametricKnife k;
  k.bevel_side = ParametricKnife::BevelSide::minus;
  k.write_step(tmp("abrade_knife.step"));
  Triangulation<3> tria;
  read_solid(tmp("abrade_knife.step"), 0.03, tria);
  EXPECT_NEAR(mesh_volume(tria), k.volume(), 1e-9);
  // the file's face numbers are the boundary ids: the one-sided knife has six faces
  std::set<types::boundary_id> ids;
  for (const auto &face : tria.active_face_iterators())
    if (face->at_boundary())
      ids.insert(face->boundary_id());
  EXPECT_EQ(ids.size(), 6u);
}

// A user's part in millimetres: an STL (no unit) with File scale 0.001 gives the knife's volume;
// without it the part is refused naming its size and the likely scale; a mesh that would need too
// many tetrahedra is refused before Gmsh meshes it. (STEP files declare their unit:
// StepRoundTrip reads a STEP in millimetres.)
TEST(SolidSurface, PartsInMillimetres)
{
  ParametricKnife    k;
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_mm_knife.msh"));
  abrade::io::PolyData surface = extract_surface(tria).as_polydata();
  for (double &x : surface.points)
    x *= 1000;
  abrade::io::write_stl(tmp("abrade_knife_mm.stl"), surface);
  SolidFileSettings mm;
  mm.scale = 0.001;
  Triangulation<3> read;
  read_solid(tmp("abrade_knife_mm.stl"), 0.03, read, mm);
  EXPECT_NEAR(mesh_volume(read) / k.volume(), 1, 1e-9);
  try
    {
      Triangulation<3> wrong;
      read_solid(tmp("abrade_knife_mm.stl"), 0.03, wrong, SolidFileSettings());
      FAIL() << "a part of 400 m was read";
    }
  catch (const abrade::InputError &e)
    {
      const std::string what = e.what();
      EXPECT_NE(what.find("abrade_knife_mm.stl"), std::string::npos) << what;
      EXPECT_NE(what.find("400 x 30 x 500 m"), std::string::npos) << what;
      EXPECT_NE(what.find("File scale"), std::string::npos) << what;
    }
  k.write_step(tmp("abrade_budget_knife.step"));
  SolidFileSettings budget;
  budget.max_cells = 1e5;
  try
    {
      Triangulation<3> fine;
      read_solid(tmp("abrade_budget_knife.step"), 0.002, fine, budget);
      FAIL() << "an over-budget mesh was made";
    }
  catch (const abrade::InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("tetrahedra"), std::string::npos) << e.what();
    }
}

// A CAD file's surfaces as triangles (a grab shell from a design tool is read this way): the
// knife's STEP file meshed at 30 mm has the area of the knife's solid surface (planar faces:
// exact), every triangle edge near the requested size; bad input names the file.
TEST(SolidSurface, CadSurfaceOfTheKnife)
{
  ParametricKnife k;
  k.write_step(tmp("abrade_cad_knife.step"));
  const SolidSurface cad = read_cad_surface(tmp("abrade_cad_knife.step"), 0.03);
  Triangulation<3>   tria;
  read_solid(tmp("abrade_cad_knife.step"), 0.03, tria);
  EXPECT_GT(cad.triangles.size(), 50u);
  EXPECT_NEAR(cad.area() / extract_surface(tria).area(), 1, 1e-9);
  double longest = 0;
  for (const auto &t : cad.triangles)
    for (int e = 0; e < 3; ++e)
      longest = std::max(longest, cad.vertices[t[e]].distance(cad.vertices[t[(e + 1) % 3]]));
  EXPECT_LT(longest, 0.03 * 1.5);
  for (const auto &t : cad.triangles) // every vertex is used
    for (unsigned v : t)
      EXPECT_LT(v, cad.vertices.size());
  EXPECT_TRUE(is_cad_file("a/b/Shell.STP") && is_cad_file("x.igs") && !is_cad_file("x.stl"));
  for (const std::string &bad : {tmp("no_such_shell.step"), tmp("abrade_knife_surface.stl")})
    try
      {
        read_cad_surface(bad, 0.03);
        FAIL() << bad << " was read as CAD";
      }
    catch (const std::exception &e)
      {
        EXPECT_NE(std::string(e.what()).find(std::filesystem::path(bad).filename().string()), std::string::npos)
          << e.what();
      }
  EXPECT_THROW(read_cad_surface(tmp("abrade_cad_knife.step"), 0), std::exception);
}

TEST(SolidSurface, BadSolidFilesAreClearErrors)
{
  Triangulation<3> t;
  EXPECT_THROW(read_solid(tmp("no_such_knife.step"), 0.01, t), std::exception);
  // an open surface (one triangle) encloses nothing
  const std::string open = tmp("abrade_open.stl");
  std::ofstream(open) << "solid o\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
                         "endloop\nendfacet\nendsolid o\n";
  Triangulation<3> t2;
  try
    {
      read_solid(open, 0.1, t2);
      FAIL() << "an open surface was meshed";
    }
  catch (const std::exception &e)
    {
      EXPECT_NE(std::string(e.what()).find("abrade_open.stl"), std::string::npos) << e.what();
    }
}

// A bolted edge's worn surface (written by a DEM lifetime run of cases/bolted_edge, session 20)
// that Gmsh refused to remesh with its facets classified at 15 degrees ("Invalid boundary mesh
// (overlapping facets) on surface 6"): the run then filled the knife inside the surface's own
// triangles, whose vertices fold again on the next step. The remesh tries larger angles in turn
// (20 degrees meshes it) before it fills: remeshed, nothing kept.
TEST(Remesh, WornSurfaceGmshRefusesAtFifteenDegrees)
{
  const abrade::io::PolyData surface =
    abrade::io::triangles_of(abrade::io::read_polydata(std::string(ABRADE_TESTS_DIR) + "/lifetime/worn_bolted_edge.stl"));
  const SolidSurface ids = surface_of(surface);
  Triangulation<3>  fresh;
  const std::string kept = mesh_closed_surface(surface, 0.02, fresh, tmp("abrade_worn_bolted"), ids);
  EXPECT_EQ(kept, "") << "filled inside its own triangles instead of remeshed";
  EXPECT_GT(fresh.n_active_cells(), 0u);
  EXPECT_EQ(mesh_quality(fresh).n_inverted, 0u);
}

TEST(SolidSurface, RemeshKeepsTheShapeAndBoundaryIds)
{
  ParametricKnife    k;
  Triangulation<3> tria, fresh;
  k.mesh(tria, 0.03, tmp("abrade_before_remesh.msh"));
  remesh(tria, 0.015, fresh, tmp("abrade_remesh"));
  EXPECT_GT(fresh.n_active_cells(), tria.n_active_cells());
  EXPECT_NEAR(mesh_volume(fresh), 0.00576, 1e-9);
  EXPECT_NEAR(boundary_area(fresh, clamped_boundary), 0.012, 1e-9);
  EXPECT_EQ(mesh_quality(fresh).n_inverted, 0u);

  // a field linear over the surface (a wear depth, say) comes across exactly, up to the
  // single-precision coordinates of the STL the remesh goes through (~1e-8 m)
  const SolidSurface  before = extract_surface(tria), after = extract_surface(fresh);
  std::vector<double> depth(before.vertices.size());
  for (std::size_t v = 0; v < depth.size(); ++v)
    depth[v] = 0.001 + 0.01 * before.vertices[v][0] - 0.004 * before.vertices[v][2];
  const auto moved = transfer_surface_field(before, depth, after);
  for (std::size_t v = 0; v < moved.size(); ++v)
    EXPECT_NEAR(moved[v], 0.001 + 0.01 * after.vertices[v][0] - 0.004 * after.vertices[v][2], 1e-9);
}

// The worn box's new mesh takes its boundary ids from the design: a 0.1 m cube with its top
// clamped, worn 20 mm on every other face (the rim moved within the clamped plane), meshed in
// 5 mm cells. Clamped: exactly the top's unworn (0.06 m)^2; everything else wears. The nearest
// design triangle's id alone clamps the side faces' top row (their centres 2.5 mm below the
// clamped plane and 20 mm inside the sides); so did the nearest face of a surface the wear had
// moved on from.
TEST(SolidSurface, IdsFromTheDesignKeepTheClampedFaceExactly)
{
  Triangulation<3> design_tria, worn;
  GridGenerator::hyper_cube(design_tria, 0, 0.1);
  for (const auto &face : design_tria.active_face_iterators())
    if (face->at_boundary())
      face->set_boundary_id(face->center()[2] > 0.1 - 1e-9 ? clamped_boundary
                                                          : wearable_boundary);
  const SolidSurface design = extract_surface(design_tria);
  GridGenerator::subdivided_hyper_rectangle(worn, {12, 12, 16}, Point<3>(0.02, 0.02, 0.02), Point<3>(0.08, 0.08, 0.1));
  const std::size_t on = set_ids_from_design(worn, design, 1e-5, wearable_boundary);
  EXPECT_EQ(on, 144u);
  EXPECT_NEAR(boundary_area(worn, clamped_boundary), 0.06 * 0.06, 1e-12);
  for (const auto &face : worn.active_face_iterators())
    if (face->at_boundary() && face->boundary_id() == clamped_boundary)
      EXPECT_NEAR(face->center()[2], 0.1, 1e-12);
}

// A curved clamped face (a cylinder's hull, 50 mm radius, clamped; its ends wear): the design
// faceted finely (two refinements onto the cylinder), the new mesh coarse (its hull faces span
// 90 degrees, their centres 15 mm inside the hull). Every hull face stays clamped, every end
// face wears: the corners lie on the design. (Judged by the centres' distance, every hull face
// had worn.)
TEST(SolidSurface, IdsFromTheDesignKeepACurvedClampedFace)
{
  Triangulation<3> design_tria, coarse;
  GridGenerator::cylinder(coarse, 0.05, 0.1);
  design_tria.copy_triangulation(coarse);
  design_tria.set_all_manifold_ids_on_boundary(0, 0);
  design_tria.set_manifold(0, CylindricalManifold<3>(0));
  design_tria.refine_global(2);
  for (auto *t : {&design_tria, &coarse})
    for (const auto &face : t->active_face_iterators())
      if (face->at_boundary())
        face->set_boundary_id(std::abs(std::abs(face->center()[0]) - 0.1) < 1e-9 ? wearable_boundary
                                                                                 : clamped_boundary);
  const SolidSurface design = extract_surface(design_tria);
  Triangulation<3>   fresh;
  fresh.copy_triangulation(coarse);
  for (const auto &face : fresh.active_face_iterators())
    if (face->at_boundary())
      face->set_boundary_id(wearable_boundary);
  set_ids_from_design(fresh, design, 1e-6, wearable_boundary);
  unsigned hull = 0;
  for (const auto &face : fresh.active_face_iterators())
    if (face->at_boundary())
      {
        const bool end = std::abs(std::abs(face->center()[0]) - 0.1) < 1e-9;
        EXPECT_EQ(face->boundary_id(), end ? wearable_boundary : clamped_boundary)
          << "face at " << face->center();
        hull += !end;
      }
  EXPECT_GT(hull, 3u);
}

TEST(SolidSurface, LocalThicknessAndWornThrough)
{
  ParametricKnife    k;
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_thickness.msh"));
  const SolidSurface  s = extract_surface(tria);
  const auto          normals = s.vertex_normals();
  const auto          thickness = local_thickness(s);
  std::vector<double> depth(s.vertices.size(), 0.0);
  int                 side_vertices = 0;
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    {
      const Point<3> &p = s.vertices[v];
      // interior vertices of the flat sides (away from edges): the plate is 30 mm thick
      if (std::abs(std::abs(p[1]) - 0.015) < 1e-9 && p[2] > 0.1 && p[2] < 0.45 && p[0] > 0.05 && p[0] < 0.35)
        {
          EXPECT_NEAR(thickness[v], 0.03, 1e-9);
          ++side_vertices;
          depth[v] = p[1] > 0 && p[2] < 0.3 ? 0.031 : 0.01; // wear through one region only
        }
      // the top face: the ray goes down through the whole knife to the edge or the bevels
      if (std::abs(p[2] - 0.5) < 1e-9 && std::abs(normals[v][2] - 1) < 1e-12)
        {
          EXPECT_GT(thickness[v], 0.45);
        }
    }
  ASSERT_GT(side_vertices, 4);
  const auto through = worn_through(s, depth);
  ASSERT_FALSE(through.empty());
  for (unsigned v : through)
    {
      EXPECT_GT(s.vertices[v][1], 0);
      EXPECT_LT(s.vertices[v][2], 0.3);
    }
}

// A hollow cube (a 1 m box around a 0.4 m cavity): the ray from a point of the outer wall meets
// the cavity's wall first, 0.3 m in, not the far outer wall 1 m away; the first hit is the
// thickness.
TEST(SolidSurface, LocalThicknessIsTheFirstWallTheRayMeets)
{
  SolidSurface s;
  auto add_box = [&](double lo, double hi, bool outward) {
    const unsigned first = static_cast<unsigned>(s.vertices.size());
    for (unsigned c = 0; c < 8; ++c)
      s.vertices.emplace_back(c & 1 ? hi : lo, c & 2 ? hi : lo, c & 4 ? hi : lo);
    // outward (counter-clockwise seen from outside) faces of the unit cube's corners
    const std::array<std::array<unsigned, 4>, 6> quads = {
      {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}};
    for (const auto &q : quads)
      for (const auto &t : {std::array<unsigned, 3>{q[0], q[1], q[2]}, std::array<unsigned, 3>{q[0], q[2], q[3]}})
        s.triangles.push_back(outward ? std::array<unsigned, 3>{first + t[0], first + t[1], first + t[2]}
                                      : std::array<unsigned, 3>{first + t[0], first + t[2], first + t[1]});
  };
  add_box(0, 1, true);
  add_box(0.3, 0.7, false);
  s.boundary_id.assign(s.triangles.size(), 1);
  // a vertex in the middle of the outer wall x = 0: split the face's triangles there
  const unsigned mid = static_cast<unsigned>(s.vertices.size());
  s.vertices.emplace_back(0, 0.5, 0.5);
  std::vector<std::array<unsigned, 3>> kept;
  for (const auto &t : s.triangles)
    if (t[0] < 8 && s.vertices[t[0]][0] == 0 && s.vertices[t[1]][0] == 0 && s.vertices[t[2]][0] == 0)
      for (unsigned e = 0; e < 3; ++e)
        kept.push_back({t[e], t[(e + 1) % 3], mid});
    else
      kept.push_back(t);
  s.triangles = kept;
  s.boundary_id.assign(s.triangles.size(), 1);
  EXPECT_NEAR(signed_volume(s), 1 - 0.4 * 0.4 * 0.4, 1e-12);
  const auto thickness = local_thickness(s);
  EXPECT_NEAR(thickness[mid], 0.3, 1e-9);
  // and a cavity's corner looks into the solid along the diagonal, away from the cavity: to the
  // outer box's corner, 0.3 sqrt(3)
  EXPECT_NEAR(thickness[8], 0.3 * std::sqrt(3.0), 1e-9);
}

// The offset surface: a uniform inward depth d moves the flat faces by d along their normals,
// the chisel tip up by d / sin(half angle) (where the two offset bevels meet), and every vertex
// on the bevel-side edge to the intersection of its two offset faces.
TEST(SolidSurface, InwardOffsetsFollowTheOffsetSurfaceAtEdges)
{
  ParametricKnife    k; // 30 mm plate, 40 mm bevel on both sides
  Triangulation<3> tria;
  k.mesh(tria, 0.03, tmp("abrade_offsets.msh"));
  const SolidSurface        s = extract_surface(tria);
  const double              d = 1e-3;
  const auto                u = s.inward_offsets(std::vector<double>(s.vertices.size(), d));
  const double              sin_half = 0.015 / std::hypot(0.015, 0.04);
  int                       tips = 0, flats = 0, bevel_edges = 0;
  const Tensor<1, 3>        bevel_plus({0, 0.04 / std::hypot(0.015, 0.04), -sin_half}); // outward
  for (std::size_t v = 0; v < s.vertices.size(); ++v)
    {
      const Point<3> &p = s.vertices[v];
      if (p[0] < 0.01 || p[0] > 0.39 || p[2] > 0.49)
        continue; // not near the end faces or the top
      if (std::abs(p[2]) < 1e-12)
        {
          EXPECT_NEAR(u[v][2], d / sin_half, 1e-12);
          EXPECT_NEAR(u[v][0], 0, 1e-12);
          EXPECT_NEAR(u[v][1], 0, 1e-12);
          ++tips;
        }
      else if (std::abs(p[1] - 0.015) < 1e-12 && std::abs(p[2] - 0.04) < 1e-12)
        {
          // on the +y face's plane moved by d, and on the +y bevel's plane moved by d
          EXPECT_NEAR(u[v][1], -d, 1e-12);
          EXPECT_NEAR(u[v] * bevel_plus, -d, 1e-12);
          ++bevel_edges;
        }
      else if (std::abs(p[1] - 0.015) < 1e-12 && p[2] > 0.05 && p[2] < 0.45)
        {
          EXPECT_NEAR(u[v][1], -d, 1e-12);
          EXPECT_NEAR(u[v][0], 0, 1e-12);
          EXPECT_NEAR(u[v][2], 0, 1e-12);
          ++flats;
        }
    }
  EXPECT_GT(tips, 3);
  EXPECT_GT(bevel_edges, 3);
  EXPECT_GT(flats, 3);
}

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
