// The DEM engine's machinery: neighbour lists with a Verlet skin and the contact history that
// must survive their rebuilds, thread independence, momentum conservation, error detection (lost
// particle, NaN, excessive overlap), the time-step check, particle generation and bed files.
#include "dem_test_helpers.h"

#include <abrade/common/error.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/thread_governor.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <numeric>
#include <random>

using namespace abrade;
using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material pellet = Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, true);

  /// A dense gas of particles with random velocities, no gravity, no walls.
  Simulation gas(int threads, double skin, int n = 400, std::uint64_t seed = 3, int shares = 0)
  {
    Settings s = quiet_settings(5e-5);
    s.threads  = threads;
    s.shares   = shares;
    s.skin     = skin;
    Simulation sim(s);
    const int  m = sim.add_material(pellet);
    sim.set_interaction(m, m, {0.6, 0.5, 0.05});
    FillRegion f;
    f.box_min = Vec3::Zero(), f.box_max = Vec3(0.5, 0.5, 0.5);
    f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.02, f.sizes.max = 0.03;
    f.count = n, f.seed = seed;
    fill_region(sim, f);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    auto &P = sim.particles();
    for (std::size_t i = 0; i < P.size(); ++i)
      P.vx[i] = u(rng), P.vy[i] = u(rng), P.vz[i] = u(rng);
    // squeeze the gas so that many contacts form
    for (std::size_t i = 0; i < P.size(); ++i)
      P.vx[i] -= 6 * (P.x[i] - 0.25), P.vy[i] -= 6 * (P.y[i] - 0.25), P.vz[i] -= 6 * (P.z[i] - 0.25);
    sim.setup();
    return sim;
  }

  std::vector<double> state_by_id(const Simulation &sim)
  {
    const auto         &P = sim.particles();
    std::vector<double> out(6 * P.size());
    for (std::size_t i = 0; i < P.size(); ++i)
      {
        const std::size_t k = 6 * P.id[i];
        out[k] = P.x[i], out[k + 1] = P.y[i], out[k + 2] = P.z[i];
        out[k + 3] = P.wx[i], out[k + 4] = P.wy[i], out[k + 5] = P.wz[i];
      }
    return out;
  }
} // namespace

// Also with more shares of the pair loop than two: a share other than the first adds into its
// own buffer over the particles its pairs reach (Impl::share_spans), and with three or more a
// share's pairs reach into the next share's rows: a span that misses them loses forces.
class EngineShares : public ::testing::TestWithParam<int>
{};
INSTANTIATE_TEST_SUITE_P(Engine, EngineShares, ::testing::Values(2, 5));

TEST_P(EngineShares, MomentumIsConservedWithoutWallsAndGravity)
{
  Simulation  sim = gas(2, 0, 400, 3, GetParam());
  ASSERT_EQ(sim.shares(), GetParam());
  const auto &P   = sim.particles();
  auto momentum = [&] {
    Vec3 p = Vec3::Zero();
    for (std::size_t i = 0; i < P.size(); ++i)
      p += P.mass[i] * Vec3(P.vx[i], P.vy[i], P.vz[i]);
    return p;
  };
  const Vec3  p0           = momentum();
  std::size_t max_contacts = 0;
  sim.run_phase("gas", 0.05, [&](const Simulation &s) { max_contacts = std::max(max_contacts, s.n_particle_contacts()); });
  EXPECT_GT(max_contacts, 50u);
  EXPECT_GT(sim.statistics().rebuilds, 5);
  EXPECT_LT((momentum() - p0).norm(), 1e-10 * P.size());
}

TEST(Engine, ResultsDoNotDependOnThreadsOrSkin)
{
  // Threads and skins change the order of summation only: after 400 steps of a dense,
  // frictional, rotating gas the states agree to round-off.
  Simulation a = gas(1, 0.0005), b = gas(2, 0.004), c = gas(2, 1e-7);
  for (auto *s : {&a, &b, &c})
    s->run_phase("gas", 0.02);
  EXPECT_GT(c.statistics().rebuilds, 350); // rebuilt (and history carried over) nearly every step
  const auto sa = state_by_id(a), sb = state_by_id(b), sc = state_by_id(c);
  double     d_ab = 0, d_ac = 0;
  for (std::size_t k = 0; k < sa.size(); ++k)
    d_ab = std::max(d_ab, std::abs(sa[k] - sb[k])), d_ac = std::max(d_ac, std::abs(sa[k] - sc[k]));
  EXPECT_LT(d_ab, 1e-8);
  EXPECT_LT(d_ac, 1e-8);
}

TEST(Engine, TheSameBitsWithAnyNumberOfThreadsWorking)
{
  // The work is cut into Settings::threads shares; how many threads work on them (the team the
  // governor picks on a busy machine) must not change a single bit: positions, spins, the
  // walls' loads and the per-triangle impulses the wear laws are built from. A gas squeezed
  // between a box of fine triangles and a plate pushed into it, rotating, frictional.
  auto run = [](int team) {
    Settings s = quiet_settings(5e-5, true);
    s.threads  = 3;
    Simulation sim(s);
    const int  m = sim.add_material(pellet);
    sim.set_interaction(m, m, {0.6, 0.5, 0.05});
    Wall box;
    box.name     = "box";
    box.mesh     = primitives::box_container(Vec3(-0.01, -0.01, 0), Vec3(0.51, 0.51, 0.6));
    box.mesh.refine(0.05);
    box.material = m;
    sim.add_wall(box);
    Wall plate   = floor_wall(m, 0.4, 0.04);
    plate.name   = "plate";
    plate.mesh.translate(Vec3(0.25, 0.25, 0.41));
    plate.motion.kind = WallMotion::Kind::prescribed;
    plate.motion.phases["push"].velocity = Vec3(0.3, 0, -1.0);
    sim.add_wall(plate);
    FillRegion f;
    f.box_min = Vec3::Zero(), f.box_max = Vec3(0.5, 0.5, 0.4);
    f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.02, f.sizes.max = 0.03;
    f.count = 300, f.seed = 4;
    fill_region(sim, f);
    sim.setup();
    sim.pin_thread_team(team);
    sim.run_phase("push", 0.1);
    std::vector<double> out = state_by_id(sim);
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        const Wall &wall = sim.wall(w);
        out.insert(out.end(), {wall.force[0], wall.force[1], wall.force[2], wall.torque[0], wall.torque[1],
                               wall.torque[2]});
        out.insert(out.end(), wall.normal_impulse.begin(), wall.normal_impulse.end());
        out.insert(out.end(), wall.tangential_impulse.begin(), wall.tangential_impulse.end());
      }
    return out;
  };
  const std::vector<double> three = run(3), two = run(2), one = run(1);
  ASSERT_EQ(three.size(), two.size());
  double impulse = 0;
  for (std::size_t k = 6 * 300; k < three.size(); ++k)
    impulse += std::abs(three[k]);
  EXPECT_GT(impulse, 1.0); // the walls were hit
  EXPECT_TRUE(one == three) << "one thread working on three shares differs from three threads";
  EXPECT_TRUE(two == three) << "two threads working on three shares differ from three threads";
}

TEST(Engine, ASimulationGoesOnWithTheGovernorOfTheOneBefore)
{
  // a lifetime run's cycles are short simulations, one after another: the next goes on with
  // the team the one before kept (Settings::governor), not with every thread again
  Settings s = quiet_settings(5e-5, true);
  s.threads  = 2;
  Simulation first(s);
  // a busy machine, made up: two threads take 2.5 ms a step, one 1 ms; the governor keeps one
  // thread, and is then in its next trial (two threads) when the simulation ends
  const auto governor = first.thread_governor();
  auto       step     = [&] { governor->record_step(governor->team() == 2 ? 2.5e-3 : 1e-3); };
  for (int k = 0; k < 2000 && governor->changes() == 0; ++k)
    step();
  ASSERT_EQ(governor->team(), 1) << "the made-up busy machine did not teach it one thread";
  for (int k = 0; k < 2000 && governor->team() == 1; ++k)
    step();
  ASSERT_EQ(governor->team(), 2) << "no trial of two threads";
  s.governor = governor;
  Simulation next(s);
  EXPECT_EQ(next.thread_governor(), governor);
  EXPECT_EQ(next.thread_governor()->team(), 1) << "the kept team, not the trial's";
  // a governor of another thread count, or for a simulation that does not adapt, is not taken
  s.threads = 3;
  Simulation other(s);
  EXPECT_NE(other.thread_governor(), governor);
  EXPECT_EQ(other.thread_governor()->team(), 3);
  s.threads = 2, s.adapt_threads = false;
  Simulation fixed(s);
  EXPECT_NE(fixed.thread_governor(), governor);
  EXPECT_EQ(fixed.thread_governor()->team(), 2);
}

TEST(Engine, TangentialHistorySurvivesRebuilds)
{
  // Two spheres pressed together and sheared slowly stick: the tangential force grows linearly
  // with the shear displacement, with or without a list rebuild every step.
  auto run = [](double skin) {
    Settings s = quiet_settings(1e-6);
    s.skin     = skin;
    Simulation sim(s);
    const int  m = sim.add_material(pellet);
    sim.set_interaction(m, m, {0.6, 0.5, 0.0});
    auto &P = sim.particles();
    P.add(0, 0, 0, 0, 0.0275, pellet.density, m);
    P.add(1, 0, 0, 0.054, 0.0275, pellet.density, m);
    P.inv_mass[0] = P.inv_mass[1] = 0; // kinematic: we drive them
    sim.setup();
    for (std::size_t i = 0; i < P.size(); ++i)
      if (P.id[i] == 1)
        P.vx[i] = 1e-3, P.inv_mass[i] = 0;
      else
        P.inv_mass[i] = 0;
    sim.run_phase("shear", 2e-4);
    const auto i = index_of(sim, 0);
    return Vec3(P.fx[i], P.fy[i], P.fz[i]);
  };
  const Vec3 with_lists = run(0.01), rebuilt = run(1e-12);
  EXPECT_GT(std::abs(with_lists[0]), 0);
  EXPECT_NEAR((rebuilt - with_lists).norm() / with_lists.norm(), 0, 1e-12);
}

TEST(Engine, LostParticleIsReportedWithIdAndStep)
{
  Settings s   = quiet_settings(1e-4);
  s.domain_min = Vec3::Constant(-1), s.domain_max = Vec3::Constant(1);
  Simulation sim(s);
  const int  m = sim.add_material(pellet);
  sim.particles().add(7, 0.9995, 0, 0, 0.01, 3700, m);
  sim.particles().add(8, 0, 0, 0, 0.01, 3700, m);
  sim.particles().vx[0] = 10;
  try
    {
      sim.run_phase("go", 0.01);
      FAIL() << "no error";
    }
  catch (const RunError &e)
    {
      EXPECT_NE(std::string(e.what()).find("particle left the domain: particle id 7 at step 1"), std::string::npos)
        << e.what();
    }

  // continue mode: warned once, removed, the rest goes on
  s.stop_on_error = false;
  Simulation keep(s);
  keep.add_material(pellet);
  keep.particles().add(7, 0.9995, 0, 0, 0.01, 3700, 0);
  keep.particles().add(8, 0, 0, 0, 0.01, 3700, 0);
  keep.particles().vx[0] = 10;
  keep.run_phase("go", 0.01);
  EXPECT_EQ(keep.particles().size(), 1u);
  EXPECT_EQ(keep.particles().id[0], 8);
  int lost_warnings = 0;
  for (const auto &w : keep.take_warnings())
    if (w.find("particle left the domain: particle id 7") != std::string::npos)
      ++lost_warnings;
  EXPECT_EQ(lost_warnings, 1);
}

TEST(Engine, NaNStopsTheRun)
{
  Simulation sim(quiet_settings(1e-4));
  const int  m = sim.add_material(pellet);
  sim.particles().add(3, 0, 0, 0, 0.01, 3700, m);
  sim.setup();
  sim.particles().vx[0] = std::nan("");
  EXPECT_THROW(sim.step(), RunError);
}

TEST(Engine, ExcessiveOverlapIsReported)
{
  Settings s             = quiet_settings(1e-4);
  s.max_overlap_fraction = 0.05;
  Simulation sim(s);
  const int  m = sim.add_material(pellet);
  sim.particles().add(1, 0, 0, 0, 0.01, 3700, m);
  sim.particles().add(2, 0.018, 0, 0, 0.01, 3700, m); // 20 % overlap
  try
    {
      sim.setup();
      sim.step();
      FAIL() << "no error";
    }
  catch (const RunError &e)
    {
      EXPECT_NE(std::string(e.what()).find("particle id 1 with particle id 2"), std::string::npos) << e.what();
    }
}

TEST(Engine, RayleighTimeStepAndWarning)
{
  // seed material: R = 27.5 mm -> T_R = 5.73e-4 s, 0.2 T_R = 1.146e-4 s (physics.md)
  Settings   s;
  Simulation sim(s);
  const int  m = sim.add_material(Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, false));
  sim.particles().add(0, 0, 0, 0, 0.0275, 3700, m);
  sim.setup();
  EXPECT_NEAR(sim.rayleigh_time_step(), 5.73e-4, 0.005e-4);
  EXPECT_NEAR(sim.dt(), 1.146e-4, 0.001e-4);
  EXPECT_TRUE(sim.take_warnings().empty());

  s.time_step = 5e-4;
  Simulation big(s);
  big.add_material(Material::from_shear_modulus("pellet", 1e8, 0.25, 3700, false));
  big.particles().add(0, 0, 0, 0, 0.0275, 3700, 0);
  big.setup();
  const auto w = big.take_warnings();
  ASSERT_FALSE(w.empty());
  EXPECT_NE(w[0].find("Hertz contact time"), std::string::npos);
}

TEST(Generation, ReproducibleFromSeedAndWithoutOverlap)
{
  auto fill = [](std::uint64_t seed, SizeDistribution::Kind kind) {
    Simulation sim(Settings{});
    sim.add_material(pellet);
    FillRegion f;
    f.box_min = Vec3::Zero(), f.box_max = Vec3(1, 1, 1);
    f.sizes.kind = kind, f.sizes.radius = 0.03, f.sizes.min = 0.02, f.sizes.max = 0.04, f.sizes.std = 0.005;
    f.solid_fraction = 0.2, f.seed = seed;
    fill_region(sim, f);
    return sim.particles();
  };
  for (auto kind : {SizeDistribution::Kind::constant, SizeDistribution::Kind::uniform, SizeDistribution::Kind::normal})
    {
      const auto a = fill(5, kind), b = fill(5, kind), c = fill(6, kind);
      ASSERT_EQ(a.size(), b.size());
      EXPECT_EQ(a.x, b.x);
      EXPECT_EQ(a.radius, b.radius);
      EXPECT_NE(a.x, c.x);
      double volume = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        {
          volume += 4.0 / 3.0 * M_PI * std::pow(a.radius[i], 3);
          EXPECT_GE(a.radius[i], kind == SizeDistribution::Kind::constant ? 0.03 : 0.02);
          EXPECT_LE(a.radius[i], kind == SizeDistribution::Kind::constant ? 0.03 : 0.04);
          EXPECT_GE(a.x[i] - a.radius[i], 0);
          EXPECT_LE(a.z[i] + a.radius[i], 1);
          for (std::size_t j = i + 1; j < a.size(); ++j)
            {
              const double d = std::hypot(a.x[i] - a.x[j], a.y[i] - a.y[j], a.z[i] - a.z[j]);
              ASSERT_GE(d, a.radius[i] + a.radius[j]);
            }
        }
      EXPECT_NEAR(volume, 0.2, 0.02);
    }
}

TEST(Generation, SweepsTheFreeSpaceWhenRandomDrawsStall)
{
  // The knife-bed fill box, 27.5 mm pellets: random draws alone stall at 11,193 (LIGGGHTS'
  // insert/pack places 10,496 there); the sweep of the free space places 12,000, none
  // overlapping, all inside the box, the same ones from the same seed.
  auto fill = [](std::uint64_t seed) {
    Simulation sim(quiet_settings(1e-4));
    sim.add_material(pellet);
    FillRegion f;
    f.box_min = Vec3(-0.97, -0.97, 0.03), f.box_max = Vec3(0.97, 0.97, 0.85);
    f.sizes.radius = 0.0275, f.count = 12000, f.seed = seed;
    EXPECT_EQ(fill_region(sim, f), 12000);
    return sim;
  };
  const Simulation a = fill(1), b = fill(1);
  const auto      &P = a.particles();
  ASSERT_EQ(P.size(), 12000u);
  EXPECT_EQ(P.x, b.particles().x);
  EXPECT_EQ(P.z, b.particles().z);
  double worst = 0; // the largest overlap, by brute force over neighbours in z order
  std::vector<std::size_t> order(P.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return P.z[i] < P.z[j]; });
  for (std::size_t a_ = 0; a_ < order.size(); ++a_)
    for (std::size_t b_ = a_ + 1; b_ < order.size() && P.z[order[b_]] - P.z[order[a_]] < 0.055; ++b_)
      {
        const std::size_t i = order[a_], j = order[b_];
        const double d = std::hypot(P.x[i] - P.x[j], P.y[i] - P.y[j], P.z[i] - P.z[j]);
        worst = std::max(worst, 0.055 - d);
      }
  EXPECT_LE(worst, 0.0);
  for (std::size_t i = 0; i < P.size(); ++i)
    ASSERT_TRUE(std::abs(P.x[i]) <= 0.97 - 0.0275 && std::abs(P.y[i]) <= 0.97 - 0.0275 && P.z[i] >= 0.03 + 0.0275 &&
                P.z[i] <= 0.85 - 0.0275);
}

TEST(Generation, TooManyParticlesIsAClearError)
{
  Simulation sim(Settings{});
  sim.add_material(pellet);
  FillRegion f;
  f.box_min = Vec3::Zero(), f.box_max = Vec3(0.2, 0.2, 0.2);
  f.count   = 1000;
  EXPECT_THROW(fill_region(sim, f), InputError);
}

TEST(Generation, FillInsideAMeshAndAvoidWalls)
{
  Simulation sim(Settings{});
  sim.add_material(pellet);
  const TriangleMesh cube = primitives::box_container(Vec3::Zero(), Vec3(0.5, 0.5, 0.5), true);
  FillRegion         f;
  f.box_min = Vec3::Constant(-1), f.box_max = Vec3::Constant(1);
  f.inside  = &cube;
  f.count   = 50;
  f.sizes.radius = 0.02;
  fill_region(sim, f);
  const auto &P = sim.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    {
      EXPECT_TRUE(inside_mesh(cube, Vec3(P.x[i], P.y[i], P.z[i])));
      EXPECT_GT(P.x[i], 0);
      EXPECT_LT(P.z[i], 0.5);
    }
}

TEST(Bed, SaveAndLoadRoundTrip)
{
  Simulation a = gas(1, 0, 50);
  a.run_phase("gas", 0.001);
  const std::string path = (std::filesystem::temp_directory_path() / "abrade_test.bed").string();
  save_bed(a, path);
  Simulation b(quiet_settings(5e-5));
  b.add_material(pellet);
  load_bed(b, path);
  EXPECT_EQ(b.particles().x, a.particles().x);
  EXPECT_EQ(b.particles().vz, a.particles().vz);
  EXPECT_EQ(b.particles().wy, a.particles().wy);
  EXPECT_EQ(b.particles().id, a.particles().id);
  EXPECT_EQ(b.particles().mass, a.particles().mass);
  // corruption is named, never read as particles: a changed byte (a radius, a count), a cut
  // file, a file of other content
  std::ifstream     in(path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  auto refused = [&](std::string changed, const std::string &why) {
    std::ofstream(path, std::ios::binary) << changed;
    try
      {
        load_bed(b, path);
        ADD_FAILURE() << "a corrupt bed was read (" << why << ")";
      }
    catch (const InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      }
  };
  std::string changed = bytes;
  changed[24 + 9 * 8 * a.particles().size() + 3] ^= 0x10; // the first particle's radius
  refused(changed, "checksum does not match");
  changed = bytes;
  changed[8] ^= 0x40; // the count
  refused(changed, "it announces");
  refused(bytes.substr(0, bytes.size() - 100), "it announces");
  refused("not a bed", "not an abrade bed file");
  refused("ABRBED01" + bytes.substr(8), "older abrade");
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_NO_THROW(load_bed(b, path));
  // a bed whose checksum holds but whose particles do not (a state that blew up)
  a.particles().vx[0] = std::nan("");
  save_bed(a, path);
  refused(std::string(std::istreambuf_iterator<char>(std::ifstream(path, std::ios::binary).rdbuf()), {}),
          "not a finite number");
  std::filesystem::remove(path);
}

TEST(Bed, ImportFromATableAndADumpGivesTheSameBed)
{
  // The same particles written by hand (not by abrade) as a CSV table with a diameter column
  // and as a LIGGGHTS dump of two snapshots (the last is read): both imports give back exactly
  // the particles of the original simulation, masses from the material's density.
  Simulation a = gas(1, 0, 60);
  a.run_phase("gas", 0.001);
  const auto       &P   = a.particles();
  const std::string dir = std::filesystem::temp_directory_path().string();
  {
    std::ofstream csv(dir + "/abrade_import.csv");
    csv << std::setprecision(17) << "# written by the test\nVX, Diameter, z, y, x, ID, colour\n";
    for (std::size_t i = 0; i < P.size(); ++i)
      csv << P.vx[i] << "," << 2 * P.radius[i] << "," << P.z[i] << "," << P.y[i] << "," << P.x[i] << "," << P.id[i]
          << ",red\n";
    std::ofstream dump(dir + "/abrade_import.dump");
    dump << std::setprecision(17);
    for (int snapshot = 0; snapshot < 2; ++snapshot)
      {
        dump << "ITEM: TIMESTEP\n" << 1000 * snapshot << "\nITEM: NUMBER OF ATOMS\n" << P.size()
             << "\nITEM: BOX BOUNDS ff ff ff\n-1 1\n-1 1\n-1 1\nITEM: ATOMS id type x y z radius vx vy vz\n";
        for (std::size_t i = 0; i < P.size(); ++i)
          dump << P.id[i] << " 1 " << P.x[i] + (snapshot == 0 ? 1 : 0) << " " << P.y[i] << " " << P.z[i] << " "
               << P.radius[i] << " " << P.vx[i] << " " << P.vy[i] << " " << P.vz[i] << "\n";
      }
  }
  for (const std::string file : {"abrade_import.csv", "abrade_import.dump"})
    {
      Simulation b(quiet_settings(5e-5));
      b.add_material(pellet);
      const ImportedBed r = import_bed(b, dir + "/" + file, 0);
      EXPECT_EQ(r.particles, P.size()) << file;
      EXPECT_EQ(r.timestep, file.find("dump") != std::string::npos ? 1000 : -1);
      const auto &Q = b.particles();
      ASSERT_EQ(Q.size(), P.size());
      for (std::size_t i = 0; i < P.size(); ++i)
        {
          const std::size_t k = index_of(b, P.id[i]);
          ASSERT_LT(k, Q.size()) << file;
          EXPECT_EQ(Q.x[k], P.x[i]) << file;
          EXPECT_EQ(Q.z[k], P.z[i]) << file;
          EXPECT_EQ(Q.radius[k], P.radius[i]) << file;
          EXPECT_EQ(Q.vx[k], P.vx[i]) << file;
          EXPECT_DOUBLE_EQ(Q.mass[k], P.mass[i]) << file;
        }
    }
}

TEST(Bed, ImportRefusesWhatItCannotRead)
{
  const std::string dir = std::filesystem::temp_directory_path().string();
  auto refused = [&](const std::string &name, const std::string &text, const std::string &why) {
    std::ofstream(dir + "/" + name) << text;
    Simulation b(quiet_settings(5e-5));
    b.add_material(pellet);
    try
      {
        import_bed(b, dir + "/" + name, 0);
        ADD_FAILURE() << "imported " << name << " (" << why << ")";
      }
    catch (const InputError &e)
      {
        EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
      }
  };
  refused("no_radius.csv", "x,y,z\n0,0,0\n", "neither a 'radius' nor a 'diameter'");
  refused("no_y.csv", "x,z,radius\n0,0,0.01\n", "no column 'y'");
  refused("word.csv", "x,y,z,radius\n0,0,0,0.01\n0,zero,0,0.01\n", "word.csv:3");
  refused("millimetres.csv", "x,y,z,radius\n0,0,0,27.5\n", "millimetres");
  refused("twice.csv", "id,x,y,z,radius\n1,0,0,0,0.01\n1,0.1,0,0,0.01\n", "id 1 comes twice");
  refused("half_id.csv", "id,x,y,z,radius\n1.5,0,0,0,0.01\n", "not a whole number");
  refused("far.csv", "x,y,z,radius\n0,0,5000,0.01\n", "outside Simulation/Domain");
  refused("empty.csv", "x,y,z,radius\n", "no particles");
  const std::string head = "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n";
  refused("cut.dump", head + "ITEM: ATOMS id x y z radius\n1 0 0 0 0.01\n", "cut short");
  refused("scaled.dump", head + "ITEM: ATOMS id xs ys zs radius\n1 0 0 0 0.01\n2 1 1 1 0.01\n", "scaled coordinates");
  refused("short_row.dump", head + "ITEM: ATOMS id x y z radius\n1 0 0 0 0.01\n2 1 1 0.01\n", "short_row.dump:11");
  refused("nan.dump", head + "ITEM: ATOMS id x y z radius\n1 0 0 0 0.01\n2 1 nan 1 0.01\n", "not a finite number");
  refused("other.dump", "hello\n", "ITEM: TIMESTEP");
  // a count the file cannot hold is refused before it is allocated (2e10 atoms: 2 TB)
  refused("huge.dump", "ITEM: TIMESTEP\n5\nITEM: NUMBER OF ATOMS\n20000000000\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
                       "ITEM: ATOMS id x y z radius\n1 0 0 0 0.01\n", "the rest of the file holds at most");
  refused("coincident.csv", "x,y,z,radius\n0,0,0,0.01\n0.5,0,0,0.01\n0,0,0,0.01\n", "centres on one point");
  refused("both.csv", "x,y,z,radius,diameter\n0,0,0,0.01,0.02\n", "both a 'radius' and a 'diameter'");
  refused("case.csv", "x,y,z,X,radius\n0,0,0,0,0.01\n", "comes twice");
}

TEST(Bed, ImportReadsWhatLammpsAndSpreadsheetsWrite)
{
  // a LAMMPS dump with units and time items (dump_modify units yes time yes), a byte order
  // mark, CRLF line ends; a CSV with a byte order mark before a comment line
  const std::string dir = std::filesystem::temp_directory_path().string();
  std::ofstream(dir + "/abrade_lammps.dump")
    << "\xEF\xBB\xBFITEM: UNITS\r\nsi\r\nITEM: TIME\r\n0.5\r\nITEM: TIMESTEP\r\n10000000000000\r\n"
       "ITEM: NUMBER OF ATOMS\r\n2\r\nITEM: BOX BOUNDS ff ff ff\r\n0 1\r\n0 1\r\n0 1\r\n"
       "ITEM: ATOMS id type xu yu zu diameter\r\n7 1 0.1 0.2 0.3 0.02\r\n9 1 0.5 0.2 0.3 0.04\r\n";
  std::ofstream(dir + "/abrade_bom.csv") << "\xEF\xBB\xBF# exported\nx,y,z,radius\n0.1,0.2,0.3,0.01\n";
  for (const std::string file : {"abrade_lammps.dump", "abrade_bom.csv"})
    {
      Simulation b(quiet_settings(5e-5));
      b.add_material(pellet);
      const ImportedBed r = import_bed(b, dir + "/" + file, 0);
      ASSERT_EQ(r.particles, file.find("dump") != std::string::npos ? 2u : 1u) << file;
      EXPECT_DOUBLE_EQ(b.particles().radius[index_of(b, file.find("dump") != std::string::npos ? 7 : 0)], 0.01);
    }
}
