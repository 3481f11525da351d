// How big a run will be before it starts: particles, steps, memory and wall time, and the runs
// refused for it (run_size.h).
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/run_size.h>
#include <abrade/dem/generation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

namespace abrade::coupling
{
  namespace
  {
    /// A rate this code reaches on one core of an ordinary machine (docs/benchmarks.md measures
    /// 0.7-1.4e7 on the knife-bed): the wall-time estimate is an order of magnitude, no more.
    constexpr double particle_steps_per_core_second = 5e6;
    constexpr double bytes_per_particle             = 1000;

    std::string g(double x) { return io::format_number(x, 3); }
  } // namespace

  RunSize estimate_run_size(const DemCase &c)
  {
    RunSize      r;
    const auto  &fill  = c.fill;
    r.particles        = dem::expected_particles(fill); // a multi-level bed's bulk: less the levels
    for (const auto &level : c.finer_levels)
      r.particles += dem::expected_particles(level.fill);
    const auto  &sizes = c.finer_levels.empty() ? fill.sizes : c.finer_levels.front().fill.sizes; // the smallest
    const double r_min = sizes.kind == dem::SizeDistribution::Kind::constant || !(sizes.min > 0) ? sizes.radius : sizes.min;
    const auto  &m     = c.particle_material;
    const double rayleigh =
      M_PI * r_min * std::sqrt(m.density / m.shear_modulus()) / (0.1631 * m.poisson_ratio + 0.8766);
    r.time_step = c.settings.time_step > 0 ? c.settings.time_step : c.settings.rayleigh_fraction * rayleigh;
    for (const auto &phase : c.phases)
      r.simulated_time += phase.second;
    if (c.bed_file.empty() || !std::ifstream(c.bed_file)) // the bed is generated and settled
      r.simulated_time += c.settle_max_time;
    r.steps          = r.simulated_time / r.time_step;
    r.particle_steps = r.particles * r.steps;
    r.bytes          = r.particles * bytes_per_particle;
    return r;
  }

  double available_memory()
  {
    std::ifstream in("/proc/meminfo");
    for (std::string key; in >> key;)
      {
        double      kb = 0;
        std::string unit;
        in >> kb >> unit;
        if (key == "MemAvailable:")
          return kb * 1024;
      }
    return 0;
  }

  void check_run_size(const DemCase &c, ParameterFile &file)
  {
    const RunSize r = estimate_run_size(c);
    if (!std::isfinite(r.particle_steps) || (c.max_particle_steps > 0 && r.particle_steps > c.max_particle_steps))
      {
        const double cores = std::max(1u, std::thread::hardware_concurrency());
        const double hours = r.particle_steps / (particle_steps_per_core_second * cores) / 3600;
        file.fail({"Simulation"}, "Maximum particle-steps",
                  "one run needs about " + g(r.particle_steps) + " particle-steps (" + g(r.particles) +
                    " particles x " + g(r.steps) + " steps of " + g(r.time_step) + " s over " + g(r.simulated_time) +
                    " s), more than the limit " + g(c.max_particle_steps) + ": about " + g(hours) + " hours on " +
                    g(cores) + " cores. Check Time step, the particles' Density and Shear modulus (the Rayleigh "
                    "time step), Radius and Count; or raise Maximum particle-steps to run it anyway");
      }
    const double available = available_memory();
    if (available > 0 && r.bytes > available)
      file.fail({"Particles", "Generation"}, "Count",
                "about " + g(r.particles) + " particles need about " + g(r.bytes / 1e9) + " GB, this machine has " +
                  g(available / 1e9) + " GB available");
    // a bed that cannot be filled is said before anything is meshed or settled (after the
    // memory: a run too large to hold is said as such): random placement with a sweep of the
    // free space saturates near a solid fraction of 0.35 in an empty box (generation.cc), less
    // where walls and the part take room
    std::vector<const dem::FillRegion *> fills = {&c.fill}; // and a multi-level bed's finer levels
    for (const auto &level : c.finer_levels)
      fills.push_back(&level.fill);
    for (const dem::FillRegion *fill : fills)
      {
        double box = (fill->box_max - fill->box_min).prod();
        for (const auto &[lo, hi] : fill->exclude) // (a level's region: its box less the finer levels')
          box -= (hi.cwiseMin(fill->box_max) - lo.cwiseMax(fill->box_min)).cwiseMax(0.0).prod();
        const double fraction = fill->count > 0 && box > 0 ? double(fill->count) * fill->sizes.mean_volume() / box
                                                           : fill->solid_fraction;
        if (fraction > 0.37)
          file.fail({"Particles", "Generation"}, fill->count > 0 ? "Count" : "Solid fraction",
                    (fill->count > 0 ? g(double(fill->count)) + " particles of " + g(fill->sizes.mean_volume()) +
                                         " m^3 each fill " + g(fraction) + " of the Region box (" + g(box) + " m^3)"
                                     : "a solid fraction of " + g(fraction)) +
                      ": random placement saturates near 0.35 in an empty box (less where walls and the part take "
                      "room); lower Count (or Solid fraction) or enlarge the Region");
      }
  }
} // namespace abrade::coupling
