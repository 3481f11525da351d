#pragma once
// The DEM engine: particles, walls, materials, and the time loop.
//
//   Simulation sim(settings);
//   int pellet = sim.add_material(...), steel = sim.add_material(...);
//   sim.set_interaction(pellet, steel, {0.6, 0.4, 0});
//   sim.particles().add(...);  sim.add_wall(...);
//   sim.setup();
//   sim.run_phase("penetration", 0.2667);
//
// Each step is velocity Verlet: half kick, drift (walls move too), neighbour-list check, forces
// (gravity, particle-particle, particle-wall Hertz-Mindlin), half kick, rigid-body walls, hooks,
// checks. Neighbours come from a cell list with a Verlet skin, rebuilt when any particle (or
// wall) has moved far enough to bring a new pair into contact; particles are sorted by cell at
// each rebuild. Threads (OpenMP) work over particles; pair forces go to per-thread buffers.
#include <abrade/dem/contact_log.h>
#include <abrade/dem/material.h>
#include <abrade/dem/particles.h>
#include <abrade/dem/wall.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  struct Settings
  {
    Vec3   gravity           = Vec3(0, 0, -9.81); ///< [m/s^2]
    double time_step         = 0;   ///< [s]; 0: rayleigh_fraction of the Rayleigh time step
    double rayleigh_fraction = 0.2; ///< used when time_step = 0
    /// Characteristic impact speed for the time-step check (Hertz contact time) [m/s].
    double characteristic_velocity = 1.5;
    double skin = 0;                ///< Verlet skin [m]; 0: 0.2 x smallest radius
    DampingModel damping = DampingModel::edem;
    int    threads = 0;             ///< 0: all available
    /// Particles outside this box are lost.
    Vec3   domain_min = Vec3::Constant(-1e3), domain_max = Vec3::Constant(1e3);
    /// Overlap beyond this fraction of the smaller radius is reported.
    double max_overlap_fraction = 0.2;
    /// What to do with a lost particle or an excessive overlap: stop, or warn and go on
    /// (lost particles are then removed). NaN always stops.
    bool   stop_on_error = true;
  };

  struct StepStatistics
  {
    long   steps = 0, rebuilds = 0;
    double loop_seconds = 0;
    long   particle_steps = 0;
  };

  /// Threads used when Settings::threads is 0: what OpenMP offered when the program started.
  int default_thread_count();

  class Simulation
  {
  public:
    explicit Simulation(const Settings &settings);
    Simulation(Simulation &&) noexcept;
    Simulation &operator=(Simulation &&) noexcept;
    ~Simulation();

    // --- set-up ---
    int  add_material(const Material &m);
    void set_interaction(int material_a, int material_b, const Interaction &i);
    int  add_wall(Wall wall);
    void add_hook(std::shared_ptr<StepHook> hook);
    ParticleStore       &particles() { return store; }
    const ParticleStore &particles() const { return store; }
    /// Precomputes pair coefficients, chooses the time step, builds neighbour lists. Call after
    /// the particles, walls and materials are in place, and again after adding particles.
    void setup();

    // --- running ---
    void step();
    /// Runs round(duration / dt) steps in the named phase (walls take that phase's velocity).
    void run_phase(const std::string &phase, double duration,
                   const std::function<void(const Simulation &)> &every_step = {});
    /// Runs (phase "settle", walls still) until the mean kinetic energy per particle is below
    /// @p ke_per_particle or @p max_time has passed; returns the time it took.
    /// @p progress is called every 100 steps.
    double settle(double ke_per_particle, double max_time,
                  const std::function<void(const Simulation &)> &progress = {});

    // --- state ---
    double time() const { return t; }
    double dt() const { return time_step; }
    long   step_number() const { return stats.steps; }
    const std::string &phase() const { return current_phase; }
    double rayleigh_time_step() const;
    double kinetic_energy() const;
    std::size_t n_walls() const { return walls.size(); }
    Wall       &wall(std::size_t w) { return walls[w]; }
    const Wall &wall(std::size_t w) const { return walls[w]; }
    int  wall_index(const std::string &name) const;
    const std::vector<Material> &materials() const { return mats; }
    const PairCoefficients &pair(int a, int b) const { return coefficients[a * mats.size() + b]; }
    const StepStatistics &statistics() const { return stats; }
    const Settings       &settings() const { return config; }
    /// Messages (warnings) collected so far; the caller decides where they are printed.
    std::vector<std::string> take_warnings();
    /// Current particle-particle contacts (pairs with positive overlap).
    std::size_t n_particle_contacts() const;

    void set_time(double time) { t = time; }

  private:
    Settings                                config;
    ParticleStore                           store;
    std::vector<Material>                   mats;
    std::vector<Interaction>                interactions; // n_mat x n_mat
    std::vector<bool>                       interaction_set;
    std::vector<PairCoefficients>           coefficients;
    std::vector<Wall>                       walls;
    std::vector<std::shared_ptr<StepHook>>  hooks;
    std::vector<std::string>                warnings;
    std::string                             current_phase;
    double                                  t         = 0;
    double                                  time_step = 0;
    double                                  skin      = 0;
    bool                                    is_set_up = false;
    bool                                    any_rotation = true;
    StepStatistics                          stats;

    struct Impl;
    std::unique_ptr<Impl> impl;

    void build_neighbour_lists();
    /// Rigid-body walls: velocity updates from this step's loads (a body's walls together).
    void accelerate_walls(double dt);
    bool needs_rebuild() const;
    void compute_forces();
    template <bool rotation>
    void pair_forces();
    template <bool rotation>
    void wall_forces();
    void check_step();
    void warn(const std::string &w);
  };
} // namespace abrade::dem
