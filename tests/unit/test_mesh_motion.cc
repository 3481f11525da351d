// The mesh-motion solver (fem/mesh_motion.h) by the method of manufactured solutions
// (shared/reference/verification.md): Q1 converges at rate 2 in L2 and 1 in H1, Q2 at 3 and 2,
// within 0.1 on the last two refinements; P1 on tetrahedra at 2 and 1; a linear displacement is
// reproduced to round-off.
#include <abrade/fem/mesh_motion.h>

#include <deal.II/base/mpi.h>
#include <deal.II/grid/grid_generator.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace dealii;
using abrade::fem::MeshMotion;

namespace
{
  /// u_c = (c + 1) sin(pi x) sin(pi y) sin(pi z) + linear part, -laplace u_c = 3 pi^2 (c+1) s(x)
  class Manufactured : public Function<3>
  {
  public:
    Manufactured() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override
    {
      return (c + 1) * std::sin(M_PI * p[0]) * std::sin(M_PI * p[1]) * std::sin(M_PI * p[2]) + 0.1 * p[c];
    }
    Tensor<1, 3> gradient(const Point<3> &p, unsigned c) const override
    {
      const double sx = std::sin(M_PI * p[0]), sy = std::sin(M_PI * p[1]), sz = std::sin(M_PI * p[2]);
      const double cx = std::cos(M_PI * p[0]), cy = std::cos(M_PI * p[1]), cz = std::cos(M_PI * p[2]);
      Tensor<1, 3> g;
      g[0] = (c + 1) * M_PI * cx * sy * sz, g[1] = (c + 1) * M_PI * sx * cy * sz, g[2] = (c + 1) * M_PI * sx * sy * cz;
      g[c] += 0.1;
      return g;
    }
  };
  class Source : public Function<3>
  {
  public:
    Source() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override
    {
      return 3 * M_PI * M_PI * (c + 1) * std::sin(M_PI * p[0]) * std::sin(M_PI * p[1]) * std::sin(M_PI * p[2]);
    }
  };
  class Linear : public Function<3>
  {
  public:
    Linear() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override { return 0.01 * (c + 1) * p[0] - 0.02 * p[1] + 0.03 * p[2] + 0.001 * c; }
  };

  /// Errors on the unit cube at @p levels refinements (hex) or subdivisions (tets).
  std::vector<std::pair<double, double>> errors(unsigned degree, bool simplex, const std::vector<unsigned> &levels)
  {
    std::vector<std::pair<double, double>> out;
    const Manufactured exact;
    const Source       source;
    for (unsigned l : levels)
      {
        Triangulation<3> tria;
        if (simplex)
          GridGenerator::subdivided_hyper_rectangle_with_simplices(tria, {l, l, l}, Point<3>(), Point<3>(1, 1, 1));
        else
          {
            GridGenerator::hyper_cube(tria);
            tria.refine_global(l);
          }
        MeshMotion motion(tria, {degree, 0.0, 1e-13});
        motion.solve({{0, &exact}}, &source);
        out.push_back(motion.errors(exact));
      }
    return out;
  }

  void expect_rates(const std::vector<std::pair<double, double>> &e, double l2_rate, double h1_rate)
  {
    for (std::size_t k = 1; k < e.size(); ++k)
      {
        const double r0 = std::log2(e[k - 1].first / e[k].first), r1 = std::log2(e[k - 1].second / e[k].second);
        std::printf("  L2 %.3e rate %.2f   H1 %.3e rate %.2f\n", e[k].first, r0, e[k].second, r1);
        if (k + 2 >= e.size()) // the last two refinements
          {
            EXPECT_NEAR(r0, l2_rate, 0.1);
            EXPECT_NEAR(r1, h1_rate, 0.1);
          }
      }
  }
} // namespace

TEST(MeshMotion, Q1ConvergesAtRates2And1)
{
  expect_rates(errors(1, false, {2, 3, 4, 5}), 2, 1);
}

TEST(MeshMotion, Q2ConvergesAtRates3And2)
{
  expect_rates(errors(2, false, {1, 2, 3, 4}), 3, 2);
}

TEST(MeshMotion, P1OnTetrahedraConvergesAtRates2And1)
{
  expect_rates(errors(1, true, {4, 8, 16, 32}), 2, 1);
}

TEST(MeshMotion, LinearDisplacementIsExact)
{
  for (bool simplex : {false, true})
    for (double stiffening : {0.0, 1.0})
      {
        Triangulation<3> tria;
        if (simplex)
          GridGenerator::subdivided_hyper_rectangle_with_simplices(tria, {3, 2, 4}, Point<3>(), Point<3>(0.4, 0.03, 0.5));
        else
          GridGenerator::subdivided_hyper_rectangle(tria, {6, 2, 5}, Point<3>(), Point<3>(0.4, 0.03, 0.5));
        const Linear linear;
        MeshMotion   motion(tria, {1, stiffening, 1e-14});
        motion.solve({{0, &linear}});
        EXPECT_LT(motion.errors(linear).first, 1e-12) << (simplex ? "tets" : "hexes") << " stiffening " << stiffening;
        // vertex displacements are the field at the vertices
        const auto d = motion.vertex_displacements();
        for (unsigned v = 0; v < tria.n_vertices(); ++v)
          for (unsigned c = 0; c < 3; ++c)
            EXPECT_NEAR(d[v][c], linear.value(tria.get_vertices()[v], c), 1e-12);
      }
}

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1); // PETSc needs MPI
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
