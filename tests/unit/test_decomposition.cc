// The DEM's domain decomposition under MPI (run with mpirun -np 3 and -np 6): recursive
// coordinate bisection balances the particles, tiles space and tells each box its neighbours,
// and a distributed simulation (ghosts and migrating particles exchanged among neighbouring
// boxes only, contact histories moving between ranks, wall loads summed over ranks) follows the
// same trajectory as the same simulation run serially on each rank.
#include "dem_test_helpers.h"

#include <abrade/dem/decomposition.h>
#include <abrade/dem/generation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <random>

using namespace abrade;
using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material pellet = Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, true);
  const Material steel  = Material::from_shear_modulus("steel", 7e10, 0.3, 7800, true);

  /// A squeezed gas of 400 spheres in a closed box, with gravity and rotation: contacts, wall
  /// contacts and particles crossing the domain boundaries.
  Simulation squeezed_gas(bool distribute)
  {
    Settings s   = quiet_settings(5e-5, true);
    s.distribute = distribute;
    Simulation sim(s);
    const int  m = sim.add_material(pellet), w = sim.add_material(steel);
    sim.set_interaction(m, m, {0.6, 0.5, 0.05});
    sim.set_interaction(m, w, {0.5, 0.4, 0.05});
    Wall box;
    box.name     = "box";
    box.material = w;
    box.mesh     = primitives::box_container(Vec3::Constant(-0.05), Vec3::Constant(0.55), true);
    sim.add_wall(box);
    FillRegion f;
    f.box_min = Vec3::Zero(), f.box_max = Vec3(0.5, 0.5, 0.5);
    f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.02, f.sizes.max = 0.03;
    f.count = 400, f.seed = 7;
    fill_region(sim, f);
    std::mt19937_64                        rng(7);
    std::uniform_real_distribution<double> u(-1, 1);
    auto                                  &P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      {
        P.vx[i] = u(rng) - 6 * (P.x[i] - 0.25), P.vy[i] = u(rng) - 6 * (P.y[i] - 0.25);
        P.vz[i] = u(rng) - 6 * (P.z[i] - 0.25);
      }
    sim.setup();
    return sim;
  }
} // namespace

TEST(Decomposition, BalancesAndTilesSpace)
{
  const Parallel ranks = Parallel::world();
  // every rank holds a different, skewed cloud
  std::mt19937_64                        rng(11 + ranks.rank());
  std::exponential_distribution<double>  e(3.0);
  std::uniform_real_distribution<double> u(0, 1);
  const std::size_t                      n = 1000 + 700 * ranks.rank();
  std::vector<double>                    x(n), y(n), z(n);
  for (std::size_t i = 0; i < n; ++i)
    x[i] = 2 * e(rng), y[i] = u(rng), z[i] = 0.3 * u(rng) + ranks.rank();
  Decomposition d;
  d.balance(ranks, x.data(), y.data(), z.data(), n);
  ASSERT_EQ(d.n_domains(), ranks.size());
  std::vector<double> owned(ranks.size(), 0.0);
  for (std::size_t i = 0; i < n; ++i)
    {
      const int r = d.owner(x[i], y[i], z[i]);
      owned[r] += 1;
      EXPECT_EQ(d.box(r).distance(x[i], y[i], z[i]), 0.0);
      for (int q = 0; q < ranks.size(); ++q) // boxes do not overlap (inside one only)
        {
          if (q != r)
            {
              EXPECT_TRUE(d.box(q).distance(x[i], y[i], z[i]) > 0 || d.box(q).depth(x[i], y[i], z[i]) == 0);
            }
        }
    }
  ranks.sum(owned);
  const double total = ranks.sum(double(n));
  for (int r = 0; r < ranks.size(); ++r)
    EXPECT_NEAR(owned[r], total / ranks.size(), 1.0) << "rank " << r;

  // Neighbours (who exchanges ghosts and migrants): symmetric, and they include every rank whose
  // box is within the reach of a point of this rank's box (checked at this rank's particles).
  const double reach = 0.05;
  for (int r = 0; r < ranks.size(); ++r)
    for (int q : d.neighbours(r, reach))
      {
        const auto back = d.neighbours(q, reach);
        EXPECT_TRUE(std::find(back.begin(), back.end(), r) != back.end()) << r << " lists " << q;
      }
  const std::vector<int> mine = d.neighbours(ranks.rank(), reach);
  for (std::size_t i = 0; i < n; ++i)
    if (d.owner(x[i], y[i], z[i]) == ranks.rank())
      {
        std::vector<int> near;
        d.ranks_near(x[i], y[i], z[i], reach, ranks.rank(), near);
        for (int q : near)
          EXPECT_TRUE(std::find(mine.begin(), mine.end(), q) != mine.end()) << "rank " << q << " not a neighbour";
      }
  if (ranks.size() >= 6) // then some boxes are far apart: the exchanges skip them
    {
      std::size_t fewest = std::size_t(ranks.size());
      for (int r = 0; r < ranks.size(); ++r)
        fewest = std::min(fewest, d.neighbours(r, reach).size());
      EXPECT_LT(fewest, std::size_t(ranks.size() - 1));
    }
}

TEST(Decomposition, DistributedRunFollowsTheSerialTrajectory)
{
  Simulation distributed = squeezed_gas(true);
  Simulation serial      = squeezed_gas(false); // the whole gas on every rank
  ASSERT_EQ(distributed.n_particles(), 400u);
  const int steps = 1500;
  for (int s = 0; s < steps; ++s)
    distributed.step(), serial.step();

  EXPECT_EQ(distributed.n_particles(), 400u); // nothing lost
  EXPECT_NEAR(distributed.kinetic_energy(), serial.kinetic_energy(), 1e-9 * serial.kinetic_energy());
  EXPECT_EQ(distributed.n_particle_contacts(), serial.n_particle_contacts());
  EXPECT_GT(serial.n_particle_contacts(), 50u); // a dense, colliding gas (97 contacts after 1,500 steps)
  // the box's load: summed over the ranks every step
  for (int d = 0; d < 3; ++d)
    EXPECT_NEAR(distributed.wall(0).force[d], serial.wall(0).force[d], 1e-8 * serial.wall(0).force.norm());
  if (distributed.parallel().distributed())
    {
      long migrated = distributed.parallel().sum(distributed.statistics().migrated);
      EXPECT_GT(migrated, 400 / 2); // the initial spread, then particles crossing boundaries
      // after the first cuts, particles cross to neighbouring boxes only (no all-to-all)
      const auto &st = distributed.statistics();
      EXPECT_GT(st.nearby_migrations, 0);
      EXPECT_GE(st.nearby_migrations + st.rebalances, st.rebuilds - 1);
    }
  const std::size_t   contacts = distributed.n_particle_contacts(); // collective
  const ParticleStore all      = distributed.gather_particles();
  if (distributed.parallel().rank() == 0)
    {
      ASSERT_EQ(all.size(), 400u);
      const ParticleStore &ref = serial.particles();
      double               worst_x = 0, worst_w = 0;
      for (std::size_t i = 0; i < all.size(); ++i)
        {
          const std::size_t k = index_of(serial, all.id[i]);
          ASSERT_LT(k, ref.size());
          worst_x = std::max({worst_x, std::abs(all.x[i] - ref.x[k]), std::abs(all.y[i] - ref.y[k]),
                              std::abs(all.z[i] - ref.z[k])});
          worst_w = std::max({worst_w, std::abs(all.wx[i] - ref.wx[k]), std::abs(all.wy[i] - ref.wy[k]),
                              std::abs(all.wz[i] - ref.wz[k])});
        }
      // round-off only (sums in another order): a lost ghost or contact history moves
      // particles by millimetres
      std::cout << "largest differences from the serial run: position " << worst_x << " m, angular velocity "
                << worst_w << " rad/s; " << contacts << " contacts" << std::endl;
      EXPECT_LT(worst_x, 1e-9) << "largest position difference [m]";
      EXPECT_LT(worst_w, 1e-6) << "largest angular velocity difference [rad/s]";
    }
}

int main(int argc, char **argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  const int rank = Parallel::world().rank();
  if (rank != 0) // one report
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
      ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
