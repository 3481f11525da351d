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
// (gravity, particle-particle, particle-wall Hertz-Mindlin), half kick, rigid-body walls, the
// mechanisms that drive walls, hooks, checks. Neighbours come from a cell list with a Verlet skin, rebuilt when any particle (or
// wall) has moved far enough to bring a new pair into contact; particles are sorted by cell at
// each rebuild. Threads (OpenMP) work over particles; the work is cut into a fixed number of
// shares with a force buffer each, so the results do not depend on how many threads work on the
// shares; on a busy machine fewer of them may (thread_governor.h).
//
// Under `mpirun -np N` the particles are spread over the ranks by recursive coordinate bisection
// (decomposition.h): each rank integrates the particles it owns and keeps ghost copies of the
// other ranks' particles within one interaction range (2 r_max + skin) of its box, updated every
// step. A pair across a domain boundary is computed on both ranks, each keeping the force on its
// own particle, so no forces travel back. At every neighbour-list build the particles that left
// a box move to their new owner with their contact histories, and the boxes are cut again when
// the particle counts differ by more than Settings::rebalance_threshold. Walls are replicated:
// their loads are summed over the ranks every step, their per-triangle fields when read.
// Every rank must add the same particles; setup() spreads the ones added since its last call.
#include <abrade/dem/contact_log.h>
#include <abrade/dem/material.h>
#include <abrade/dem/parallel.h>
#include <abrade/dem/particles.h>
#include <abrade/dem/wall.h>

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abrade::dem
{
  class ThreadGovernor;
  class WallDriver;

  struct Settings
  {
    Vec3   gravity           = Vec3(0, 0, -9.81); ///< [m/s^2]
    double time_step         = 0;   ///< [s]; 0: rayleigh_fraction of the Rayleigh time step
    double rayleigh_fraction = 0.2; ///< used when time_step = 0
    /// Characteristic impact speed for the time-step check (Hertz contact time) [m/s].
    double characteristic_velocity = 1.5;
    double skin = 0;                ///< Verlet skin [m]; 0: 0.2 x smallest radius
    DampingModel damping = DampingModel::edem;
    ContactModel contact; ///< rolling and cohesion sub-models (contact_law.h)
    int    threads = 0;             ///< at most this many threads work; 0: all available
    /// The shares each step's work is cut into (0: as many as threads). The shares and the order
    /// their results are summed in fix the arithmetic: a run gives the same bits with any number
    /// of threads working on the same shares, so a fixed count makes a case's results the same
    /// on any machine. More threads than shares are not used.
    int    shares = 0;
    /// Work with fewer of the threads while that is faster (a busy machine; thread_governor.h).
    /// The results do not depend on it: the work is cut into `shares` shares either way.
    bool   adapt_threads = true;
    /// The governor of an earlier simulation (Simulation::thread_governor()), to go on with
    /// what it found out about the machine: the many short simulations of a lifetime run's
    /// cycles end before a fresh governor would adapt. Used when it governs as many threads
    /// as this simulation has and adapt_threads is on; unset: a fresh one.
    std::shared_ptr<ThreadGovernor> governor;
    /// Particles outside this box are lost.
    Vec3   domain_min = Vec3::Constant(-1e3), domain_max = Vec3::Constant(1e3);
    /// Overlap beyond this fraction of the smaller radius is reported.
    double max_overlap_fraction = 0.2;
    /// What to do with a lost particle or an excessive overlap: stop, or warn and go on
    /// (lost particles are then removed). NaN always stops.
    bool   stop_on_error = true;
    /// Spread the particles over the MPI ranks when running under mpirun with several ranks.
    bool   distribute = true;
    /// The ranks to spread them over when distributing (a group of Parallel::split(): one bed
    /// of an ensemble); unset: all of them (Parallel::world()).
    std::optional<Parallel> ranks;
    /// Cut the domains again when the largest rank owns more than this times the mean count.
    double rebalance_threshold = 1.1;
  };

  struct StepStatistics
  {
    long   steps = 0, rebuilds = 0;
    long   rebalances = 0, migrated = 0; ///< domain cuts; particles that changed rank (this rank)
    long   nearby_migrations = 0;        ///< migrations among neighbouring boxes only (no all-to-all)
    long   ghost_steps = 0;              ///< sum over steps of this rank's ghost count
    double loop_seconds = 0;
    long   particle_steps = 0;
    long   thread_steps = 0; ///< sum over steps of the threads that worked on them
    long   team_changes = 0; ///< times the governor kept a different number of threads
  };

  /// Threads used when Settings::threads is 0: what OpenMP offered when the program started.
  int default_thread_count();
  /// The same shared by the ranks of @p ranks that run on this machine (under mpirun -np 2 on
  /// 16 cores: 8 each). Collective.
  int default_thread_count(const Parallel &ranks);

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
    /// A mechanism that moves some of the walls (wall_driver.h), called every step after the
    /// rigid-body walls.
    void add_driver(std::shared_ptr<WallDriver> driver);
    /// The particles owned by this rank (all of them in a serial run). Non-const access drops
    /// the ghost layer (the next step rebuilds it), so particles may be added or moved.
    ParticleStore       &particles();
    const ParticleStore &particles() const { return store; }
    /// The ranks the particles are spread over (serial: one).
    const Parallel &parallel() const;
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
    /// Kinetic energy of all particles (collective under MPI, like the others below) [J].
    double kinetic_energy() const;
    /// Number of particles on all ranks.
    std::size_t n_particles() const;
    /// Mass of all particles whose centre lies above @p z [kg] (a grab's payload).
    double mass_above(double z) const;
    /// Height (z) of the particles' centre of mass [m] (0 without particles): how a bed packs.
    double centre_of_mass_height() const;
    /// Radius of the largest particle on any rank [m] (0 without particles).
    double largest_radius() const;
    /// Particle-steps per second between two statistics: all ranks' particle-steps over the
    /// slowest rank's time in the loop.
    double throughput(const StepStatistics &before, const StepStatistics &after) const;
    /// Every particle of every rank, sorted by id, on rank 0 (empty elsewhere).
    ParticleStore gather_particles() const;
    std::size_t n_walls() const { return walls.size(); }
    Wall       &wall(std::size_t w) { return walls[w]; }
    const Wall &wall(std::size_t w) const { return walls[w]; }
    int  wall_index(const std::string &name) const;
    const std::vector<Material> &materials() const { return mats; }
    const PairCoefficients &pair(int a, int b) const { return coefficients[a * mats.size() + b]; }
    const StepStatistics &statistics() const { return stats; }
    /// The shares each step's work is cut into (Settings::shares, or the thread count).
    int shares() const;
    /// The most threads that work on them (Settings::threads or the machine's, at most shares()).
    int threads() const;
    /// Works with @p team of shares() from now on, without adapting (tests, benchmarks).
    void pin_thread_team(int team);
    /// What chooses how many threads work (for Settings::governor of the next simulation).
    std::shared_ptr<ThreadGovernor> thread_governor() const;
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
    std::vector<std::shared_ptr<WallDriver>> drivers;
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
    // domain decomposition (domain_exchange.cc)
    void distribute_new_particles();
    void drop_ghosts();
    void carry_pair_histories();
    void rebalance_and_migrate();
    void exchange_ghosts(double cutoff);
    void sort_ghosts();
    void update_ghosts();
    void permute_wall_histories(const std::vector<std::size_t> &order);
    /// Rigid-body walls: velocity updates from this step's loads (a body's walls together).
    void accelerate_walls(double dt);
    /// Sets the walls (and the drivers) to @p phase.
    void enter_phase(const std::string &phase);
    bool needs_rebuild() const;
    void compute_forces();
    /// Pair and wall forces with the contact law of Settings::contact (contact_law.h).
    void pair_forces();
    void wall_forces();
    template <bool rotation, class Law>
    void pair_forces_with();
    template <bool rotation, class Law>
    void wall_forces_with();
    void check_step();
    void warn(const std::string &w);
    // set-up (simulation.cc)
    /// Refuses a rigid body whose walls carry no mass.
    void check_rigid_body_masses() const;
    /// The pair coefficients of every pair of materials.
    void tabulate_pair_coefficients();
    /// Inverse inertias; a non-rotating material's particles get none (and no spin).
    void set_rotational_inertia();
    /// The time step (Settings, or a fraction of the Rayleigh step), with a warning where it
    /// exceeds a tenth of the Hertz contact time of the smallest particle (radius @p r_min).
    void choose_time_step(double r_min);
    // the time step's parts (simulation.cc)
    /// The rebuild criterion and a lost or NaN particle (@p bad, else the largest long) agreed
    /// by all ranks: a NaN stops the run, a particle out of the domain is removed with a warning
    /// (or stops it with Settings::stop_on_error).
    void agree_on_the_step(double max_d2, long bad);
    /// Each wall triangle's normal and tangential impulse from this step's contacts.
    void add_triangle_impulses(double dt);
    /// The step's time and particle counts, and the thread governor's measurement.
    void count_the_step(std::chrono::steady_clock::time_point start, std::size_t particles);
  };
} // namespace abrade::dem
