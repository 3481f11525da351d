// Coarse graining keeps the bulk: the same real particles (3.5 mm radius, 20 % spread)
// described once and simulated at two coarse-graining ratios through dem::coarse_grain's rules
//  - settle in a 0.24 m box (f = 24/7 and 12/7: particles of 12 and 6 mm, 700 and 5,600 of
//    them) to the same bulk density inside the bed (within 2 %; measured: 0.1 %) and nearly the
//    same height: the layer next to a wall is looser over about a particle radius, and in a box
//    10 coarse particles wide that makes the coarse bed about 6 % taller (limit 10 %);
//  - pour from a column onto a floor to the same angle of repose (f = 12/7 and 12/7 / sqrt 2:
//    6 and 4.2 mm, heaps of 3,472 and 9,819 particles; within 2 degrees, measured 0.2). A heap
//    of the 434 particles of 12 mm stands about 6 degrees flatter: the angle is kept only once
//    the heap spans many particles (docs/coarse-graining.md).
// A count scaled by f^-2 instead of f^-3 doubles the bed's height; a density scaled with the
// particle's volume moves the bulk density by f^3; a friction scaled with the size moves the
// angle.
#include "dem_test_helpers.h"

#include <abrade/dem/coarse_graining.h>
#include <abrade/dem/generation.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <optional>

using namespace abrade::dem;
using namespace abrade::dem::testing;

namespace
{
  const Material pellet = Material::from_shear_modulus("pellet", 1e7, 0.25, 2500, false);

  /// The real particles: radii uniform in [3.15, 3.85] mm, @p count of them in the fill box.
  FillRegion real_particles(const Vec3 &lo, const Vec3 &hi, long count)
  {
    FillRegion f;
    f.box_min = lo, f.box_max = hi;
    f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.00315, f.sizes.max = 0.00385;
    f.count = count, f.seed = 5, f.velocity = Vec3(0, 0, -0.5);
    return f;
  }

  /// An empty simulation of the pellets (two threads) with walls @p walls.
  std::unique_ptr<Simulation> pellet_simulation(const Settings &s, const TriangleMesh &walls)
  {
    auto      sim = std::make_unique<Simulation>(s);
    const int m   = sim->add_material(pellet);
    sim->set_interaction(m, m, {0.5, 0.5, 0.0});
    Wall w;
    w.name = "walls", w.mesh = walls, w.material = m;
    sim->add_wall(w);
    return sim;
  }

  /// A simulation of the real particles coarse-grained by @p f, with walls @p walls.
  std::unique_ptr<Simulation> coarse_grained(double f, FillRegion fill, const TriangleMesh &walls)
  {
    Settings s;
    s.threads = 2;
    coarse_grain(f, fill, s);
    auto sim = pellet_simulation(s, walls);
    fill.avoid.push_back(walls);
    fill_region(*sim, fill);
    sim->setup();
    return sim;
  }

  /// Pairs of particles that overlap (by brute force).
  int overlapping_pairs(const ParticleStore &P)
  {
    int n = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      for (std::size_t j = i + 1; j < P.size(); ++j)
        {
          const double dx = P.x[i] - P.x[j], dy = P.y[i] - P.y[j], dz = P.z[i] - P.z[j], s = P.radius[i] + P.radius[j];
          n += dx * dx + dy * dy + dz * dz < s * s * (1 - 1e-12);
        }
    return n;
  }

  /// The settled bed's measuring band: its height from the centre of mass (twice its height,
  /// for a bed of uniform density) and the layer from a quarter to three quarters of it, away
  /// from the floor and the top.
  struct Band
  {
    double height, z0, z1;
  };
  Band measuring_band(const ParticleStore &P)
  {
    double mass = 0, mz = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      mass += P.mass[i], mz += P.mass[i] * P.z[i];
    const double height = 2 * mz / mass;
    return {height, 0.25 * height, 0.75 * height};
  }

  /// The volume of a sphere of radius @p r centred at @p c between the planes @p a and @p b
  /// (a < b) across one axis: pi int (r^2 - (z - c)^2) dz.
  double sphere_between(double r, double c, double a, double b)
  {
    const double lo = std::clamp(a - c, -r, r), hi = std::clamp(b - c, -r, r);
    return M_PI * (r * r * (hi - lo) - (hi * hi * hi - lo * lo * lo) / 3);
  }

  struct Bed
  {
    double height, bulk_density, particles;
  };

  /// A bed poured into a 0.24 m square box: its height from the centre of mass (twice its
  /// height, for a bed of uniform density) and its bulk density inside, away from the walls,
  /// the floor and the top: the mass of the particles whose centres lie within 0.08 m of the
  /// box's axis, between a quarter and three quarters of the height (each sphere cut exactly at
  /// those heights), over that volume.
  Bed settled_bed(double f)
  {
    const double L   = 0.24;
    auto         sim = coarse_grained(f, real_particles(Vec3(-0.115, -0.115, 0.01), Vec3(0.115, 0.115, 0.4), 28212),
                                      primitives::box_container(Vec3(-L / 2, -L / 2, 0), Vec3(L / 2, L / 2, 0.5)));
    sim->run_phase("settle", 1.2);
    const auto  &P = sim->particles();
    const Band   band = measuring_band(P);
    const double a    = 0.08;
    double       inside = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (std::abs(P.x[i]) <= a && std::abs(P.y[i]) <= a)
        inside += sphere_between(P.radius[i], P.z[i], band.z0, band.z1) * pellet.density;
    return {band.height, inside / (4 * a * a * (band.z1 - band.z0)), double(P.size())};
  }

  /// The slope of a heap from its moments: a cone of base radius R and height h has its
  /// centroid at h / 4 and its material at a mean distance R / 2 from the axis, so
  /// tan(angle) = h / R = 2 (mean height above the floor) / (mean distance from the axis). All
  /// particles count (the highest one per ring, heap_angle, hangs on a few at a heap of a few
  /// hundred); the particles further out than twice the mean distance (rolled away) do not.
  double heap_slope(const ParticleStore &P)
  {
    double cx = 0, cy = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      cx += P.x[i], cy += P.y[i];
    cx /= P.size(), cy /= P.size();
    double mean_r = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      mean_r += std::hypot(P.x[i] - cx, P.y[i] - cy) / P.size();
    double r = 0, z = 0, n = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      if (const double d = std::hypot(P.x[i] - cx, P.y[i] - cy); d < 2 * mean_r)
        r += d, z += P.z[i] - P.radius[i], ++n; // the height of the particle's bottom above the floor
    return std::atan(2 * z / r) * 180 / M_PI;
  }

  /// The angle of repose of the real particles poured from a column onto a floor.
  double heap(double f)
  {
    auto sim = coarse_grained(f, real_particles(Vec3(-0.08, -0.08, 0.02), Vec3(0.08, 0.08, 0.6), 17490),
                              primitives::plate(Vec3::Zero(), 2, 2.0, 2.0, 0));
    sim->run_phase("pour", 2.0);
    std::printf("f = %.3f: heap of %zu particles: %.1f deg from the highest per ring, %.1f deg from its moments\n", f,
                sim->particles().size(), heap_angle(sim->particles()), heap_slope(sim->particles()));
    return heap_slope(sim->particles());
  }
} // namespace

TEST(CoarseGraining, RulesScaleSizesCountAndSkin)
{
  FillRegion f = real_particles(Vec3::Zero(), Vec3::Ones(), 8000);
  Settings   s;
  s.skin = 0.001;
  coarse_grain(2, f, s);
  EXPECT_DOUBLE_EQ(f.sizes.min, 0.0063);
  EXPECT_DOUBLE_EQ(f.sizes.max, 0.0077);
  EXPECT_EQ(f.count, 1000);
  EXPECT_DOUBLE_EQ(s.skin, 0.002);
  EXPECT_DOUBLE_EQ(coarse_grain_energy(2, 1e-4), 8e-4); // kinetic energy per particle, as the mass
  EXPECT_TRUE(coarse_graining_warnings(2, s).empty());
  s.time_step = 1e-5; // a fixed step does not follow the radius
  EXPECT_EQ(coarse_graining_warnings(2, s).size(), 1u);
  EXPECT_TRUE(coarse_graining_warnings(1, s).empty());
}

TEST(CoarseGraining, KeepsBedHeightAndBulkDensity)
{
  const Bed coarse = settled_bed(24.0 / 7), fine = settled_bed(12.0 / 7);
  std::printf("settled bed: %.0f particles: height %.4f m, bulk density %.1f kg/m^3; %.0f particles: %.4f m, "
              "%.1f kg/m^3\n",
              coarse.particles, coarse.height, coarse.bulk_density, fine.particles, fine.height, fine.bulk_density);
  EXPECT_NEAR(coarse.particles * 8, fine.particles, 8);
  EXPECT_NEAR(coarse.height / fine.height, 1.0, 0.10);
  EXPECT_NEAR(coarse.bulk_density / fine.bulk_density, 1.0, 0.02);
}

TEST(CoarseGraining, KeepsTheAngleOfRepose)
{
  const double coarse = heap(12.0 / 7), fine = heap(12.0 / 7 / std::sqrt(2.0));
  EXPECT_GT(fine, 20);
  EXPECT_NEAR(coarse, fine, 2.0);
}

TEST(CoarseGraining, FineRegionHoldsTheFinerParticles)
{
  // multi-level coarse graining without intermediate sizes: a box of the fill region with
  // particles coarse-grained by 1.5, the rest by 3; the real count split by volume, every
  // particle of its own size in its own part
  FillRegion coarse = real_particles(Vec3(0, 0, 0), Vec3(0.4, 0.2, 0.2), 20000);
  FineRegion region;
  region.lo = Vec3(0.1, -1, -1), region.hi = Vec3(0.2, 1, 1), region.factor = 1.5, region.step = 0;
  const auto levels = split_into_levels(coarse, region, 3);
  ASSERT_EQ(levels.size(), 1u);
  const FillRegion &fine = levels[0].fill;
  EXPECT_EQ(fine.count, std::lround(5000 / 3.375));
  EXPECT_EQ(coarse.count, 15000);
  Settings s;
  coarse_grain(3, coarse, s);
  Simulation sim(s);
  sim.add_material(pellet);
  EXPECT_EQ(fill_region(sim, fine), std::lround(5000 / 3.375));
  EXPECT_EQ(fill_region(sim, coarse), std::lround(15000 / 27.0));
  const auto &P = sim.particles(); // the fine ones' centres in their box, the others' out of it
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.radius[i] <= fine.sizes.max)
      EXPECT_TRUE(P.x[i] >= 0.1 && P.x[i] <= 0.2) << P.x[i];
    else
      EXPECT_TRUE(P.x[i] <= 0.1 || P.x[i] >= 0.2) << P.x[i];
  EXPECT_EQ(overlapping_pairs(P), 0);
}

TEST(CoarseGraining, LevelsNestInThreeDimensionsAndKeepTheSolidFraction)
{
  // a fine box strictly inside the fill box: shells on all six sides; with Count 0 every level
  // fills its own region to the solid fraction, so the bed's solid fraction is the same in each
  FillRegion bulk = real_particles(Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5), 0);
  bulk.solid_fraction = 0.25;
  FineRegion region;
  region.lo = Vec3(0.2, 0.2, 0.2), region.hi = Vec3(0.3, 0.3, 0.3), region.factor = 2, region.step = 1.5;
  const auto levels = split_into_levels(bulk, region, 4);
  ASSERT_EQ(levels.size(), 2u); // 2 -> 4 in two steps of 1.41
  const auto &shell = *levels[1].fill.centres_in;
  const double t    = 2 * 0.00385 * levels[1].factor;
  EXPECT_NEAR((shell.second - shell.first - Vec3::Constant(0.1 + 2 * t)).norm(), 0, 1e-12); // one diameter each side
  EXPECT_NEAR(levels[1].volume, std::pow(0.1 + 2 * t, 3) - 1e-3, 1e-12);
  Settings s;
  coarse_grain(4, bulk, s);
  Simulation sim(s);
  sim.add_material(pellet);
  std::vector<double> solid;
  for (const auto &l : levels)
    {
      const long n = fill_region(sim, l.fill);
      solid.push_back(double(n) * l.fill.sizes.mean_volume() / l.volume);
    }
  const long n = fill_region(sim, bulk);
  solid.push_back(double(n) * bulk.sizes.mean_volume() / (0.125 - levels[0].volume - levels[1].volume));
  for (double v : solid)
    EXPECT_NEAR(v, 0.25, 0.01);
  EXPECT_EQ(overlapping_pairs(sim.particles()), 0);
}

TEST(CoarseGraining, LevelsThatLeaveTheBulkNoRoomAreRefused)
{
  FillRegion bulk = real_particles(Vec3(0, 0, 0), Vec3(1, 0.2, 0.2), 1000);
  FineRegion region;
  region.factor = 1.5, region.step = 0;
  region.lo = Vec3(0, -1, -1), region.hi = Vec3(0.99, 1, 1); // a 10 mm gap: narrower than a bulk particle
  FillRegion copy = bulk;
  EXPECT_THROW(split_into_levels(copy, region, 3), std::invalid_argument);
  region.hi = Vec3(0.9, 1, 1); // a 0.1 m gap: room
  copy = bulk;
  EXPECT_NO_THROW(split_into_levels(copy, region, 3));
  region.step = 1.25, region.layer_diameters = 20; // a shell 0.1 m and more thick reaches the far face
  copy = bulk;
  EXPECT_THROW(split_into_levels(copy, region, 3), std::invalid_argument);
  EXPECT_THROW(level_factors(1, 2, 1.01), std::invalid_argument); // thousands of levels
}

TEST(CoarseGraining, LevelsStepFromTheFineFactorToTheBulksInEqualRatios)
{
  // 1.5 -> 3 in steps of at most 1.25: ln 2 / ln 1.25 = 3.1, so four equal steps of 2^(1/4)
  const auto f = level_factors(1.5, 3, 1.25);
  ASSERT_EQ(f.size(), 4u);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(f[k], 1.5 * std::pow(2.0, k / 4.0), 1e-12);
  EXPECT_EQ(level_factors(1.5, 3, 0).size(), 1u);
  EXPECT_EQ(level_factors(1.5, 3, 2).size(), 1u); // one step of 2 is allowed
  EXPECT_EQ(level_factors(1.5, 3, 1.9).size(), 2u);

  // the shells: each the given number of its particles' largest diameters thick, nested, the
  // real count split by the volume each holds, every particle inside its own shell
  FillRegion bulk = real_particles(Vec3(0, 0, 0), Vec3(0.6, 0.2, 0.2), 30000);
  FineRegion region;
  region.lo = Vec3(0.25, -1, -1), region.hi = Vec3(0.35, 1, 1), region.factor = 1.5, region.step = 1.25;
  region.layer_diameters = 2;
  const auto levels = split_into_levels(bulk, region, 3);
  ASSERT_EQ(levels.size(), 4u);
  const auto region_of = [&](std::size_t k) { return *levels[k].fill.centres_in; }; // the centres' box
  double lo = 0.25, hi = 0.35;
  long   real = 0;
  for (std::size_t k = 0; k < levels.size(); ++k)
    {
      const FillRegion &l = levels[k].fill;
      const double      t = k == 0 ? 0 : 2 * 2 * 0.00385 * levels[k].factor;
      EXPECT_NEAR(region_of(k).first.x(), lo - t, 1e-12);
      EXPECT_NEAR(region_of(k).second.x(), hi + t, 1e-12);
      EXPECT_NEAR(l.sizes.max, 0.00385 * levels[k].factor, 1e-12);
      const double width = 2 * t + (k == 0 ? hi - lo : 0);
      EXPECT_NEAR(l.count * std::pow(levels[k].factor, 3), 30000 * width / 0.6, std::pow(levels[k].factor, 3));
      real += std::lround(30000 * width / 0.6);
      lo -= t, hi += t;
    }
  EXPECT_EQ(bulk.count, 30000 - real);
  Settings s;
  coarse_grain(3, bulk, s);
  Simulation sim(s);
  sim.add_material(pellet);
  std::vector<long> first_id = {0}; // the levels' ids follow each other
  for (const auto &l : levels)
    first_id.push_back(first_id.back() + fill_region(sim, l.fill));
  fill_region(sim, bulk);
  const auto &P = sim.particles();
  for (std::size_t i = 0; i < P.size(); ++i)
    {
      std::size_t k = 0; // the particle's level
      while (k < levels.size() && P.id[i] >= first_id[k + 1])
        ++k;
      const double in_lo = k == 0 ? -1 : region_of(k - 1).first.x(), in_hi = k == 0 ? -1 : region_of(k - 1).second.x();
      const double out_lo = k < levels.size() ? region_of(k).first.x() : -1, out_hi = k < levels.size() ? region_of(k).second.x() : 1;
      const double x = P.x[i]; // the centres in their level's region
      EXPECT_TRUE(x >= out_lo && x <= out_hi && (k == 0 || x <= in_lo || x >= in_hi)) << k << " " << x;
    }
  EXPECT_EQ(overlapping_pairs(P), 0); // the levels touch without overlapping
}

namespace
{
  /// A bed of the real particles poured (not yet settled) into a box 0.48 m long (x), 0.24 m
  /// wide and 0.5 m high, coarse-grained by @p bulk, with the finer levels of @p region between
  /// (none: a uniform bed) and placement seed @p seed; @p counts, where not empty, the number
  /// of particles of each level, the bulk's last (empty: the split's). What was poured: the
  /// levels, the particles per level and their mean masses.
  struct PouredBox
  {
    std::unique_ptr<Simulation> sim;
    std::vector<Level>          levels;
    std::vector<long>           counts;
    std::vector<double>         mean_mass;
  };

  PouredBox pour_box(const std::optional<FineRegion> &region, double bulk, std::uint64_t seed,
                     const std::vector<long> &counts = {})
  {
    const double L    = 0.24;
    FillRegion   rest = real_particles(Vec3(-0.235, -0.115, 0.01), Vec3(0.235, 0.115, 0.4), 57650);
    rest.seed         = seed;
    PouredBox out;
    if (region)
      out.levels = split_into_levels(rest, *region, bulk);
    Settings s;
    s.threads = 2;
    coarse_grain(bulk, rest, s);
    const TriangleMesh box = primitives::box_container(Vec3(-L, -L / 2, 0), Vec3(L, L / 2, 0.5));
    out.sim                = pellet_simulation(s, box);
    std::vector<FillRegion> fills;
    for (const auto &level : out.levels)
      fills.push_back(level.fill);
    fills.push_back(rest);
    for (std::size_t k = 0; k < fills.size(); ++k)
      {
        FillRegion f = fills[k];
        f.avoid.push_back(box);
        if (!counts.empty())
          f.count = counts[k];
        const std::size_t first = out.sim->particles().size();
        out.counts.push_back(fill_region(*out.sim, f));
        double mass = 0;
        for (std::size_t i = first; i < out.sim->particles().size(); ++i)
          mass += out.sim->particles().mass[i];
        out.mean_mass.push_back(mass / out.counts.back());
      }
    return out;
  }

  /// The solid fraction across a multi-level bed's interface: pour_box with the finest particles
  /// (coarse-grained by @p fine) in x < 0, @p bulk beyond with levels by @p step (shells @p layer
  /// diameters thick) between, settled; the solid fraction in @p n slabs of width @p w centred on
  /// x = 0, each sphere cut exactly at the slabs' faces, of the particles whose centres lie
  /// within 0.08 m of the box's axis (y) and between a quarter and three quarters of the bed's
  /// height.
  std::vector<double> interface_profile(double fine, double bulk, double step, double layer, double w, int n, std::uint64_t seed)
  {
    std::optional<FineRegion> region;
    if (fine != bulk)
      {
        region.emplace();
        region->lo = Vec3(-1, -1, -1), region->hi = Vec3(0, 1, 1), region->factor = fine, region->step = step,
        region->layer_diameters = layer;
      }
    auto sim = pour_box(region, bulk, seed).sim;
    sim->setup();
    sim->run_phase("settle", 1.2);
    const auto  &P = sim->particles();
    const Band   band = measuring_band(P);
    const double a    = 0.08;
    std::vector<double> phi(n, 0.0);
    for (std::size_t i = 0; i < P.size(); ++i)
      if (std::abs(P.y[i]) <= a && P.z[i] >= band.z0 && P.z[i] <= band.z1)
        for (int b = 0; b < n; ++b)
          {
            const double x0 = (b - n / 2.0) * w;
            phi[b] += sphere_between(P.radius[i], P.x[i], x0, x0 + w) / (w * 2 * a * (band.z1 - band.z0));
          }
    return phi;
  }

  /// interface_profile's mean over three beds.
  std::vector<double> mean_profile(double fine, double bulk, double step, double layer, double w, int n)
  {
    std::vector<double> mean(n, 0.0);
    for (std::uint64_t seed : {5, 6, 7})
      {
        const auto phi = interface_profile(fine, bulk, step, layer, w, n, seed);
        for (int b = 0; b < n; ++b)
          mean[b] += phi[b] / 3;
      }
    return mean;
  }
} // namespace

TEST(CoarseGraining, AGradedInterfaceKeepsTheUniformBedsDensity)
{
  // particles of 6 mm (coarse-grained by 12/7) in x < 0 and of 12 mm (24/7) beyond, with the
  // default levels between (steps of at most 1.25, shells one diameter thick): across the
  // interface, in slabs of 20 mm (about three fine diameters) over |x| < 0.1 m, the settled
  // bed's solid fraction (the mean of three beds) is the uniform 6 mm bed's within 3 %
  // (measured: 2.6 %; with three other beds, the finest level then placed whole in its box,
  // 2.6 % too). The two sizes meeting directly
  // (Fine region step 0) put 12 % more solid in the first slab on the coarse side, where the fine
  // particles fill the coarse ones' boundary voids, 6 % less in the next and 4 % less in the
  // last slab on the fine side (a wall of large spheres); steps of 1.25 with shells two
  // diameters thick left 3.7 % at one shell's boundary.
  const double w = 0.02, ff = 12.0 / 7;
  const int    n = 10;
  FineRegion   defaults;
  const auto   uniform = mean_profile(ff, ff, 0, 0, w, n);
  const auto   graded  = mean_profile(ff, 2 * ff, defaults.step, defaults.layer_diameters, w, n);
  double       phi0    = 0;
  for (double v : uniform)
    phi0 += v / n;
  for (int b = 0; b < n; ++b)
    {
      std::printf("x %+.3f m: solid fraction %.4f (uniform bed %.4f)\n", (b - n / 2.0 + 0.5) * w, graded[b], uniform[b]);
      EXPECT_NEAR(graded[b] / phi0, 1.0, 0.03) << "slab at x = " << (b - n / 2.0 + 0.5) * w;
    }
  EXPECT_GT(phi0, 0.45); // a settled bed, not a loose one
}

namespace
{
  /// pour_box with the particles coarse-grained by 12/7 (6 mm) in a strip |x| < 0.06 m across
  /// the box's width, by 24/7 (12 mm) beyond, the default levels between, poured with @p counts.
  PouredBox strip_bed(const std::vector<long> &counts)
  {
    FineRegion region;
    region.lo = Vec3(-0.06, -1, -1), region.hi = Vec3(0.06, 1, 1), region.factor = 12.0 / 7;
    return pour_box(region, 24.0 / 7, 5, counts); // (real_particles' seed)
  }
} // namespace

TEST(CoarseGraining, ARefilledPourHoldsTheFineRegionsMassPerArea)
{
  // The finer particles spread into the coarser ones' voids as the bed settles: the fine strip
  // (0.12 m wide, two interfaces) loses mass to its shells, and its top settles lower than the
  // uniform bed's (measured: 96.2 % of the mass poured over it). Poured again twice (the
  // default three pours) with the counts refilled by what the strip lacked (refill_counts), it
  // holds what the case pours over it within 1 % (measured: 99.3 %, after one refill 99.2 %), and the total mass
  // stays.
  std::vector<Level>  levels;
  std::vector<long>   counts;
  std::vector<double> mean_mass;
  std::vector<double> wanted, settled;
  double              total_wanted = 0;
  for (int pour = 1; pour <= 3; ++pour)
    {
      PouredBox bed = strip_bed(counts);
      auto     &sim = bed.sim;
      levels = bed.levels, counts = bed.counts, mean_mass = bed.mean_mass;
      ASSERT_EQ(counts.size(), levels.size() + 1);
      const auto poured = footprint_masses(levels, sim->particles());
      double     total  = 0;
      for (double m : poured)
        total += m;
      if (pour == 1)
        wanted = poured, total_wanted = total;
      EXPECT_NEAR(total / total_wanted, 1.0, 0.002); // the mass moved between the levels, not added
      sim->run_phase("settle", 1.2);
      settled = footprint_masses(levels, sim->particles());
      double total_settled = 0;
      for (double m : settled)
        total_settled += m;
      EXPECT_NEAR(total_settled / total, 1.0, 1e-12); // every particle over some footprint
      std::printf("pour %d: the fine strip holds %.2f %% of the mass the case pours over it\n", pour,
                  100 * settled[0] / wanted[0]);
      if (pour == 1) // what the refill is for: a fine region that loses mass
        {
          EXPECT_LT(settled[0] / wanted[0], 0.98);
        }
      const auto next = refill_counts(counts, mean_mass, wanted, settled);
      if (pour == 1)
        {
          EXPECT_GT(next[0], counts[0]);
        }
      counts = next;
    }
  EXPECT_NEAR(settled[0] / wanted[0], 1.0, 0.01);
}

TEST(CoarseGraining, FootprintsFollowTheLevelsBoxesAcrossXAndY)
{
  // a fine box in the middle of the fill box's x, reaching its faces across y: its footprint
  // goes on past those faces (a particle settled against the wall), the shell's around it, the
  // bulk's beyond; refill_counts adds what a footprint lost in its level's particles
  FillRegion fill = real_particles(Vec3(0, 0, 0), Vec3(0.6, 0.2, 0.2), 30000);
  FineRegion region;
  region.lo = Vec3(0.25, -1, -1), region.hi = Vec3(0.35, 1, 1), region.factor = 1.5, region.step = 1.9;
  const auto levels = split_into_levels(fill, region, 3); // 1.5 and 2.12 (its shell 16.3 mm thick)
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_EQ(footprint_of(levels, 0.3, 0.1), 0u);
  EXPECT_EQ(footprint_of(levels, 0.3, 0.25), 0u);  // past the fill box's face across y
  EXPECT_EQ(footprint_of(levels, 0.3, -0.05), 0u);
  EXPECT_EQ(footprint_of(levels, 0.36, 0.1), 1u); // the shell
  EXPECT_EQ(footprint_of(levels, 0.24, 0.1), 1u);
  EXPECT_EQ(footprint_of(levels, 0.37, 0.1), 2u);  // the bulk
  EXPECT_EQ(footprint_of(levels, -0.01, 0.1), 2u);
  // the fine footprint lacked 5 (5 particles of mass 1), the shell held 1 more than its share
  // (kept: emptier shells take in more of the finer particles), the bulk gives the 5 (0.6 of
  // its particles, rounded to 1)
  EXPECT_EQ(refill_counts({100, 50, 10}, {1, 2, 8}, {100, 100, 80}, {95, 101, 84}), (std::vector<long>{105, 50, 9}));
  // a shell that lacks is refilled too
  EXPECT_EQ(refill_counts({100, 50, 10}, {1, 2, 8}, {100, 100, 80}, {95, 96, 89}), (std::vector<long>{105, 52, 9}));
  EXPECT_THROW(refill_counts({100, 50}, {1, 2, 8}, {100, 100, 80}, {95, 96, 89}), std::invalid_argument);
}
