// Mesh motion in parallel (run under `mpirun -np 2`): the knife on a parallel::shared
// triangulation partitioned by METIS gives the same vertex displacements as the serial solve
// on one process, and each process assembles only its own cells.
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/mesh_motion.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_output.h>

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/shared_tria.h>
#include <deal.II/grid/grid_in.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace dealii;
using namespace abrade::fem;

namespace
{
  class Wear : public Function<3>
  {
  public:
    Wear() : Function<3>(3) {}
    double value(const Point<3> &p, unsigned c) const override
    {
      return c == 2 ? 0.008 * std::max(0.0, 1 - p[2] / 0.1) : c == 1 ? 0.002 * std::sin(10 * p[0]) : 0.0;
    }
  };
} // namespace

TEST(MeshMotionMpi, PartitionedSolveMatchesSerial)
{
  const unsigned n_ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
  const std::string msh = (std::filesystem::temp_directory_path() / "abrade_knife_mpi.msh").string();
  ParametricKnife     k;
  const Wear        wear;
  Functions::ZeroFunction<3> zero(3);
  const std::map<types::boundary_id, const Function<3> *> bc = {{wearable_boundary, &wear},
                                                                {clamped_boundary, &zero}};

  parallel::shared::Triangulation<3> shared(MPI_COMM_WORLD, Triangulation<3>::none, false,
                                            parallel::shared::Triangulation<3>::partition_metis);
  k.mesh(shared, 0.008, msh); // fine enough for interior nodes in the 30 mm plate
  unsigned owned = 0;
  for (const auto &cell : shared.active_cell_iterators())
    owned += cell->is_locally_owned();
  if (n_ranks > 1)
    EXPECT_LT(owned, shared.n_active_cells());
  EXPECT_EQ(Utilities::MPI::sum(owned, MPI_COMM_WORLD), shared.n_active_cells());
  MeshMotion parallel_motion(shared, {1, 1.0, 1e-12});
  parallel_motion.solve(bc);
  const auto d_parallel = parallel_motion.vertex_displacements();

  // the same problem on this process alone
  Triangulation<3> serial;
  GridIn<3>        in;
  in.attach_triangulation(serial);
  std::ifstream file(msh);
  in.read_msh(file);
  MeshMotion serial_motion(serial, {1, 1.0, 1e-12});
  serial_motion.solve(bc);
  const auto d_serial = serial_motion.vertex_displacements();
  EXPECT_GT(parallel_motion.last_iterations(), 0u); // a real solve, not only boundary values
  EXPECT_GT(serial_motion.last_iterations(), 0u);

  ASSERT_EQ(d_parallel.size(), d_serial.size());
  double diff = 0, scale = 0;
  for (std::size_t v = 0; v < d_serial.size(); ++v)
    diff = std::max(diff, (d_parallel[v] - d_serial[v]).norm()), scale = std::max(scale, d_serial[v].norm());
  EXPECT_LT(diff, 1e-9 * scale);
  move_vertices(shared, d_parallel);
  EXPECT_EQ(mesh_quality(shared).n_inverted, 0u);
  if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0)
    std::printf("%u ranks: %u of %u cells on rank 0, CG %u (parallel) / %u (serial) iterations, max difference "
                "to serial %.2e m (displacements up to %.2e m)\n",
                n_ranks, owned, shared.n_active_cells(), parallel_motion.last_iterations(),
                serial_motion.last_iterations(), diff, scale);
}

int main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
