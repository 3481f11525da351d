#pragma once
// Small set-ups shared by the DEM verification tests: one or two spheres, an optional flat wall.
#include <abrade/dem/generation.h>
#include <abrade/dem/simulation.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace abrade::dem::testing
{
  inline Settings quiet_settings(double dt, bool gravity = false)
  {
    Settings s;
    s.gravity              = gravity ? Vec3(0, 0, -9.81) : Vec3::Zero();
    s.time_step            = dt;
    s.threads              = 1;
    s.max_overlap_fraction = 1;
    return s;
  }

  /// Index of the particle with identifier @p id (particles are reordered by the cell sort).
  inline std::size_t index_of(const Simulation &sim, std::int64_t id)
  {
    const auto &ids = sim.particles().id;
    for (std::size_t i = 0; i < ids.size(); ++i)
      if (ids[i] == id)
        return i;
    return ids.size();
  }

  /// Analytic Hertz impact (shared/reference/verification.md).
  struct HertzImpact
  {
    double delta_max, force_max, contact_time;
    HertzImpact(double m_eff, double r_eff, double e_star, double v)
    {
      delta_max    = std::pow(15 * m_eff * v * v / (16 * e_star * std::sqrt(r_eff)), 0.4);
      force_max    = 4.0 / 3.0 * e_star * std::sqrt(r_eff) * std::pow(delta_max, 1.5);
      contact_time = 2.868 * std::pow(m_eff * m_eff / (r_eff * e_star * e_star * v), 0.2);
    }
  };

  inline double e_star(const Material &a, const Material &b)
  {
    return 1 / ((1 - a.poisson_ratio * a.poisson_ratio) / a.youngs_modulus +
                (1 - b.poisson_ratio * b.poisson_ratio) / b.youngs_modulus);
  }

  /// Slope (degrees) of a heap's flank: the highest particle in rings around the heap's axis,
  /// fitted by a straight line between 20 % and 80 % of the heap's radius (the distance from
  /// the axis within which 97 % of the particles lie: a few that rolled away do not stretch it).
  inline double heap_angle(const ParticleStore &P)
  {
    double cx = 0, cy = 0;
    for (std::size_t i = 0; i < P.size(); ++i)
      cx += P.x[i], cy += P.y[i];
    cx /= P.size(), cy /= P.size();
    std::vector<double> d(P.size());
    for (std::size_t i = 0; i < P.size(); ++i)
      d[i] = std::hypot(P.x[i] - cx, P.y[i] - cy);
    std::nth_element(d.begin(), d.begin() + long(0.97 * (d.size() - 1)), d.end());
    const double r_max = d[long(0.97 * (d.size() - 1))];
    const int           bins = 12;
    std::vector<double> top(bins, 0.0);
    for (std::size_t i = 0; i < P.size(); ++i)
      {
        const int b = int(std::hypot(P.x[i] - cx, P.y[i] - cy) / r_max * bins);
        if (b < bins)
          top[b] = std::max(top[b], P.z[i]);
      }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int    n  = 0;
    for (int b = bins / 5; b < 4 * bins / 5; ++b)
      {
        const double r = (b + 0.5) * r_max / bins;
        sx += r, sy += top[b], sxx += r * r, sxy += r * top[b], ++n;
      }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    return std::atan(-slope) * 180 / M_PI;
  }

  inline double sphere_mass(double r, double rho) { return rho * 4.0 / 3.0 * M_PI * r * r * r; }

  /// A poured heap (the angle-of-repose tests): 800 grains of 9-11 mm radius dropped from a
  /// column 16 cm wide onto a floor of the same material, interaction @p i between all; its
  /// angle after 1.5 s of pouring and after 0.5 s more, and its kinetic energy at the end.
  struct PouredHeap
  {
    double after_pour, after_rest, kinetic_energy;
  };
  inline PouredHeap pour_heap(Settings s, const Material &grain, const Interaction &i);

  /// A large flat wall (the plane z = 0, normal +z) made of triangles no longer than @p h.
  inline Wall floor_wall(int material, double size = 1.0, double h = 0)
  {
    Wall w;
    w.name     = "floor";
    w.mesh     = primitives::plate(Vec3::Zero(), 2, size, size, h);
    w.material = material;
    return w;
  }

  /// Records what a single-contact impact does: overlap, force, contact start/end (linearly
  /// interpolated) and the velocities after separation.
  struct ImpactRecorder
  {
    double max_overlap = 0, max_force = 0, t_start = -1, t_end = -1;
    double prev_overlap = -1, prev_t = 0;
    void   record(double t, double overlap, double force)
    {
      max_overlap = std::max(max_overlap, overlap);
      max_force   = std::max(max_force, force);
      if (prev_overlap <= 0 && overlap > 0 && t_start < 0)
        t_start = prev_t + (t - prev_t) * (-prev_overlap) / (overlap - prev_overlap);
      if (prev_overlap > 0 && overlap <= 0 && t_end < 0)
        t_end = prev_t + (t - prev_t) * prev_overlap / (prev_overlap - overlap);
      prev_overlap = overlap, prev_t = t;
    }
    double contact_time() const { return t_end - t_start; }
  };

  inline PouredHeap pour_heap(Settings s, const Material &grain, const Interaction &i)
  {
    Simulation sim(s);
    const int  mg = sim.add_material(grain), mw = sim.add_material(grain);
    sim.set_interaction(mg, mg, i);
    sim.set_interaction(mg, mw, i);
    sim.add_wall(floor_wall(mw, 2.0));
    FillRegion f;
    f.box_min = Vec3(-0.08, -0.08, 0.02), f.box_max = Vec3(0.08, 0.08, 0.6);
    f.sizes.kind = SizeDistribution::Kind::uniform, f.sizes.min = 0.009, f.sizes.max = 0.011;
    f.count = 800, f.seed = 11;
    fill_region(sim, f);
    sim.setup();
    sim.run_phase("pour", 1.5);
    PouredHeap h;
    h.after_pour = heap_angle(sim.particles());
    sim.run_phase("rest", 0.5);
    h.after_rest     = heap_angle(sim.particles());
    h.kinetic_energy = sim.kinetic_energy();
    return h;
  }
} // namespace abrade::dem::testing
