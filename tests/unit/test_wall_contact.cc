// Sphere-triangle contacts that touch several triangles count once
// (shared/reference/design-notes.md): a sphere over a shared edge or vertex of a flat,
// triangulated plane feels exactly the force it feels over a face with the same overlap, and a
// sphere against a convex edge or corner of a box feels the Hertz force of that overlap along
// the line to the edge or corner.
#include "dem_test_helpers.h"

#include <gtest/gtest.h>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  struct CountContacts : StepHook
  {
    std::size_t contacts = 0;
    void after_step(const Simulation &, const ContactLog &log) override { contacts = log.size(); }
  };

  const Material pellet = Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, false);
  const Material steel  = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, false);
  constexpr double R = 0.0275, overlap = 1e-3;

  /// Force on a resting sphere placed at @p centre against @p mesh, and the number of contacts.
  std::pair<Vec3, std::size_t> static_force(const TriangleMesh &mesh, const Vec3 &centre)
  {
    Simulation sim(quiet_settings(1e-5));
    const int  mp = sim.add_material(pellet), mw = sim.add_material(steel);
    sim.set_interaction(mp, mw, {0.6, 0.5, 0.0});
    Wall w;
    w.name = "wall", w.mesh = mesh, w.material = mw;
    sim.add_wall(w);
    auto counter = std::make_shared<CountContacts>();
    sim.add_hook(counter);
    sim.particles().add(0, centre[0], centre[1], centre[2], R, pellet.density, mp);
    sim.setup(); // computes the forces of the initial positions
    const auto &P = sim.particles();
    const Vec3  f(P.fx[0], P.fy[0], P.fz[0]);
    sim.step(); // the hook counts the contacts of one step
    return {f, counter->contacts};
  }

  double hertz(double delta)
  {
    return 4.0 / 3.0 * e_star(pellet, steel) * std::sqrt(R) * std::pow(delta, 1.5);
  }
} // namespace

TEST(WallContact, EdgeAndVertexOfFlatMeshGiveTheFaceForce)
{
  // a 1 m plate split into a regular grid of 0.1 m right triangles
  TriangleMesh plate = primitives::plate(Vec3::Zero(), 2, 1.0, 1.0, 0.1);
  ASSERT_GT(plate.n_triangles(), 100u);
  const double z = R - overlap;

  // find an interior vertex and an interior edge midpoint
  Vec3 vertex = plate.vertices[0];
  for (const auto &v : plate.vertices)
    if (v.norm() < vertex.norm())
      vertex = v;
  const auto &t0   = plate.triangles[plate.n_triangles() / 2];
  const Vec3  edge = 0.5 * (plate.vertices[t0[0]] + plate.vertices[t0[1]]);
  const Vec3  face = (plate.vertices[t0[0]] + plate.vertices[t0[1]] + plate.vertices[t0[2]]) / 3;

  const auto [f_face, n_face]     = static_force(plate, Vec3(face[0], face[1], z));
  const auto [f_edge, n_edge]     = static_force(plate, Vec3(edge[0], edge[1], z));
  const auto [f_vertex, n_vertex] = static_force(plate, Vec3(vertex[0], vertex[1], z));
  const double expected           = hertz(overlap);
  EXPECT_NEAR(f_face[2] / expected, 1, 1e-12);
  EXPECT_NEAR(f_edge[2] / f_face[2], 1, 1e-12);
  EXPECT_NEAR(f_vertex[2] / f_face[2], 1, 1e-12);
  EXPECT_NEAR(f_edge[0], 0, 1e-9 * expected);
  EXPECT_NEAR(f_vertex[1], 0, 1e-9 * expected);
  EXPECT_EQ(n_face, 1u);
  EXPECT_EQ(n_edge, 1u);
  EXPECT_EQ(n_vertex, 1u);
}

TEST(WallContact, DeepOverlapOnAFineMeshIsOneContact)
{
  // triangles of 5 mm under a 27.5 mm sphere with 6 mm overlap: the contact circle (18 mm)
  // covers many triangles, whose own closest points lie on their edges; only one contact counts
  const TriangleMesh plate = primitives::plate(Vec3::Zero(), 2, 0.2, 0.2, 0.005);
  for (const Vec3 &c : {Vec3(0.0013, 0.0021, 0), Vec3(0, 0, 0), Vec3(0.0025, 0, 0)})
    {
      const auto [f, n] = static_force(plate, c + Vec3(0, 0, R - 0.006));
      EXPECT_EQ(n, 1u);
      EXPECT_NEAR(f[2] / hertz(0.006), 1, 1e-12);
      EXPECT_NEAR(f.head<2>().norm(), 0, 1e-9 * f[2]);
    }
}

TEST(WallContact, ConvexEdgeAndCornerOfABox)
{
  // closed unit box [0,1]^3; contacts from outside at its edge x = 1, z = 1 and corner (1,1,1)
  const TriangleMesh box = primitives::box_container(Vec3::Zero(), Vec3::Ones(), true);
  const double       d   = R - overlap;
  const Vec3         edge_dir   = Vec3(1, 0, 1).normalized();
  const Vec3         corner_dir = Vec3(1, 1, 1).normalized();
  const auto [f_edge, n_edge]     = static_force(box, Vec3(1, 0.5, 1) + d * edge_dir);
  const auto [f_corner, n_corner] = static_force(box, Vec3(1, 1, 1) + d * corner_dir);
  EXPECT_NEAR(f_edge.norm() / hertz(overlap), 1, 1e-12);
  EXPECT_NEAR(f_corner.norm() / hertz(overlap), 1, 1e-12);
  EXPECT_NEAR(f_edge.normalized().dot(edge_dir), 1, 1e-12);
  EXPECT_NEAR(f_corner.normalized().dot(corner_dir), 1, 1e-12);
  EXPECT_EQ(n_edge, 1u);
  EXPECT_EQ(n_corner, 1u);
}

TEST(WallContact, ConcaveCornerGivesOneContactPerFace)
{
  // inside the container corner a sphere touching the floor and two side walls: three contacts
  const TriangleMesh box = primitives::box_container(Vec3::Zero(), Vec3::Ones());
  const double       d   = R - overlap;
  const auto [f, n]      = static_force(box, Vec3(d, d, d));
  EXPECT_EQ(n, 3u);
  for (int k = 0; k < 3; ++k)
    EXPECT_NEAR(f[k] / hertz(overlap), 1, 1e-12);
}
