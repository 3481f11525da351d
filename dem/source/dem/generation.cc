// Beds of particles: generated without overlap in a region, and saved to and loaded from bed
// files (generation.h).
#include <abrade/common/atomic_file.h>
#include <abrade/common/error.h>
#include <abrade/common/hash.h>
#include <abrade/common/closest_point.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/simulation.h>
#include "bed_columns.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace abrade::dem
{
  namespace
  {
    // uniform in [0, 1) from 53 random bits: identical on every platform (std's distributions
    // are implementation-defined)
    double uniform01(std::mt19937_64 &rng) { return (rng() >> 11) * 0x1.0p-53; }

    double standard_normal(std::mt19937_64 &rng)
    {
      double u1 = uniform01(rng);
      while (u1 <= 0)
        u1 = uniform01(rng);
      return std::sqrt(-2 * std::log(u1)) * std::cos(2 * M_PI * uniform01(rng));
    }
  } // namespace

  double SizeDistribution::sample(std::mt19937_64 &rng) const
  {
    switch (kind)
      {
        case Kind::constant: return radius;
        case Kind::uniform: return min + (max - min) * uniform01(rng);
        case Kind::normal:
          for (int tries = 0; tries < 1000; ++tries)
            {
              const double r = radius + std * standard_normal(rng);
              if (r >= min && r <= max)
                return r;
            }
          return std::clamp(radius, min, max);
      }
    return radius;
  }

  double SizeDistribution::mean_volume() const
  {
    // by sampling: exact enough to choose a particle count
    std::mt19937_64 rng(12345);
    double          v = 0;
    const int       n = kind == Kind::constant ? 1 : 20000;
    for (int k = 0; k < n; ++k)
      v += std::pow(sample(rng), 3);
    return 4.0 / 3.0 * M_PI * v / n;
  }

  bool inside_mesh(const TriangleMesh &mesh, const Vec3 &p)
  {
    // ray along a slightly skewed direction to avoid hitting edges exactly
    const Vec3 dir = Vec3(0.5773, 0.5774, 0.5775).normalized();
    int        crossings = 0;
    for (const auto &t : mesh.triangles)
      {
        const Vec3  &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
        const Vec3   e1 = b - a, e2 = c - a, pv = dir.cross(e2);
        const double det = e1.dot(pv);
        if (std::abs(det) < 1e-300)
          continue;
        const Vec3   tv = p - a;
        const double u  = tv.dot(pv) / det;
        if (u < 0 || u > 1)
          continue;
        const Vec3   qv = tv.cross(e1);
        const double v  = dir.dot(qv) / det;
        if (v < 0 || u + v > 1)
          continue;
        if (e2.dot(qv) / det > 0)
          ++crossings;
      }
    return crossings % 2 == 1;
  }

  namespace
  {
    /// Whether a particle at a point is clear of the walls to avoid: outside a closed one, and
    /// farther than 1.05 radii from every triangle of those whose box (grown by a diameter of
    /// the largest particle) holds the point.
    class WallClearance
    {
    public:
      WallClearance(const std::vector<TriangleMesh> &avoid, double r_big)
        : avoid(avoid)
      {
        for (const auto &m : avoid)
          {
            Vec3 lo, hi;
            m.bounding_box(lo, hi);
            closed.push_back(m.is_closed());
            boxes.emplace_back(lo - Vec3::Constant(2 * r_big), hi + Vec3::Constant(2 * r_big));
          }
      }

      bool clear(const Vec3 &p, double r) const
      {
        for (std::size_t k = 0; k < avoid.size(); ++k)
          {
            if (!(p.array() >= boxes[k].first.array()).all() || !(p.array() <= boxes[k].second.array()).all())
              continue;
            const auto &m = avoid[k];
            if (closed[k] && inside_mesh(m, p))
              return false;
            for (const auto &t : m.triangles)
              {
                const auto cp = closest_point_on_triangle(p.data(), m.vertices[t[0]].data(),
                                                          m.vertices[t[1]].data(), m.vertices[t[2]].data());
                if ((p - Vec3(cp.p[0], cp.p[1], cp.p[2])).norm() < 1.05 * r)
                  return false;
              }
          }
        return true;
      }

    private:
      const std::vector<TriangleMesh>   &avoid;
      std::vector<std::pair<Vec3, Vec3>> boxes;
      std::vector<char>                  closed;
    };

    /// The particles placed so far in the fill box, on a grid of cells of the largest
    /// diameter, and whether another fits: inside the box (whole), the region mesh, out of the
    /// excluded boxes, clear of the particles placed and of the walls.
    class PlacedParticles
    {
    public:
      PlacedParticles(const FillRegion &f, double r_big, long wanted, const WallClearance &walls)
        : f(f), extent(f.box_max - f.box_min), walls(walls)
      {
        const double cell = 2 * r_big;
        n[0] = std::max(1L, long(extent[0] / cell)), n[1] = std::max(1L, long(extent[1] / cell)),
        n[2] = std::max(1L, long(extent[2] / cell));
        if (double(n[0]) * n[1] * n[2] > 5e7)
          throw InputError("particle generation", "the fill box is too large for the particle size (more than 5e7 cells)");
        grid.resize(n[0] * n[1] * n[2]);
        placed.reserve(wanted);
        placed_radii.reserve(wanted);
      }

      bool fits(const Vec3 &p, double r) const
      {
        for (int d = 0; d < 3; ++d)
          if (!(p[d] >= f.box_min[d] + r && p[d] <= f.box_max[d] - r))
            return false;
        if (f.inside && !inside_mesh(*f.inside, p))
          return false;
        const double reach = f.centres_in ? 0.0 : r; // a level's centres, else whole spheres
        if (f.centres_in && !((p.array() >= f.centres_in->first.array()).all() && (p.array() <= f.centres_in->second.array()).all()))
          return false;
        for (const auto &[lo, hi] : f.exclude)
          if ((p.array() > lo.array() - reach).all() && (p.array() < hi.array() + reach).all())
            return false;
        const long ci = cell_of(p, 0), cj = cell_of(p, 1), ck = cell_of(p, 2);
        for (long c = std::max(0L, ck - 1); c <= std::min(n[2] - 1, ck + 1); ++c)
          for (long b = std::max(0L, cj - 1); b <= std::min(n[1] - 1, cj + 1); ++b)
            for (long a = std::max(0L, ci - 1); a <= std::min(n[0] - 1, ci + 1); ++a)
              for (int q : grid[(c * n[1] + b) * n[0] + a])
                if ((placed[q] - p).squaredNorm() < (r + placed_radii[q]) * (r + placed_radii[q]))
                  return false;
        return walls.clear(p, r);
      }

      void add(const Vec3 &p, double r)
      {
        grid[(cell_of(p, 2) * n[1] + cell_of(p, 1)) * n[0] + cell_of(p, 0)].push_back(int(placed.size()));
        placed.push_back(p);
        placed_radii.push_back(r);
      }

      const std::vector<Vec3>   &positions() const { return placed; }
      const std::vector<double> &radii() const { return placed_radii; }
      std::size_t                cells() const { return grid.size(); }

      /// Point @p k of the 4 x 4 x 4 set in grid cell @p c, at a random offset in its
      /// sub-cell (the sweep's).
      Vec3 sweep_point(long c, int k, std::mt19937_64 &rng) const
      {
        const long idx[3] = {c % n[0], (c / n[0]) % n[1], c / (n[0] * n[1])};
        const int  sub[3] = {k % 4, (k / 4) % 4, k / 16};
        Vec3       p;
        for (int d = 0; d < 3; ++d)
          p[d] = f.box_min[d] + extent[d] * (double(idx[d]) + (sub[d] + uniform01(rng)) / 4) / double(n[d]);
        return p;
      }

    private:
      const FillRegion             &f;
      const Vec3                    extent;
      long                          n[3];
      std::vector<Vec3>             placed;
      std::vector<double>           placed_radii;
      const WallClearance          &walls;
      std::vector<std::vector<int>> grid;
      long cell_of(const Vec3 &p, int d) const { return std::clamp(long((p[d] - f.box_min[d]) / extent[d] * n[d]), 0L, n[d] - 1); }
    };

    /// Near saturation random positions almost never fit (the free volume is a few per cent of
    /// the box): in the knife-bed's fill box random draws stall at 11,193 pellets of 27.5 mm.
    /// Then the placement sweeps the box instead: the grid cells in a random order, in each a
    /// 4 x 4 x 4 set of points with a random offset each, every point that fits taken. Passes
    /// repeat with new offsets until one places nothing (12,417 in that box, a solid fraction of
    /// 0.35). Both stages draw from the seed: the same bed every time.
    struct Sweep
    {
      bool              on = false;
      std::vector<long> cells; ///< this pass' order
      std::size_t       next_cell = 0;
      int               next_point = 64;
      long              placed_this_pass = 0;

      /// The next point to try; false: a whole pass placed nothing.
      bool next(const PlacedParticles &bed, std::mt19937_64 &rng, Vec3 &p)
      {
        for (;;)
          {
            if (next_point == 64)
              {
                next_point = 0;
                if (next_cell == cells.size())
                  {
                    if (on && placed_this_pass == 0)
                      return false;
                    on = true, placed_this_pass = 0, next_cell = 0;
                    cells.resize(bed.cells());
                    for (std::size_t c = 0; c < bed.cells(); ++c)
                      cells[c] = long(c);
                    for (std::size_t c = bed.cells(); c > 1; --c) // Fisher-Yates with our own draws
                      std::swap(cells[c - 1], cells[std::size_t(uniform01(rng) * double(c))]);
                  }
                ++next_cell;
              }
            p = bed.sweep_point(cells[next_cell - 1], next_point++, rng);
            return true;
          }
      }
    };

  } // namespace

  double expected_particles(const FillRegion &f)
  {
    if (f.count > 0)
      return double(f.count);
    const Vec3 lo_box = f.centres_in ? f.centres_in->first.cwiseMax(f.box_min) : f.box_min; // a level's region
    const Vec3 hi_box = f.centres_in ? f.centres_in->second.cwiseMin(f.box_max) : f.box_max;
    double     region_volume = f.inside ? std::abs(f.inside->volume()) : (hi_box - lo_box).prod();
    for (const auto &[lo, hi] : f.exclude) // (the solid fraction is of the region left)
      region_volume -= (hi.cwiseMin(hi_box) - lo.cwiseMax(lo_box)).cwiseMax(0.0).prod();
    return f.solid_fraction * region_volume / std::max(f.sizes.mean_volume(), 1e-300);
  }

  long fill_region(Simulation &sim, const FillRegion &f)
  {
    const double r_big  = f.sizes.largest();
    const Vec3   extent = f.box_max - f.box_min;
    if (!(r_big > 0) || !(extent.array() > 2 * r_big).all())
      throw InputError("particle generation", "the fill box must be larger than a particle diameter in every direction");
    auto  &P = sim.particles();
    double r_grid = r_big; // a level's neighbours include the finer levels' particles
    if (f.centres_in)
      for (std::size_t i = 0; i < P.size(); ++i)
        r_grid = std::max(r_grid, P.radius[i]);
    // a level draws its positions in its centres' box, else the spheres in the fill box
    const Vec3 draw_lo = f.centres_in ? f.centres_in->first.cwiseMax(f.box_min) : f.box_min;
    const Vec3 draw_hi = f.centres_in ? f.centres_in->second.cwiseMin(f.box_max) : f.box_max;

    // Random sequential addition: each particle at a uniformly random position that overlaps
    // no particle placed before it (a cell grid finds the neighbours), like LIGGGHTS'
    // insert/pack; near saturation a sweep of the box (Sweep)
    const WallClearance walls(f.avoid, r_big);
    const long          wanted = std::lround(expected_particles(f));
    PlacedParticles     bed(f, r_grid, wanted, walls);
    const std::size_t   first_new = f.centres_in ? P.size() : 0;
    for (std::size_t i = 0; i < first_new; ++i)
      bed.add(Vec3(P.x[i], P.y[i], P.z[i]), P.radius[i]);
    std::mt19937_64     rng(f.seed);
    Sweep               sweep;
    constexpr int       max_attempts = 20000;
    for (long k = 0; k < wanted; ++k)
      {
        const double r  = f.sizes.sample(rng);
        bool         ok = false;
        Vec3         p;
        for (int attempt = 0; attempt < max_attempts && !ok && !sweep.on; ++attempt)
          {
            for (int d = 0; d < 3; ++d)
              if (f.centres_in)
                {
                  const double lo = std::max(draw_lo[d], f.box_min[d] + r), hi = std::min(draw_hi[d], f.box_max[d] - r);
                  p[d]            = lo + (hi - lo) * uniform01(rng);
                }
              else
                p[d] = f.box_min[d] + r + (extent[d] - 2 * r) * uniform01(rng);
            ok = bed.fits(p, r);
          }
        while (!ok && sweep.next(bed, rng, p))
          ok = bed.fits(p, r);
        if (!ok)
          throw InputError("particle generation",
                           "bed seed " + std::to_string(f.seed) + ": could place only " + std::to_string(k) + " of " +
                             std::to_string(wanted) +
                             " particles without overlap (random placement with a sweep of the free space "
                             "saturates near a solid fraction of 0.35); reduce Count or Solid fraction, or "
                             "enlarge the region");
        sweep.placed_this_pass += sweep.on;
        bed.add(p, r);
      }

    std::int64_t next_id = 0;
    for (auto id : P.id)
      next_id = std::max(next_id, id + 1);
    const double density = sim.materials().at(f.material).density;
    const auto  &placed  = bed.positions();
    for (std::size_t k = first_new; k < placed.size(); ++k)
      {
        const std::size_t i = P.add(next_id++, placed[k][0], placed[k][1], placed[k][2], bed.radii()[k], density,
                                    f.material);
        P.vx[i] = f.velocity[0], P.vy[i] = f.velocity[1], P.vz[i] = f.velocity[2];
      }
    return wanted;
  }

  // ---------------------------------------------------------------------------------------------
  // A bed file: "ABRBED02", the particle count n (uint64), the time (double), then per field n
  // values (x y z, v, w, radius, mass as doubles; material as int; id as int64), and last the
  // 16 hex digits of the FNV-1a hash of all before it. The count is checked against the file's
  // size before anything is allocated, the checksum before anything is read as particles.
  namespace
  {
    constexpr char        bed_magic[9]     = "ABRBED02";
    constexpr char        old_bed_magic[9] = "ABRBED01";
    constexpr std::size_t bed_header       = 8 + sizeof(std::uint64_t) + sizeof(double);
    constexpr std::size_t bytes_per_particle = 11 * sizeof(double) + sizeof(int) + sizeof(std::int64_t);
    constexpr std::size_t checksum_digits    = 16;

    template <typename T>
    void append(std::string &out, const T *data, std::size_t n)
    {
      out.append(reinterpret_cast<const char *>(data), n * sizeof(T));
    }

    template <typename T>
    void take(const std::string &in, std::size_t &at, T *data, std::size_t n)
    {
      std::memcpy(data, in.data() + at, n * sizeof(T));
      at += n * sizeof(T);
    }
  } // namespace

  void save_bed(const Simulation &sim, const std::string &path)
  {
    const ParticleStore P = sim.gather_particles(); // sorted by id: the same file on any ranks
    if (sim.parallel().rank() != 0)
      return;
    const std::uint64_t n = P.size();
    const double        t = sim.time();
    std::string         bytes(bed_magic, 8);
    bytes.reserve(bed_header + n * bytes_per_particle + checksum_digits);
    append(bytes, &n, 1);
    append(bytes, &t, 1);
    for (const auto *a : {&P.x, &P.y, &P.z, &P.vx, &P.vy, &P.vz, &P.wx, &P.wy, &P.wz, &P.radius, &P.mass})
      append(bytes, a->data(), n);
    append(bytes, P.material.data(), n);
    append(bytes, P.id.data(), n);
    bytes += io::fnv1a_hex(bytes);
    io::write_file_atomically(path, bytes); // a crash never leaves half a bed
  }

  void load_bed(Simulation &sim, const std::string &path)
  {
    std::ifstream in(path, std::ios::binary);
    if (!in)
      throw InputError(path, "cannot open bed file");
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (bytes.compare(0, 8, old_bed_magic) == 0)
      throw InputError(path, "a bed file of an older abrade (format 01, without a checksum): delete it, the bed is "
                             "made again");
    if (bytes.size() < bed_header + checksum_digits || bytes.compare(0, 8, bed_magic) != 0)
      throw InputError(path, "not an abrade bed file (bad header)");
    std::uint64_t n;
    double        t;
    std::size_t   at = 8;
    take(bytes, at, &n, 1);
    take(bytes, at, &t, 1);
    if (!std::isfinite(t))
      throw InputError(path, "corrupt bed file (its time is not a finite number)");
    const std::size_t body = bytes.size() - bed_header - checksum_digits;
    if (body % bytes_per_particle != 0 || n != body / bytes_per_particle)
      throw InputError(path, "corrupt bed file: it announces " + std::to_string(n) + " particles, its size of " +
                               std::to_string(bytes.size()) + " bytes holds " +
                               std::to_string(double(body) / bytes_per_particle) + " (cut short or changed)");
    if (n == 0)
      throw InputError(path, "the bed holds no particles");
    if (io::fnv1a_hex(bytes.substr(0, bytes.size() - checksum_digits)) != bytes.substr(bytes.size() - checksum_digits))
      throw InputError(path, "corrupt bed file (its checksum does not match: changed or cut); delete it, the bed is "
                             "made again");
    BedColumns bed;
    bed.resize(n);
    for (auto *c : bed.doubles())
      take(bytes, at, c->data(), n);
    take(bytes, at, bed.material.data(), n);
    take(bytes, at, bed.id.data(), n);
    // what a checksum cannot catch (a file written by other code)
    replace_particles(sim, path, bed, [&](std::size_t k) {
      return "particle " + std::to_string(k) + " (id " + std::to_string(bed.id[k]) + ")";
    });
  }

  void replace_particles(Simulation &sim, const std::string &path, const BedColumns &bed,
                         const std::function<std::string(std::size_t)> &name_of)
  {
    const std::size_t n = bed.size();
    if (n == 0)
      throw InputError(path, "the bed holds no particles");
    const int   n_mat = static_cast<int>(sim.materials().size());
    const auto &box   = sim.settings();
    const auto  columns = bed.doubles();
    for (std::size_t k = 0; k < n; ++k)
      {
        if (bed.material[k] < 0 || bed.material[k] >= n_mat)
          throw InputError(path, name_of(k) + " has unknown material " + std::to_string(bed.material[k]));
        for (const auto *c : columns)
          if (!std::isfinite((*c)[k]))
            throw InputError(path, name_of(k) + " has a value that is not a finite number");
        if (!(bed.radius[k] >= 1e-6 && bed.radius[k] <= 10) || !(bed.mass[k] > 0))
          throw InputError(path, name_of(k) + " has a radius of " + std::to_string(bed.radius[k]) +
                                   " m (a bed's are 1 um to 10 m: millimetres read as metres?) or a mass that is "
                                   "not positive");
        const double p[3] = {bed.x[k], bed.y[k], bed.z[k]};
        for (int d = 0; d < 3; ++d)
          if (p[d] < box.domain_min[d] || p[d] > box.domain_max[d])
            throw InputError(path, name_of(k) + " lies outside Simulation/Domain (a bed made for another domain?)");
      }
    std::vector<std::int64_t> sorted = bed.id;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
      throw InputError(path, "particle id " + std::to_string(*std::adjacent_find(sorted.begin(), sorted.end())) +
                               " comes twice");
    // two centres (nearly) on one point: the contact between them has no direction and the
    // first step gives NaN. By x, each against those within the tolerance of it.
    std::vector<std::size_t> by_x(n);
    for (std::size_t k = 0; k < n; ++k)
      by_x[k] = k;
    std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) { return bed.x[a] < bed.x[b]; });
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = a + 1; b < n; ++b)
        {
          const std::size_t i = by_x[a], j = by_x[b];
          const double      tolerance = 1e-6 * std::min(bed.radius[i], bed.radius[j]);
          if (bed.x[j] - bed.x[i] > 1e-6 * 10) // (radii <= 10 m)
            break;
          if (std::abs(bed.x[j] - bed.x[i]) <= tolerance && std::abs(bed.y[j] - bed.y[i]) <= tolerance &&
              std::abs(bed.z[j] - bed.z[i]) <= tolerance)
            throw InputError(path, name_of(std::min(i, j)) + " and " + name_of(std::max(i, j)) +
                                     " have their centres on one point");
        }
    auto &P = sim.particles();
    P.clear();
    for (std::size_t k = 0; k < n; ++k)
      {
        const double r       = bed.radius[k];
        const double density = bed.mass[k] / (4.0 / 3.0 * M_PI * r * r * r);
        const auto   i       = P.add(bed.id[k], bed.x[k], bed.y[k], bed.z[k], r, density, bed.material[k]);
        P.mass[i] = bed.mass[k], P.inv_mass[i] = 1 / bed.mass[k];
        P.vx[i] = bed.vx[k], P.vy[i] = bed.vy[k], P.vz[i] = bed.vz[k];
        P.wx[i] = bed.wx[k], P.wy[i] = bed.wy[k], P.wz[i] = bed.wz[k];
      }
  }
} // namespace abrade::dem
