// The DEM engine's time loop (simulation.h): set-up, integration, walls' motion and wear,
// checks. The steps it calls have files of their own: the neighbour lists with a Verlet skin
// (neighbour_lists.cc), the particle-particle forces (pair_forces.cc), the particle-wall forces
// (wall_forces.cc), the domain decomposition's exchanges (domain_exchange.cc).
#include <abrade/common/error.h>
#include <abrade/dem/contact_law.h>
#include <abrade/dem/wall_driver.h>
#include <abrade/dem/wall_motion_model.h>
#include "simulation_impl.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <type_traits>

namespace abrade::dem
{
  namespace
  {
    /// The name of a wall's motion (wall_motion_model.h; "" without one: its kind decides).
    std::string motion_name(const Wall &w) { return w.motion.model ? w.motion.model->name() : std::string(); }

    /// Half kick of a particle's spin: w += h_ii T (h_ii: half step / moment of inertia), then
    /// the rolling resistance (torque magnitude @p rolling, the contacts' sum of mu_r |F_n| R,
    /// opposed to w) slows the spin by h_ii rolling, but never reverses it. Applied as a torque
    /// vector -rolling w/|w| (EDEM's constant directional torque as written), it overshoots
    /// w = 0 whenever h_ii rolling > |w| and the spin chatters: for jammed pellets under kN
    /// normal forces the chatter reaches metres per second at the contact points, which Archard
    /// wear counts as sliding (a grab holding its payload wore 15x more at 4x the time step).
    inline void spin_kick(double &wx, double &wy, double &wz, double tx, double ty, double tz,
                          double rolling, double h_ii)
    {
      wx += h_ii * tx, wy += h_ii * ty, wz += h_ii * tz;
      const double w    = std::sqrt(wx * wx + wy * wy + wz * wz);
      const double stop = h_ii * rolling;
      const double keep = w > stop ? 1 - stop / w : 0.0;
      wx *= keep, wy *= keep, wz *= keep;
    }

    /// The arrays a half kick reads and writes (fetched again after each list build, which
    /// reorders them).
    struct KickArrays
    {
      double       *vx, *vy, *vz, *wx, *wy, *wz;
      const double *fx, *fy, *fz, *tx, *ty, *tz, *rolling, *inv_mass, *inv_inertia;
      explicit KickArrays(ParticleStore &P)
        : vx(P.vx.data()), vy(P.vy.data()), vz(P.vz.data()), wx(P.wx.data()), wy(P.wy.data()),
          wz(P.wz.data()), fx(P.fx.data()), fy(P.fy.data()), fz(P.fz.data()), tx(P.tx.data()),
          ty(P.ty.data()), tz(P.tz.data()), rolling(P.rolling.data()), inv_mass(P.inv_mass.data()),
          inv_inertia(P.inv_inertia.data())
      {}
      /// v += h F / m and, with rotation, the spin's half kick of particles @p begin .. @p end
      /// - 1. (A template: a run-time test in the loop keeps the compiler from vectorising it.)
      template <bool rotation>
      void kick_range(std::size_t begin, std::size_t end, double h) const
      {
        double *__restrict VX = vx, *__restrict VY = vy, *__restrict VZ = vz;
        const double *__restrict FX = fx, *__restrict FY = fy, *__restrict FZ = fz, *__restrict IM = inv_mass;
#pragma omp simd
        for (std::size_t i = begin; i < end; ++i)
          {
            const double im = IM[i];
            VX[i] += h * FX[i] * im, VY[i] += h * FY[i] * im, VZ[i] += h * FZ[i] * im;
          }
        if (rotation) // (inverse inertia 0: rotation off for the particle's material)
          {
            double *__restrict WX = wx, *__restrict WY = wy, *__restrict WZ = wz;
            const double *__restrict TX = tx, *__restrict TY = ty, *__restrict TZ = tz, *__restrict RL = rolling,
                                     *__restrict II = inv_inertia;
#pragma omp simd
            for (std::size_t i = begin; i < end; ++i)
              spin_kick(WX[i], WY[i], WZ[i], TX[i], TY[i], TZ[i], RL[i], h * II[i]);
          }
      }
    };

    /// First half of a velocity-Verlet step: half kick and drift of every particle. Returns
    /// the largest squared displacement since the last list build (@p x0, @p y0, @p z0) and
    /// the first particle outside the domain [@p lo, @p hi] (or the largest long). (Plain
    /// loops over each thread's share with restrict pointers: GCC 12 turns the same loop under
    /// 'omp parallel for simd' into gathers, 8x slower.)
    template <bool rotation>
    void kick_and_drift(ParticleStore &P, const double *__restrict X0, const double *__restrict Y0,
                        const double *__restrict Z0, const Vec3 &lo, const Vec3 &hi, double h, double dt,
                        int n_threads, double &max_d2, long &bad)
    {
      const std::size_t n = P.size();
      double            d2_max = 0;
      long              first_bad = std::numeric_limits<long>::max();
#pragma omp parallel num_threads(n_threads) reduction(max : d2_max) reduction(min : first_bad)
      {
        const auto [begin, end] = share(n, omp_get_thread_num(), omp_get_num_threads());
        const KickArrays k(P);
        k.kick_range<rotation>(begin, end, h);
        double *__restrict X = P.x.data(), *__restrict Y = P.y.data(), *__restrict Z = P.z.data();
        const double *__restrict VX = k.vx, *__restrict VY = k.vy, *__restrict VZ = k.vz;
        const double x_lo = lo[0], y_lo = lo[1], z_lo = lo[2], x_hi = hi[0], y_hi = hi[1], z_hi = hi[2];
        auto         inside = [=](double x, double y, double z) { // (false for NaN)
          return x >= x_lo && x <= x_hi && y >= y_lo && y <= y_hi && z >= z_lo && z <= z_hi;
        };
        double d2 = 0;
        int    outside = 0;
#pragma omp simd reduction(max : d2) reduction(+ : outside)
        for (std::size_t i = begin; i < end; ++i)
          {
            X[i] += dt * VX[i], Y[i] += dt * VY[i], Z[i] += dt * VZ[i];
            const double dx = X[i] - X0[i], dy = Y[i] - Y0[i], dz = Z[i] - Z0[i];
            d2 = std::max(d2, dx * dx + dy * dy + dz * dz);
            outside += !inside(X[i], Y[i], Z[i]);
          }
        d2_max = d2;
        for (std::size_t i = begin; outside > 0 && i < end; ++i) // (rare) the first one outside
          if (!inside(X[i], Y[i], Z[i]))
            {
              first_bad = long(i);
              break;
            }
      }
      max_d2 = d2_max, bad = first_bad;
    }

    /// Second half of a velocity-Verlet step: the half kick with the new forces.
    template <bool rotation>
    void half_kick(ParticleStore &P, double h, int n_threads)
    {
#pragma omp parallel num_threads(n_threads)
      {
        const auto [begin, end] = share(P.size(), omp_get_thread_num(), omp_get_num_threads());
        KickArrays(P).kick_range<rotation>(begin, end, h);
      }
    }

    // The thread count OpenMP offers when the program starts (OMP_NUM_THREADS, or the cores),
    // taken before anything else can lower it: deal.II's MPI set-up for the FEM limits the
    // threads of the process to one.
    const int threads_at_start = omp_get_max_threads();
  } // namespace

  int default_thread_count() { return threads_at_start; }

  int default_thread_count(const Parallel &ranks)
  {
    // the ranks on one machine share its cores
    return std::max(1, threads_at_start / ranks.ranks_on_this_machine());
  }

  Simulation::Simulation(const Settings &s) : config(s), impl(std::make_unique<Impl>())
  {
    impl->parallel  = !config.distribute ? Parallel() : config.ranks ? *config.ranks : Parallel::world();
    // n_threads is the count of shares (the arithmetic); the governor's team works on them
    const int threads = config.threads > 0 ? config.threads : default_thread_count(impl->parallel);
    impl->n_threads   = config.shares > 0 ? config.shares : threads;
    const int team    = std::min(threads, impl->n_threads);
    if (config.governor && config.governor->threads() == team && config.adapt_threads)
      {
        impl->governor = config.governor;
        impl->governor->carry_on();
      }
    else
      impl->governor = std::make_shared<ThreadGovernor>(team, config.adapt_threads);
    with_contact_law(config.contact, [&](auto law) { impl->history = decltype(law)::history; });
  }

  int Simulation::shares() const { return impl->n_threads; }
  int Simulation::threads() const { return impl->governor->threads(); }
  std::shared_ptr<ThreadGovernor> Simulation::thread_governor() const { return impl->governor; }

  void Simulation::pin_thread_team(int team) { impl->governor->pin(team); }

  Simulation::Simulation(Simulation &&) noexcept = default;
  Simulation &Simulation::operator=(Simulation &&) noexcept = default;
  Simulation::~Simulation() = default;

  int Simulation::add_material(const Material &m)
  {
    if (!(m.youngs_modulus > 0 && m.density > 0 && m.poisson_ratio > -1 && m.poisson_ratio < 0.5))
      throw InputError("material '" + m.name + "'", "needs E > 0, density > 0, -1 < nu < 0.5");
    const std::size_t n = mats.size();
    std::vector<Interaction> ni((n + 1) * (n + 1));
    std::vector<bool>        ns((n + 1) * (n + 1), false);
    for (std::size_t a = 0; a < n; ++a)
      for (std::size_t b = 0; b < n; ++b)
        {
          ni[a * (n + 1) + b] = interactions[a * n + b];
          ns[a * (n + 1) + b] = interaction_set[a * n + b];
        }
    interactions.swap(ni);
    interaction_set.swap(ns);
    mats.push_back(m);
    is_set_up = false;
    return static_cast<int>(n);
  }

  void Simulation::set_interaction(int a, int b, const Interaction &i)
  {
    const std::size_t n = mats.size();
    interactions[a * n + b] = interactions[b * n + a] = i;
    interaction_set[a * n + b] = interaction_set[b * n + a] = true;
    is_set_up = false;
  }

  int Simulation::add_wall(Wall w)
  {
    if (w.material < 0 || w.material >= static_cast<int>(mats.size()))
      throw InputError("wall '" + w.name + "'", "unknown material index");
    if (w.mesh.n_triangles() == 0)
      throw InputError("wall '" + w.name + "'", "mesh has no triangles");
    if (w.motion.kind == WallMotion::Kind::rigid_body && w.motion.body.empty() && !(w.motion.mass > 0))
      throw InputError("wall '" + w.name + "'", "a rigid-body wall needs a positive mass");
    if (w.motion.kind == WallMotion::Kind::rigid_body && w.motion.mass < 0)
      throw InputError("wall '" + w.name + "'", "negative mass");
    if (!w.motion.body.empty())
      for (const Wall &o : walls)
        if (o.motion.body == w.motion.body &&
            (o.motion.kind != w.motion.kind || motion_name(o) != motion_name(w) || o.motion.free != w.motion.free ||
             o.motion.centre != w.motion.centre || o.motion.free_phases != w.motion.free_phases))
          throw InputError("wall '" + w.name + "'", "walls of one body ('" + w.motion.body + "', with '" + o.name +
                                                       "') need the same motion type, centre, free degrees of freedom "
                                                       "and free phases");
    w.initialise();
    walls.push_back(std::move(w));
    is_set_up = false;
    return static_cast<int>(walls.size()) - 1;
  }

  void Simulation::accelerate_walls(double dt)
  {
    // a body's walls share its loads, mass and inertia (checked in add_wall: same centre, same
    // free degrees of freedom); each gets the same velocity change
    for (std::size_t a = 0; a < walls.size(); ++a)
      {
        Wall &w = walls[a];
        if (!w.free_now())
          continue;
        Vec3   f = w.force, t = w.torque, inertia = w.motion.inertia;
        double mass = w.motion.mass;
        if (!w.motion.body.empty())
          for (std::size_t b = 0; b < walls.size(); ++b)
            if (b != a && walls[b].motion.body == w.motion.body)
              f += walls[b].force, t += walls[b].torque, mass += walls[b].motion.mass,
                inertia += walls[b].motion.inertia;
        w.accelerate(config.gravity, dt, f, t, mass, inertia);
      }
  }

  int Simulation::wall_index(const std::string &name) const
  {
    for (std::size_t w = 0; w < walls.size(); ++w)
      if (walls[w].name == name)
        return static_cast<int>(w);
    return -1;
  }

  void Simulation::add_hook(std::shared_ptr<StepHook> hook) { hooks.push_back(std::move(hook)); }

  void Simulation::add_driver(std::shared_ptr<WallDriver> driver) { drivers.push_back(std::move(driver)); }

  void Simulation::enter_phase(const std::string &phase)
  {
    current_phase = phase;
    for (auto &w : walls)
      w.set_phase(phase);
    for (auto &driver : drivers)
      driver->phase_changed(*this, phase);
  }

  void Simulation::warn(const std::string &w) { warnings.push_back(w); }

  std::vector<std::string> Simulation::take_warnings()
  {
    std::vector<std::string> w;
    w.swap(warnings);
    return w;
  }

  double Simulation::rayleigh_time_step() const
  {
    double dt = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < store.size(); ++i)
      {
        const Material &m = mats[store.material[i]];
        dt = std::min(dt, M_PI * store.radius[i] * std::sqrt(m.density / m.shear_modulus()) /
                            (0.1631 * m.poisson_ratio + 0.8766));
      }
    return impl->parallel.min(dt);
  }

  void Simulation::setup()
  {
    check_rigid_body_masses();
    if (mats.empty())
      throw InputError("", "no materials defined");
    distribute_new_particles();
    tabulate_pair_coefficients();
    set_rotational_inertia();
    double r_min = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < store.size(); ++i)
      r_min = std::min(r_min, store.radius[i]);
    r_min = impl->parallel.min(r_min);
    if (!std::isfinite(r_min)) // no particles
      r_min = 1;
    choose_time_step(r_min);

    skin = config.skin > 0 ? config.skin : 0.2 * r_min;
    impl->buffers.assign(impl->n_threads, {});
    impl->wall_loads.assign(impl->n_threads, std::vector<double>(6 * walls.size()));
    impl->log.per_thread.assign(impl->n_threads, {});
    for (auto &l : impl->log.per_thread)
      l.reserve(1024);
    impl->force_rebuild = true;
    build_neighbour_lists(); // sizes the wall histories too
    compute_forces();
    is_set_up = true;
  }

  void Simulation::check_rigid_body_masses() const
  {
    for (const Wall &w : walls) // a body's walls may carry no mass of their own, the body must
      if (w.motion.kind == WallMotion::Kind::rigid_body && !w.motion.body.empty())
        {
          double mass = 0;
          for (const Wall &o : walls)
            if (o.motion.body == w.motion.body)
              mass += o.motion.mass;
          if (!(mass > 0))
            throw InputError("wall '" + w.name + "'", "the rigid body '" + w.motion.body + "' has no mass");
        }
  }

  void Simulation::tabulate_pair_coefficients()
  {
    const std::size_t nm = mats.size();
    coefficients.assign(nm * nm, PairCoefficients());
    for (std::size_t a = 0; a < nm; ++a)
      for (std::size_t b = 0; b < nm; ++b)
        coefficients[a * nm + b] =
          make_pair_coefficients(mats[a], mats[b], interactions[a * nm + b], config.damping);
  }

  void Simulation::set_rotational_inertia()
  {
    // Non-rotating materials: zero inverse inertia keeps the angular velocity at 0.
    any_rotation = false;
    for (std::size_t i = 0; i < store.size(); ++i)
      {
        const bool rot = mats[store.material[i]].rotation;
        store.inv_inertia[i] = rot ? 1 / (0.4 * store.mass[i] * store.radius[i] * store.radius[i]) : 0.0;
        if (!rot)
          store.wx[i] = store.wy[i] = store.wz[i] = 0;
        any_rotation |= rot;
      }
  }

  void Simulation::choose_time_step(const double r_min)
  {
    // explicit, or a fraction of the Rayleigh time step of the smallest particle
    time_step = config.time_step > 0 ? config.time_step : config.rayleigh_fraction * rayleigh_time_step();
    if (!(time_step > 0) || !std::isfinite(time_step))
      throw InputError("", "cannot choose a time step: set one explicitly, or add particles");

    // Warn when dt exceeds a tenth of the shortest Hertz contact time at the characteristic
    // speed (smallest particle against each material, walls as infinitely heavy).
    const std::size_t nm = mats.size();
    for (std::size_t i = 0; i < store.size(); ++i)
      if (store.radius[i] == r_min)
        {
          for (std::size_t b = 0; b < nm; ++b)
            {
              const auto  &c      = pair(store.material[i], b);
              const bool   wall_b = std::any_of(walls.begin(), walls.end(),
                                              [b](const Wall &w) { return w.material == int(b); });
              const double m_eff  = wall_b ? store.mass[i] : store.mass[i] / 2;
              const double r_eff  = wall_b ? r_min : r_min / 2;
              const double th     = 2.87 * std::pow(m_eff * m_eff / (r_eff * c.e_star * c.e_star *
                                                                   config.characteristic_velocity), 0.2);
              if (time_step > th / 10)
                {
                  std::ostringstream s;
                  s << "time step " << time_step << " s exceeds a tenth of the Hertz contact time ("
                    << th << " s) of material '" << mats[store.material[i]].name << "' against '"
                    << mats[b].name << "' at " << config.characteristic_velocity << " m/s";
                  warn(s.str());
                }
            }
          break;
        }
  }

  // ---------------------------------------------------------------------------------------------
  // Neighbour lists
  // ---------------------------------------------------------------------------------------------

  bool Simulation::needs_rebuild() const
  {
    if (impl->force_rebuild)
      return true;
    const double dp = impl->max_displacement;
    if (2 * dp > skin)
      return true;
    for (const auto &w : walls)
      if (w.motion.kind != WallMotion::Kind::fixed && dp + w.max_displacement_since_build() > skin)
        return true;
    return false;
  }

  void Simulation::compute_forces()
  {
    pair_forces();
    wall_forces();
  }

  // ---------------------------------------------------------------------------------------------
  // Time loop
  // ---------------------------------------------------------------------------------------------

  void Simulation::step()
  {
    if (!is_set_up)
      setup();
    const auto        start = std::chrono::steady_clock::now();
    Impl             &m     = *impl;
    ParticleStore    &P     = store;
    const double      dt = time_step, h = 0.5 * dt;
    const Vec3        dmin = config.domain_min, dmax = config.domain_max;

    // half kick and drift
    double max_d2 = 0;
    long   bad    = std::numeric_limits<long>::max();
    if (any_rotation)
      kick_and_drift<true>(P, m.x0.data(), m.y0.data(), m.z0.data(), dmin, dmax, h, dt, m.team(), max_d2, bad);
    else
      kick_and_drift<false>(P, m.x0.data(), m.y0.data(), m.z0.data(), dmin, dmax, h, dt, m.team(), max_d2, bad);
    for (auto &w : walls)
      w.advance(dt);
    t += dt;
    ++stats.steps;
    agree_on_the_step(max_d2, bad);

    if (needs_rebuild())
      build_neighbour_lists();
    else
      update_ghosts();
    compute_forces();

    // second half kick
    const std::size_t n2 = P.size();
    if (any_rotation)
      half_kick<true>(P, h, m.team());
    else
      half_kick<false>(P, h, m.team());
    accelerate_walls(dt);
    for (auto &driver : drivers)
      driver->drive(*this, dt);

    // built-in per-triangle impulses, then the plug-ins
    add_triangle_impulses(dt);
    for (auto &hook : hooks)
      hook->after_step(*this, m.log);
    check_step();
    count_the_step(start, n2);
  }

  void Simulation::agree_on_the_step(const double max_d2, const long bad)
  {
    Impl                &m = *impl;
    const ParticleStore &P = store;
    // one reduction for the rebuild criterion and the problems of all ranks
    std::vector<double> flags{max_d2, bad != std::numeric_limits<long>::max() ? 1.0 : 0.0, m.force_rebuild ? 1.0 : 0.0};
    m.parallel.max(flags);
    m.max_displacement = std::sqrt(flags[0]);
    m.force_rebuild    = flags[2] > 0;
    if (!(flags[1] > 0))
      return;
    std::ostringstream s;
    bool               nan = false;
    if (bad != std::numeric_limits<long>::max())
      {
        nan = !std::isfinite(P.x[bad] + P.y[bad] + P.z[bad]);
        s << (nan ? "NaN position" : "particle left the domain") << ": particle id " << P.id[bad] << " at step "
          << stats.steps << " (t = " << t << " s), position (" << P.x[bad] << ", " << P.y[bad] << ", " << P.z[bad]
          << ")";
      }
    const int   holder = m.parallel.max_location(s.str().empty() ? 0.0 : 1.0 + nan).second;
    std::string text   = m.parallel.broadcast(s.str(), holder);
    nan                = text.rfind("NaN", 0) == 0;
    if (nan || config.stop_on_error)
      throw RunError(text);
    warn(text + "; removed");
    m.force_rebuild = true;
  }

  void Simulation::add_triangle_impulses(const double dt)
  {
    impl->log.for_each([&](const WallContactRecord &r) {
      Wall &w = walls[r.wall];
      w.normal_impulse[r.triangle] += std::abs(r.normal_force) * dt;
      w.tangential_impulse[r.triangle] +=
        std::sqrt(r.tangential_force[0] * r.tangential_force[0] + r.tangential_force[1] * r.tangential_force[1] +
                  r.tangential_force[2] * r.tangential_force[2]) * dt;
    });
  }

  void Simulation::count_the_step(const std::chrono::steady_clock::time_point start, const std::size_t particles)
  {
    Impl        &m       = *impl;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    stats.loop_seconds += seconds;
    stats.thread_steps += m.team();
    const long kept_before = m.governor->changes();
    m.governor->record_step(seconds);
    stats.team_changes += m.governor->changes() - kept_before;
    stats.particle_steps += static_cast<long>(particles);
    stats.ghost_steps += static_cast<long>(store.n_ghost);
  }

  void Simulation::check_step()
  {
    const Impl &m = *impl;
    const double worst = m.worst_overlap_all; // over all ranks (wall_forces)
    const int    holder = m.worst_overlap_rank;
    if (worst > config.max_overlap_fraction)
      {
        std::ostringstream s;
        if (holder == m.parallel.rank())
          {
            s << "overlap of " << 100 * m.worst_overlap_ratio << " % of the radius (limit "
              << 100 * config.max_overlap_fraction << " %): particle id " << store.id[m.worst_overlap_i];
            if (m.worst_overlap_j >= 0)
              s << " with particle id " << store.id[m.worst_overlap_j];
            else
              s << " with a wall";
            s << " at step " << stats.steps << " (t = " << t
              << " s): the time step is too large, or the loads too high for the particles' stiffness";
          }
        const std::string text = m.parallel.broadcast(s.str(), holder);
        if (config.stop_on_error)
          throw RunError(text);
        // warn once per phase, not every step
        if (warnings.empty() || warnings.back().rfind("overlap", 0) != 0)
          warn(text);
      }
  }

  void Simulation::run_phase(const std::string &phase, double duration,
                             const std::function<void(const Simulation &)> &every_step)
  {
    if (!is_set_up)
      setup();
    enter_phase(phase);
    for (auto &hook : hooks)
      hook->phase_changed(*this, phase);
    const double steps = duration / time_step;
    if (!std::isfinite(steps) || steps > 1e15) // (lround of 1e300 is undefined: it ran 0 steps)
      throw RunError("phase '" + phase + "' of " + std::to_string(duration) + " s needs " + std::to_string(steps) +
                     " steps of " + std::to_string(time_step) + " s: a time step that small is no run (a particle "
                     "radius or mass far too small?)");
    const long n_steps = std::lround(steps);
    for (long s = 0; s < n_steps; ++s)
      {
        step();
        if (every_step)
          every_step(*this);
      }
  }

  double Simulation::settle(double ke_per_particle, double max_time,
                            const std::function<void(const Simulation &)> &progress)
  {
    if (!is_set_up)
      setup();
    enter_phase("settle");
    const double t0 = t;
    while (t - t0 < max_time)
      {
        for (int s = 0; s < 100; ++s)
          step();
        if (progress)
          progress(*this);
        // the kinetic energy and the count are both global: every rank stops at the same step
        // (with this rank's own count the ranks compared one sum with different thresholds, and
        // one went on settling while the other saved the bed: a hang)
        if (kinetic_energy() < ke_per_particle * std::max<std::size_t>(1, n_particles()))
          break;
      }
    return t - t0;
  }

  double Simulation::kinetic_energy() const
  {
    double e = 0;
    for (std::size_t i = 0; i < store.size(); ++i)
      {
        e += 0.5 * store.mass[i] *
             (store.vx[i] * store.vx[i] + store.vy[i] * store.vy[i] + store.vz[i] * store.vz[i]);
        if (store.inv_inertia[i] > 0)
          e += 0.5 / store.inv_inertia[i] *
               (store.wx[i] * store.wx[i] + store.wy[i] * store.wy[i] + store.wz[i] * store.wz[i]);
      }
    return impl->parallel.sum(e);
  }

  std::size_t Simulation::n_particle_contacts() const
  {
    // a pair with a ghost is counted by both ranks: half each
    double            c = 0;
    const std::size_t n = impl->offsets.empty() ? 0 : store.size();
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = impl->offsets[i]; k < impl->offsets[i + 1]; ++k)
        {
          const std::size_t j  = impl->neighbours[k];
          const double      dx = store.x[i] - store.x[j], dy = store.y[i] - store.y[j], dz = store.z[i] - store.z[j];
          const double      sr = store.radius[i] + store.radius[j];
          if (dx * dx + dy * dy + dz * dz < sr * sr)
            c += j < n ? 1.0 : 0.5;
        }
    return std::size_t(std::lround(impl->parallel.sum(c)));
  }
} // namespace abrade::dem
