// The stored wear (coupling/include/abrade/coupling/lifetime/stored_wear.h):
//  - written and read back bit for bit (surface, beds, volumes, tonnes), and a changed or
//    corrupt file refused naming it;
//  - carried onto another surface: a wear volume per unit area linear in x on a box meshed
//    4 x 4 per face, carried onto the same box meshed 8 x 8, keeps its density at every vertex
//    to 1e-9 (a linear density is interpolated exactly, and the lumped areas integrate it
//    exactly); onto a box 2 mm smaller (a knife worn inside the stored one) it takes the
//    density at each vertex's closest point on the stored box, scaled so that the total is
//    kept (a smaller area: denser), to 1e-4 inside the faces and 2 % on the edges (where either
//    face is as near); the total volume is the stored one to 1e-12 in both; onto the very same
//    surface the stored volumes come back unchanged.
// Broken once: the volumes interpolated as they are, not per unit area (the areas of a finer
// mesh's vertices are a quarter of the stored ones'), puts the density 17 % off inside the
// faces of the same box after the total is restored, and the check fails.
#include <abrade/common/error.h>
#include <abrade/coupling/lifetime/stored_wear.h>
#include <abrade/fem/surface_filter.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace abrade;
using namespace abrade::coupling::lifetime;

namespace
{
  /// The closed surface of the box [lo, hi]^3 (per axis), each face n x n squares of two
  /// outward triangles; vertices shared along edges and corners.
  fem::SolidSurface box(double lo, double hi, int n)
  {
    fem::SolidSurface s;
    std::map<std::array<long, 3>, unsigned> index;
    auto vertex = [&](std::array<long, 3> k) {
      auto it = index.find(k);
      if (it != index.end())
        return it->second;
      const double h = (hi - lo) / n;
      s.vertices.emplace_back(lo + h * k[0], lo + h * k[1], lo + h * k[2]);
      return index[k] = unsigned(s.vertices.size() - 1);
    };
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side)
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j)
            {
              const int a = (axis + 1) % 3, b = (axis + 2) % 3;
              auto      corner = [&](int di, int dj) {
                std::array<long, 3> k{};
                k[axis] = side * n, k[a] = i + di, k[b] = j + dj;
                return vertex(k);
              };
              const unsigned p = corner(0, 0), q = corner(1, 0), r = corner(1, 1), t = corner(0, 1);
              // outward: (a, b, axis) is right-handed, so a x b points along +axis
              if (side == 1)
                s.triangles.push_back({p, q, r}), s.triangles.push_back({p, r, t});
              else
                s.triangles.push_back({p, r, q}), s.triangles.push_back({p, t, r});
              s.boundary_id.push_back(1), s.boundary_id.push_back(1);
            }
    return s;
  }

  std::vector<double> volumes(const fem::SolidSurface &s, double (*density)(const dealii::Point<3> &))
  {
    const auto          area = fem::vertex_areas(s);
    std::vector<double> v(s.vertices.size());
    for (std::size_t k = 0; k < v.size(); ++k)
      v[k] = density(s.vertices[k]) * area[k];
    return v;
  }

  double linear(const dealii::Point<3> &p) { return 1e-9 * (2 + p[0] / 0.1); }

  double sum(const std::vector<double> &v)
  {
    double s = 0;
    for (double x : v)
      s += x;
    return s;
  }
} // namespace

TEST(StoredWear, WrittenAndReadBackBitForBit)
{
  StoredWear s;
  s.update       = 7;
  s.tonnes_start = 1234567.8901234567;
  s.bed_seeds    = {1, 502301537, 3};
  s.surface      = box(-0.05, 0.05, 3);
  s.surface.boundary_id[4] = 2;
  s.wear.tonnes_per_cycle = 1.0 / 3.0;
  s.wear.particle_radius  = 0.0275;
  s.wear.phase_volume     = {1e-10 / 3, M_PI * 1e-11};
  s.phases                = {"penetration", "drag"};
  s.wear_coefficient      = 2e-14;
  s.removes_volume        = true;
  for (int k = 0; k < 3; ++k)
    s.wear.seed_volume.push_back(volumes(s.surface, linear)), s.wear.seed_volume.back()[k] *= std::sqrt(2.0);
  const std::string path = testing::TempDir() + "/update_00007.wear";
  write_stored_wear(path, s);
  const StoredWear r = read_stored_wear(path);
  EXPECT_EQ(r.update, 7);
  EXPECT_EQ(r.tonnes_start, s.tonnes_start);
  EXPECT_EQ(r.bed_seeds, s.bed_seeds);
  EXPECT_EQ(r.surface.vertices, s.surface.vertices);
  EXPECT_EQ(r.surface.triangles, s.surface.triangles);
  EXPECT_EQ(r.surface.boundary_id, s.surface.boundary_id);
  EXPECT_EQ(r.wear.seed_volume, s.wear.seed_volume);
  EXPECT_EQ(r.wear.phase_volume, s.wear.phase_volume);
  EXPECT_EQ(r.phases, s.phases);
  EXPECT_EQ(r.wear.tonnes_per_cycle, s.wear.tonnes_per_cycle);
  EXPECT_EQ(r.wear.particle_radius, s.wear.particle_radius);
  EXPECT_EQ(r.wear_coefficient, s.wear_coefficient);

  // a changed number: the checksum names the file
  std::stringstream all;
  all << std::ifstream(path).rdbuf();
  std::string text = all.str();
  text.replace(text.find("update = 7"), 10, "update = 8");
  std::ofstream(path) << text;
  try
    {
      read_stored_wear(path);
      FAIL() << "a changed file was read";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("update_00007.wear"), std::string::npos) << e.what();
    }
}

TEST(StoredWear, CarriedOntoAnotherSurfaceKeepsDensityAndVolume)
{
  const fem::SolidSurface   stored = box(-0.05, 0.05, 4);
  const std::vector<double> v      = volumes(stored, linear);
  // the same surface: the stored volumes themselves
  EXPECT_EQ(carry_wear_volume(stored, v, stored), v);
  for (const double half : {0.05, 0.048}) // the same box meshed finer; one worn 2 mm into it
    {
      const fem::SolidSurface to      = box(-half, half, 8);
      const auto              carried = carry_wear_volume(stored, v, to);
      EXPECT_NEAR(sum(carried) / sum(v), 1, 1e-12) << half;
      // where each vertex lands on the stored box (its closest point: a face's coordinate pushed
      // out to the stored face; along an edge either face is as near, within 2 mm of x) and the
      // density there, scaled so that the total is the stored one (a smaller box: denser)
      const auto          area = fem::vertex_areas(to);
      std::vector<double> expected(to.vertices.size());
      double              total = 0;
      for (std::size_t k = 0; k < expected.size(); ++k)
        {
          dealii::Point<3> foot = to.vertices[k];
          if (std::abs(std::abs(foot[0]) - half) < 1e-12)
            foot[0] *= 0.05 / half;
          expected[k] = linear(foot);
          total += expected[k] * area[k];
        }
      double worst = 0, worst_inside = 0;
      for (std::size_t k = 0; k < expected.size(); ++k)
        {
          const double e = std::abs(carried[k] / area[k] / (expected[k] * sum(v) / total) - 1);
          int          extreme = 0;
          for (int d = 0; d < 3; ++d)
            extreme += std::abs(std::abs(to.vertices[k][d]) - half) < 1e-12;
          worst = std::max(worst, e);
          if (extreme == 1) // inside a face, not on an edge or a corner
            worst_inside = std::max(worst_inside, e);
        }
      // (the same box: linear densities are exact, the lumped areas integrate them exactly)
      EXPECT_LT(worst, half == 0.05 ? 1e-9 : 0.02) << half;
      EXPECT_LT(worst_inside, half == 0.05 ? 1e-9 : 1e-4) << half; // (the total: the edges as expected)
      std::cout << "box of half-width " << half << ": density off by at most " << worst << " (" << worst_inside
                << " inside the faces); volume " << sum(carried) / sum(v) << " of the stored\n";
    }
}

// Runs of one bed each, joined (the replay of several runs, Lifetime/Replay/Run = a, b, c), are
// what one run of their beds stores: the beds and their volumes in the runs' order, the phases'
// volumes added bed by bed, each over the beds' number, as dem_wear_source.cc adds them (the
// same bits; the sum of the three then divided by three differs in the last bits for these
// numbers, and the check fails for it); a run of two beds (their mean stored) joined with one
// gives the three beds' mean; a grab's tonnes (its payload, bed by bed) the beds' mean, and a
// size distribution's largest particle the last bed's. Refused, naming the run: a bed two runs
// share, another W, another surface, other tonnes per cycle where they are not a payload.
TEST(StoredWear, RunsOfOneBedJoinedAreTheRunOfTheirBeds)
{
  const auto one_bed = [](int seed, double penetration, double travel) {
    StoredWear s;
    s.update                = 1;
    s.bed_seeds             = {seed};
    s.surface               = box(-0.05, 0.05, 2);
    s.wear.tonnes_per_cycle = 0.7;
    s.wear.particle_radius  = 0.0275;
    s.wear.phase_volume     = {penetration, travel};
    s.phases                = {"penetration", "travel"};
    s.wear_coefficient      = 2e-14;
    s.wear.seed_volume.push_back(volumes(s.surface, linear));
    s.wear.seed_volume.back()[0] = penetration; // (tells the beds apart)
    return s;
  };
  const std::vector<double> pen = {1e-10 / 3, 0.7e-10, M_PI * 1e-11}, trav = {0.1e-9, 0.2e-9, 0.3e-9};
  std::vector<StoredWear>   runs;
  for (int b = 0; b < 3; ++b)
    runs.push_back(one_bed(b + 1, pen[b], trav[b]));
  const StoredWear j = join_stored_wear(runs, {"a", "b", "c"});
  EXPECT_EQ(j.bed_seeds, (std::vector<int>{1, 2, 3}));
  ASSERT_EQ(j.wear.seed_volume.size(), 3u);
  for (int b = 0; b < 3; ++b)
    EXPECT_EQ(j.wear.seed_volume[b], runs[b].wear.seed_volume[0]);
  // the DEM's sum over its beds (one knife): each bed's phase volume over (knives x beds)
  std::vector<double> dem(2, 0.0);
  for (int b = 0; b < 3; ++b)
    dem[0] += pen[b] / (1 * 3), dem[1] += trav[b] / (1 * 3);
  EXPECT_EQ(j.wear.phase_volume, dem);
  EXPECT_NE((pen[0] + pen[1] + pen[2]) / 3, dem[0]) << "the numbers no longer tell the two sums apart";
  EXPECT_EQ(j.wear.tonnes_per_cycle, 0.7);
  EXPECT_EQ(j.surface.vertices, runs[0].surface.vertices);

  // a run of two beds with one of one: the three beds' mean; a grab's payload, bed by bed; a
  // size distribution's largest particle, the last bed's (as the DEM keeps it)
  StoredWear two = join_stored_wear({runs[0], runs[1]}, {"a", "b"});
  StoredWear third = runs[2];
  two.wear.tonnes_per_cycle = 0.6, third.wear.tonnes_per_cycle = 0.9;
  third.wear.particle_radius = 0.0271;
  const StoredWear m = join_stored_wear({two, third}, {"ab", "c"}, true);
  EXPECT_EQ(m.wear.particle_radius, 0.0271);
  EXPECT_EQ(m.bed_seeds, (std::vector<int>{1, 2, 3}));
  EXPECT_NEAR(m.wear.phase_volume[0], (pen[0] + pen[1] + pen[2]) / 3, 1e-15 * pen[1]);
  EXPECT_NEAR(m.wear.phase_volume[1], (trav[0] + trav[1] + trav[2]) / 3, 1e-15 * trav[2]);
  EXPECT_NEAR(m.wear.tonnes_per_cycle, (2 * 0.6 + 0.9) / 3, 1e-15);

  // other tonnes per cycle where they are the case's, not a payload: refused
  try
    {
      join_stored_wear({two, third}, {"ab", "run-c"});
      ADD_FAILURE() << "other tonnes per cycle joined";
    }
  catch (const InputError &e)
    {
      EXPECT_NE(std::string(e.what()).find("run-c"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("Tonnes per cycle"), std::string::npos) << e.what();
    }

  const auto refused = [&](std::vector<StoredWear> parts, const std::string &words) {
    try
      {
        join_stored_wear(parts, {"run-a", "run-b", "run-c"});
        ADD_FAILURE() << "joined: " << words;
      }
    catch (const InputError &e)
      {
        const std::string what = e.what();
        EXPECT_NE(what.find("run-c"), std::string::npos) << what;
        EXPECT_NE(what.find(words), std::string::npos) << what;
      }
  };
  StoredWear again = runs[2];
  again.bed_seeds  = {1};
  refused({runs[0], runs[1], again}, "seed 1 is in another of the runs");
  StoredWear other_w = runs[2];
  other_w.wear_coefficient = 3e-14;
  refused({runs[0], runs[1], other_w}, "wear law or W");
  StoredWear other_part = runs[2];
  other_part.surface    = box(-0.05, 0.051, 2);
  refused({runs[0], runs[1], other_part}, "surface");
}
