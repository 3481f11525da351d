// Triangle meshes: the reference knife's volume, conforming refinement, welding, closedness,
// the closest-point features, mesh files through VTK (STL written and read back), and the signed
// distance and wear depth of surface_distance.h.
#include <abrade/common/error.h>
#include <abrade/common/closest_point.h>
#include <abrade/common/surface_distance.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/mesh_io.h>
#include <abrade/dem/triangle_mesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <thread>

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

// ---------------------------------------------------------------------------------------------
// Signed distance and wear depth (surface_distance.h): exact distances and signs at faces,
// edges and corners of a box and of a chisel prism with a 41-degree edge, the inward offset of
// the chisel at depth d everywhere (its tip moved 2.86 d), and random points against a brute
// force loop (closest point, pseudonormal) and against ray parity.

namespace
{
  using geometry::SurfaceDistance;

  /// A surface as SurfaceDistance takes it.
  struct Soup
  {
    std::vector<double>              points;
    std::vector<std::array<long, 3>> triangles;
    long add(const Vec3 &p)
    {
      points.insert(points.end(), {p[0], p[1], p[2]});
      return long(points.size() / 3 - 1);
    }
    SurfaceDistance distance() const { return SurfaceDistance(points, triangles); }
  };

  Soup soup(const TriangleMesh &m)
  {
    Soup s;
    for (const auto &v : m.vertices)
      s.add(v);
    for (const auto &t : m.triangles)
      s.triangles.push_back({t[0], t[1], t[2]});
    return s;
  }

  TriangleMesh mesh(const Soup &s)
  {
    TriangleMesh m;
    for (std::size_t v = 0; v < s.points.size() / 3; ++v)
      m.vertices.emplace_back(s.points[3 * v], s.points[3 * v + 1], s.points[3 * v + 2]);
    for (const auto &t : s.triangles)
      m.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    return m;
  }

  double sd(const SurfaceDistance &s, const Vec3 &q)
  {
    const double p[3] = {q[0], q[1], q[2]};
    return s.signed_distance(p);
  }

  /// A polygon in the (y, z) plane, counter-clockwise seen from +x and star-shaped from its first
  /// vertex, extruded over x0 <= x <= x1: caps fanned from the first vertex, sides split in two.
  Soup prism(const std::vector<std::array<double, 2>> &polygon, double x0, double x1)
  {
    Soup       s;
    const long n = long(polygon.size());
    for (double x : {x0, x1})
      for (const auto &p : polygon)
        s.add(Vec3(x, p[0], p[1]));
    for (long k = 1; k + 1 < n; ++k)
      {
        s.triangles.push_back({0, k + 1, k});         // x0 cap, normal -x
        s.triangles.push_back({n, n + k, n + k + 1}); // x1 cap, normal +x
      }
    for (long k = 0; k < n; ++k)
      {
        const long a0 = k, b0 = (k + 1) % n, a1 = a0 + n, b1 = b0 + n;
        s.triangles.push_back({a0, b0, b1});
        s.triangles.push_back({a0, b1, a1});
      }
    return s;
  }

  /// The chisel: back face y = 0, bevel from the tip (y, z) = (0, 0) to (w, w / tan 41 deg),
  /// side y = w, top z = h; a sharp 41-degree edge along x.
  const double chisel_angle = 41 * M_PI / 180, chisel_w = 0.03, chisel_h = 0.2, chisel_x0 = -0.05, chisel_x1 = 0.07;
  std::vector<std::array<double, 2>> chisel_polygon()
  {
    return {{0, 0}, {chisel_w, chisel_w / std::tan(chisel_angle)}, {chisel_w, chisel_h}, {0, chisel_h}};
  }

  /// Outward unit normals (in y, z) of a counter-clockwise polygon's edges (k, k+1), and the
  /// offsets h_k of their lines n_k . p = h_k.
  void polygon_planes(const std::vector<std::array<double, 2>> &p, std::vector<Vec3> &n, std::vector<double> &h)
  {
    n.clear(), h.clear();
    for (std::size_t k = 0; k < p.size(); ++k)
      {
        const auto &a = p[k], &b = p[(k + 1) % p.size()];
        Vec3        e(0, b[0] - a[0], b[1] - a[1]);
        e.normalize();
        n.emplace_back(0, e[2], -e[1]);
        h.push_back(n.back()[1] * a[0] + n.back()[2] * a[1]);
      }
  }

  /// The polygon whose edges are those of @p p moved inward by @p d (p convex, d small).
  std::vector<std::array<double, 2>> offset_polygon(const std::vector<std::array<double, 2>> &p, double d)
  {
    std::vector<Vec3>   n;
    std::vector<double> h;
    polygon_planes(p, n, h);
    std::vector<std::array<double, 2>> q;
    const std::size_t                  m = p.size();
    for (std::size_t k = 0; k < m; ++k) // vertex k: the lines of edges k-1 and k
      {
        const Vec3  &a = n[(k + m - 1) % m], &b = n[k];
        const double ha = h[(k + m - 1) % m] - d, hb = h[k] - d, det = a[1] * b[2] - a[2] * b[1];
        q.push_back({(ha * b[2] - hb * a[2]) / det, (a[1] * hb - b[1] * ha) / det});
      }
    return q;
  }

  /// Brute force: the closest point over all triangles, and the sign from the pseudonormal of its
  /// feature, the faces around an edge or a vertex found by their coordinates.
  double brute_force(const TriangleMesh &m, const Vec3 &q)
  {
    double       best = 1e300;
    std::size_t  bt   = 0;
    ClosestPoint bc{};
    for (std::size_t t = 0; t < m.n_triangles(); ++t)
      {
        const auto        &tri = m.triangles[t];
        const ClosestPoint c   = closest_point_on_triangle(q.data(), m.vertices[tri[0]].data(), m.vertices[tri[1]].data(),
                                                           m.vertices[tri[2]].data());
        const double       d2  = (q - Vec3(c.p[0], c.p[1], c.p[2])).squaredNorm();
        if (d2 < best)
          best = d2, bt = t, bc = c;
      }
    const auto &tri = m.triangles[bt];
    Vec3        n   = Vec3::Zero();
    if (bc.feature == face)
      n = m.normal(bt);
    else if (bc.feature <= edge20)
      {
        const int  k = bc.feature - edge01;
        const Vec3 a = m.vertices[tri[k]], b = m.vertices[tri[(k + 1) % 3]];
        for (std::size_t t = 0; t < m.n_triangles(); ++t)
          {
            int has = 0;
            for (int j : m.triangles[t])
              has += (m.vertices[j] == a) + (m.vertices[j] == b);
            if (has == 2)
              n += m.normal(t);
          }
      }
    else
      {
        const Vec3 v = m.vertices[tri[bc.feature - vertex0]];
        for (std::size_t t = 0; t < m.n_triangles(); ++t)
          for (int j = 0; j < 3; ++j)
            if (m.vertices[m.triangles[t][j]] == v)
              {
                const Vec3 u = m.vertices[m.triangles[t][(j + 1) % 3]] - v, w = m.vertices[m.triangles[t][(j + 2) % 3]] - v;
                n += std::acos(std::clamp(u.normalized().dot(w.normalized()), -1.0, 1.0)) * m.normal(t);
              }
      }
    const double r = std::sqrt(best);
    return (q - Vec3(bc.p[0], bc.p[1], bc.p[2])).dot(n) < 0 ? -r : r;
  }
} // namespace

TEST(SurfaceDistance, BoxFacesEdgesCorners)
{
  const Soup box = prism({{0, 0}, {2, 0}, {2, 3}, {0, 3}}, 0, 1); // [0,1] x [0,2] x [0,3]
  EXPECT_NEAR(mesh(box).volume(), 6, 1e-14);                    // closed, outward
  const SurfaceDistance s = box.distance();
  EXPECT_EQ(s.n_triangles(), 12u);
  // faces, outside and inside
  EXPECT_NEAR(sd(s, Vec3(0.3, 0.7, 3.2)), 0.2, 1e-12);
  EXPECT_NEAR(sd(s, Vec3(0.3, 0.7, 2.8)), -0.2, 1e-12);
  EXPECT_NEAR(sd(s, Vec3(-0.25, 1.1, 1.4)), 0.25, 1e-12);
  EXPECT_NEAR(sd(s, Vec3(0.5, 1, 1.5)), -0.5, 1e-12); // the centre
  EXPECT_NEAR(sd(s, Vec3(0.3, 0.7, 3)), 0.0, 1e-15); // on the face
  // every edge and every corner: outside along their normal cones (the distance to the edge's
  // line or to the corner), inside just within them (the distance to the nearer face)
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 2, 3};
  for (int a = 0; a < 3; ++a)
    for (int sb = 0; sb < 2; ++sb)
      for (int sc = 0; sc < 2; ++sc)
        {
          const int b = (a + 1) % 3, c = (a + 2) % 3;
          Vec3      p, u = Vec3::Zero();
          p[a] = 0.5 * (lo[a] + hi[a]) + 0.1;
          p[b] = sb ? hi[b] : lo[b], u[b] = sb ? 1 : -1;
          p[c] = sc ? hi[c] : lo[c], u[c] = sc ? 1 : -1;
          for (double f : {0.2, 1.0, 3.0}) // off the bisector, on it, off it
            {
              Vec3 v = u;
              v[b] *= f;
              EXPECT_NEAR(sd(s, p + 0.1 * v), 0.1 * v.norm(), 1e-12) << "edge " << a << sb << sc << " f " << f;
              EXPECT_NEAR(sd(s, p - 0.01 * v), -0.01 * std::min(1.0, f), 1e-12) << "edge " << a << sb << sc << " f " << f;
            }
        }
  for (int corner = 0; corner < 8; ++corner)
    {
      Vec3 p, u;
      for (int k = 0; k < 3; ++k)
        p[k] = (corner >> k & 1) ? hi[k] : lo[k], u[k] = (corner >> k & 1) ? 1 : -1;
      for (const Vec3 &w : {Vec3(1, 1, 1), Vec3(0.1, 1, 2), Vec3(3, 0.2, 0.5)})
        {
          const Vec3 v = u.cwiseProduct(w);
          EXPECT_NEAR(sd(s, p + 0.05 * v), 0.05 * w.norm(), 1e-12) << "corner " << corner;
          EXPECT_NEAR(sd(s, p - 0.01 * v), -0.01 * w.minCoeff(), 1e-12) << "corner " << corner;
        }
    }
}

TEST(SurfaceDistance, ChiselFacesEdgesCorners)
{
  const auto soup_ = prism(chisel_polygon(), chisel_x0, chisel_x1);
  const auto m     = mesh(soup_);
  EXPECT_GT(m.volume(), 0);
  EXPECT_TRUE(m.is_closed());
  const SurfaceDistance s = soup_.distance();
  // the faces' outward normals and planes n . x = h: four sides, then the caps x0 and x1
  const auto          poly = chisel_polygon();
  std::vector<Vec3>   n;
  std::vector<double> h;
  polygon_planes(poly, n, h);
  n.emplace_back(-1, 0, 0), h.push_back(-chisel_x0);
  n.emplace_back(1, 0, 0), h.push_back(chisel_x1);
  EXPECT_NEAR(std::acos(-n[0].dot(n[3])), chisel_angle, 1e-12); // the 41-degree edge (bevel, back)

  // outside: q = p + t u, u a unit vector of the normal cone at p (positive combinations of the
  // normals of the faces that meet there) has distance t; some of these u make an obtuse angle
  // with one of the faces' normals (the sign test of a face normal alone fails there)
  std::mt19937                           rng(41);
  std::uniform_real_distribution<double> unit(0, 1);
  const std::size_t                      m4 = poly.size();
  int                                    obtuse = 0;
  auto check_cone = [&](const Vec3 &p, const std::vector<int> &faces, const std::string &what) {
    for (int i = 0; i < 40; ++i)
      {
        Vec3 u = Vec3::Zero();
        for (int f : faces)
          u += (i < int(faces.size()) ? double(f == faces[i]) : unit(rng)) * n[f]; // the faces' normals, then mixes
        u.normalize();
        for (int f : faces)
          obtuse += u.dot(n[f]) < 0;
        for (double t : {1e-4, 3e-3, 0.05})
          EXPECT_NEAR(sd(s, p + t * u), t, 1e-12) << what << " u " << u.transpose() << " t " << t;
      }
  };
  for (std::size_t k = 0; k < m4; ++k)
    {
      const std::size_t prev = (k + m4 - 1) % m4;
      const Vec3        pk(0, poly[k][0], poly[k][1]), pn(0, poly[(k + 1) % m4][0], poly[(k + 1) % m4][1]);
      for (int end = 0; end < 2; ++end)
        {
          const double x = end ? chisel_x1 : chisel_x0;
          const int    cap = 4 + end;
          check_cone(pk + Vec3(x, 0, 0), {int(prev), int(k), cap}, "corner " + std::to_string(k) + "/" + std::to_string(end));
          check_cone(0.3 * pk + 0.7 * pn + Vec3(x, 0, 0), {int(k), cap}, "cap edge " + std::to_string(k));
        }
      check_cone(pk + Vec3(0.013, 0, 0), {int(prev), int(k)}, "long edge " + std::to_string(k));
      check_cone(0.4 * pk + 0.6 * pn + Vec3(0.021, 0, 0), {int(k)}, "side " + std::to_string(k));
    }
  EXPECT_GT(obtuse, 50); // the test holds such directions

  // inside a convex body the distance is that to the nearest face plane: points near the
  // sharp edge and the tip's corners (on the bisector the two faces tie), and elsewhere
  auto inside = [&](const Vec3 &q) {
    double d = -1e300;
    for (std::size_t f = 0; f < n.size(); ++f)
      d = std::max(d, n[f].dot(q) - h[f]);
    return d;
  };
  const Vec3 bisector = -(n[0] + n[3]).normalized();
  for (double t : {1e-5, 1e-3, 0.01})
    for (double x : {chisel_x0 + 1e-3, 0.0, chisel_x1 - 0.002})
      {
        const Vec3 q = Vec3(x, 0, 0) + t * bisector;
        EXPECT_NEAR(sd(s, q), inside(q), 1e-12) << q.transpose();
        EXPECT_LT(sd(s, q), 0);
      }
  std::uniform_real_distribution<double> ux(chisel_x0, chisel_x1), uy(0, chisel_w), uz(0, chisel_h);
  for (int i = 0; i < 2000; ++i)
    {
      const Vec3 q(ux(rng), uy(rng), uz(rng) * (i % 2 ? 1 : 0.3));
      const double expected = inside(q);
      if (expected < 0)
        {
          EXPECT_NEAR(sd(s, q), expected, 1e-12) << q.transpose();
        }
    }
}

TEST(SurfaceDistance, SharpApexOfATetrahedron)
{
  // a tall tetrahedron: its three side faces meet at the apex at acute dihedral angles, so that
  // for a point just outside the apex or a side edge, q - p makes an obtuse angle with the
  // normals of all but one of the faces there, whichever triangle the locator returns
  Soup t;
  for (int k = 0; k < 3; ++k)
    t.add(Vec3(0.02 * std::cos(2 * M_PI * k / 3), 0.02 * std::sin(2 * M_PI * k / 3), 0));
  const Vec3 apex(0.003, -0.002, 0.1);
  t.add(apex);
  t.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  const TriangleMesh m = mesh(t);
  ASSERT_GT(m.volume(), 0);
  const SurfaceDistance s = t.distance();
  const Vec3 n[3] = {m.normal(1), m.normal(2), m.normal(3)}; // sides (b0,b1), (b1,b2), (b2,b0)
  EXPECT_LT(n[0].dot(n[1]), -0.45);                          // dihedral angles of about 60 degrees
  int obtuse = 0;
  for (const Vec3 &w : {Vec3(1, 0.05, 0.05), Vec3(0.05, 1, 0.05), Vec3(0.05, 0.05, 1), Vec3(1, 1, 1), Vec3(1, 0.3, 0)})
    {
      const Vec3 u = (w[0] * n[0] + w[1] * n[1] + w[2] * n[2]).normalized();
      for (int f = 0; f < 3; ++f)
        obtuse += u.dot(n[f]) < 0;
      for (double d : {1e-4, 0.01})
        EXPECT_NEAR(sd(s, apex + d * u), d, 1e-12) << "apex, u " << u.transpose();
    }
  for (int k = 0; k < 3; ++k) // the side edge from base vertex k + 1 to the apex, between sides k and k + 1
    {
      const Vec3 p = 0.6 * apex + 0.4 * m.vertices[(k + 1) % 3];
      for (double w : {0.05, 0.5, 0.95})
        {
          const Vec3 u = (w * n[k] + (1 - w) * n[(k + 1) % 3]).normalized();
          obtuse += u.dot(n[k]) < 0 || u.dot(n[(k + 1) % 3]) < 0;
          EXPECT_NEAR(sd(s, p + 0.002 * u), 0.002, 1e-12) << "edge " << k << ", u " << u.transpose();
        }
    }
  EXPECT_GE(obtuse, 10);
  // inside: the distance to the nearest face plane
  for (const Vec3 &q : {Vec3(0.001, 0, 0.05), Vec3(0.00291, -0.00194, 0.097), Vec3(0, 0, 0.001)})
    {
      double expected = m.normal(0).dot(q - m.vertices[0]);
      for (int f = 0; f < 3; ++f)
        expected = std::max(expected, n[f].dot(q - apex));
      EXPECT_LT(expected, 0);
      EXPECT_NEAR(sd(s, q), expected, 1e-12) << q.transpose();
    }
}

TEST(SurfaceDistance, InwardOffsetOfTheChiselIsAtDepthD)
{
  const auto            poly   = chisel_polygon();
  const SurfaceDistance design = prism(poly, chisel_x0, chisel_x1).distance();
  std::mt19937          rng(7);
  std::uniform_real_distribution<double> unit(0, 1);
  for (double d : {1e-4, 0.001, 0.004})
    {
      const auto inner = offset_polygon(poly, d);
      // the tip moves d / sin(20.5 deg) = 2.856 d along the bisector, yet lies d below the design
      EXPECT_NEAR(std::hypot(inner[0][0], inner[0][1]), d / std::sin(chisel_angle / 2), 1e-15);
      const Soup offset = prism(inner, chisel_x0 + d, chisel_x1 - d);
      // its vertices (the tip's corners among them), points along its edges and on its faces
      std::vector<double> points = offset.points;
      auto vertex = [&](long v) { return Vec3(offset.points[3 * v], offset.points[3 * v + 1], offset.points[3 * v + 2]); };
      for (const auto &t : offset.triangles)
        for (int i = 0; i < 20; ++i)
          {
            double a = unit(rng), b = unit(rng);
            if (a + b > 1)
              a = 1 - a, b = 1 - b;
            const Vec3 e = (1 - a) * vertex(t[0]) + a * vertex(t[1]); // on an edge
            const Vec3 f = (1 - a - b) * vertex(t[0]) + a * vertex(t[1]) + b * vertex(t[2]);
            points.insert(points.end(), {e[0], e[1], e[2], f[0], f[1], f[2]});
          }
      for (double a : {0.25, 0.5, 0.75}) // along the tip edge
        {
          const Vec3 p = (1 - a) * vertex(0) + a * vertex(long(poly.size()));
          points.insert(points.end(), {p[0], p[1], p[2]});
        }
      const std::vector<double> depth = geometry::wear_depth(design, points);
      ASSERT_EQ(depth.size(), points.size() / 3);
      for (std::size_t i = 0; i < depth.size(); ++i)
        EXPECT_NEAR(depth[i], d, 1e-12) << "d " << d << " point " << i << ": " << points[3 * i] << ' '
                                         << points[3 * i + 1] << ' ' << points[3 * i + 2];
    }
  // outside the design the depth is negative: the offset outward (edges kept sharp: the
  // distance is d on the faces, more beyond the moved edge)
  const auto          outer = offset_polygon(poly, -0.002);
  std::vector<double> tip   = {0.01, outer[0][0], outer[0][1], 0.01, 0.5 * (outer[1][0] + outer[2][0]), 0.5 * (outer[1][1] + outer[2][1])};
  const auto          depth = geometry::wear_depth(design, tip);
  EXPECT_NEAR(depth[0], -0.002 / std::sin(chisel_angle / 2), 1e-12);
  EXPECT_NEAR(depth[1], -0.002, 1e-12);
}

TEST(SurfaceDistance, RandomPointsAgainstBruteForce)
{
  // the knife-bed knife (a 41-degree double bevel), refined (vertices where 3 to 8 triangles
  // meet), a refined L-shaped prism (concave edges and corners), and a 4 m x 30 mm x 0.3 m
  // plate (a grader blade's: the search grid's cells span its thickness; points metres away)
  TriangleMesh knife = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  knife.refine(0.03);
  TriangleMesh ell = mesh(prism({{0, 0}, {0.2, 0}, {0.2, 0.1}, {0.1, 0.1}, {0.1, 0.2}, {0, 0.2}}, -0.1, 0.15));
  ell.refine(0.04);
  TriangleMesh plate = mesh(prism({{0, 0}, {4, 0}, {4, 0.03}, {0, 0.03}}, 0, 0.3));
  plate.refine(0.05);
  for (const TriangleMesh *m : {&knife, &ell, &plate})
    {
      ASSERT_TRUE(m->is_closed());
      ASSERT_GT(m->volume(), 0);
      const SurfaceDistance s = soup(*m).distance();
      Vec3                  lo, hi;
      m->bounding_box(lo, hi);
      std::mt19937                           rng(2005);
      std::uniform_real_distribution<double> unit(0, 1), near(-0.01, 0.01);
      std::vector<Vec3>                      queries;
      for (int i = 0; i < 3000; ++i) // in the box and beyond it
        queries.push_back(lo + (hi - lo).cwiseProduct(Vec3(unit(rng), unit(rng), unit(rng)) * 1.4 - Vec3::Constant(0.2)));
      for (int i = 0; i < 3000; ++i) // near vertices (the features where signs go wrong)
        queries.push_back(m->vertices[std::size_t(unit(rng) * m->vertices.size()) % m->vertices.size()] +
                          Vec3(near(rng), near(rng), near(rng)));
      for (int i = 0; i < 300; ++i) // far away: up to three times the part's size from it
        queries.push_back(lo + (hi - lo).norm() * Vec3(unit(rng), unit(rng), unit(rng)) * 7 - Vec3::Constant(3 * (hi - lo).norm()));
      int sign_checked = 0;
      for (const Vec3 &q : queries)
        {
          const double got = sd(s, q), expected = brute_force(*m, q);
          EXPECT_NEAR(got, expected, 1e-12) << q.transpose();
          if (std::abs(expected) > 1e-9)
            {
              EXPECT_EQ(got < 0, inside_mesh(*m, q)) << q.transpose(); // ray parity, independent of normals
              ++sign_checked;
            }
        }
      EXPECT_GT(sign_checked, 6200);
    }
}

TEST(SurfaceDistance, SoupsDegenerateTrianglesAndBadInput)
{
  const Soup      box = prism({{0, 0}, {2, 0}, {2, 3}, {0, 3}}, 0, 1);
  std::vector<Vec3> queries = {Vec3(1.1, 2.2, 3.2), Vec3(1.2, 1, 3.2), Vec3(0.9, 1.9, 2.9), Vec3(0.5, 1, 1.5), Vec3(1, 2, 3)};
  const SurfaceDistance reference = box.distance();
  // every triangle with its own corners (an STL file): the same answers
  Soup separate;
  for (const auto &t : box.triangles)
    {
      std::array<long, 3> u;
      for (int k = 0; k < 3; ++k)
        u[k] = separate.add(Vec3(box.points[3 * t[k]], box.points[3 * t[k] + 1], box.points[3 * t[k] + 2]));
      separate.triangles.push_back(u);
    }
  // degenerate triangles: a repeated corner, collinear corners along an edge, all in one point
  Soup degenerate = box;
  const long mid  = degenerate.add(Vec3(1, 1, 3)); // on the edge from (1,0,3) to (1,2,3)
  degenerate.triangles.push_back({0, 0, 1});
  degenerate.triangles.push_back({7, mid, 6}); // (1,0,3), (1,1,3), (1,2,3)
  degenerate.triangles.push_back({5, 5, 5});
  const SurfaceDistance a = separate.distance();
  SurfaceDistance       b = degenerate.distance();
  EXPECT_EQ(b.n_triangles(), 15u);
  for (const Vec3 &q : queries)
    {
      EXPECT_EQ(sd(a, q), sd(reference, q));
      EXPECT_TRUE(std::isfinite(sd(b, q)));
      EXPECT_NEAR(sd(b, q), sd(reference, q), 1e-15);
    }
  EXPECT_NEAR(sd(reference, Vec3(1.1, 2.2, 3.2)), 0.3, 1e-12);
  EXPECT_TRUE(std::isnan(sd(reference, Vec3(NAN, 0, 0))));
  // moved, the object answers the same
  SurfaceDistance moved = std::move(b);
  EXPECT_NEAR(sd(moved, Vec3(0.9, 1.9, 2.9)), -0.1, 1e-12);
  // bad input
  EXPECT_THROW(SurfaceDistance({0, 0, 0, 1, 0}, {{0, 0, 0}}), std::invalid_argument);
  EXPECT_THROW(SurfaceDistance({0, 0, 0, 1, 0, 0, 0, 1, 0}, {{0, 1, 3}}), std::invalid_argument);
  EXPECT_THROW(SurfaceDistance({0, 0, 0, 1, 0, 0, 2, 0, 0}, {{0, 1, 2}}), std::invalid_argument); // no area
  EXPECT_THROW(SurfaceDistance({0, 0, NAN, 1, 0, 0, 0, 1, 0}, {{0, 1, 2}}), std::invalid_argument);
  EXPECT_THROW(geometry::wear_depth(reference, {1, 2}), std::invalid_argument);
}

TEST(SurfaceDistance, ConcurrentCallsAgreeWithOneThread)
{
  TriangleMesh knife = primitives::chisel_knife(0.4, 0.5, 0.03, 0.04);
  knife.refine(0.01);
  const SurfaceDistance s = soup(knife).distance();
  std::mt19937          rng(3);
  std::uniform_real_distribution<double> x(-0.25, 0.25), y(-0.03, 0.03), z(-0.02, 0.52);
  std::vector<double> points;
  for (int i = 0; i < 20000; ++i)
    points.insert(points.end(), {x(rng), y(rng), z(rng)});
  const std::vector<double> serial = geometry::wear_depth(s, points);
  std::vector<double>       threaded(serial.size());
  std::vector<std::thread>  threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (std::size_t i = t; i < threaded.size(); i += 4)
        threaded[i] = -s.signed_distance(points.data() + 3 * i);
    });
  for (auto &t : threads)
    t.join();
  EXPECT_EQ(threaded, serial);
}
