// A rope grab's mechanism moving DEM walls (rope_grab_driver.h).
#include <abrade/common/error.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/format_number.h>
#include <abrade/common/list_items.h>
#include <abrade/dem/rope_grab_driver.h>
#include <abrade/dem/simulation.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace abrade::dem
{
  RopeGrabDriver::RopeGrabDriver(const RopeGrabRig &r, Simulation &sim)
    : grab(r.design)
    , rig(r)
  {
    const Vec3 gravity = sim.settings().gravity;
    if (gravity.x() != 0 || gravity.y() != 0 || !(gravity.z() < 0))
      throw InputError("Grab mechanism", "the grab's mechanism hangs along z: Simulation/Gravity must point along -z");
    g = -gravity.z();
    for (const auto &[name, part] : rig.walls)
      {
        const int w = sim.wall_index(name);
        if (w < 0)
          throw InputError("Grab mechanism", "no wall '" + name + "' to move");
        Wall &wall = sim.wall(w);
        if (wall.motion.kind != WallMotion::Kind::fixed && wall.motion.kind != WallMotion::Kind::driven)
          throw InputError("Wall " + name, "the grab's mechanism moves this wall: leave out its Motion/Type");
        wall.motion.kind   = WallMotion::Kind::driven;
        wall.motion.centre = rig.hinge; // (translation is zero until the first step)
        parts.emplace_back(static_cast<std::size_t>(w), part);
      }
    // hanging open on the holding ropes, the closing rope just taut
    now.z = rig.hinge.z();
    grab.tension_ropes(now, 0, g * grab.mass_matrix(0)(0, 0));
  }

  Winch RopeGrabDriver::closing_winch(const std::string &phase) const
  {
    const auto it = rig.closing.find(phase);
    return it == rig.closing.end() ? Winch{} : it->second;
  }

  Winch RopeGrabDriver::holding_winch(const std::string &phase) const
  {
    const auto it = rig.holding.find(phase);
    return it == rig.holding.end() ? Winch{} : it->second;
  }

  void RopeGrabDriver::phase_changed(Simulation &sim, const std::string &phase)
  {
    const bool was_moving = moving;
    moving = std::find(rig.phases.begin(), rig.phases.end(), phase) != rig.phases.end();
    if (was_moving && !moving)
      {
        // held still: the walls are one drift behind the mechanism's state (they move with the
        // velocities it set in the next step), so it goes back to their pose and stops there
        now.z -= sim.dt() * now.z_rate;
        now.angle -= sim.dt() * now.angle_rate;
        now.z_rate = now.angle_rate = now.head_distance_rate = 0;
        now.closing_drum_speed = now.holding_drum_speed = 0;
        trolley_x -= sim.dt() * trolley_v;
        trolley_v = 0;
        if (!records.empty()) // (the phase ends where its walls are)
          {
            PhaseRecord &r = records.back().second;
            r.hinge_end    = now.z;
            r.angle_end    = now.angle;
            r.trolley_end  = trolley_x;
          }
      }
    if (moving)
      {
        PhaseRecord r;
        r.hinge_start = r.hinge_end = now.z;
        r.angle_start = r.angle_end = now.angle;
        r.head_distance_end         = grab.head_distance(now.angle);
        r.trolley_start = r.trolley_end = trolley_x;
        records.emplace_back(phase, r);
      }
    set_velocities(sim);
  }

  void RopeGrabDriver::drive(Simulation &sim, double dt)
  {
    if (!moving)
      return;
    const std::string &phase = records.back().first;
    const Winch        closing = closing_winch(phase), holding = holding_winch(phase);
    // the particles' generalised loads (virtual work): the walls' vertical forces and, on the
    // shells, their torques about the hinge
    loads = Eigen::Vector2d::Zero();
    for (const auto &[w, part] : parts)
      loads += grab.load(part, sim.wall(w).force.z(), sim.wall(w).torque.y(), now.angle);
    const double closing_paid = now.closing_paid_out, holding_paid = now.holding_paid_out;
    grab.step(now, dt, loads, g, closing, holding);
    const auto   target = rig.trolley.find(phase);
    const double wanted = target == rig.trolley.end() ? 0.0 : target->second;
    trolley_v           = ramped(trolley_v, wanted, rig.trolley_acceleration, dt);
    trolley_x += dt * trolley_v;
    set_velocities(sim);

    PhaseRecord &r = records.back().second;
    const double t_c = grab.closing_tension(now, closing), t_h = grab.holding_tension(now, holding);
    r.hinge_end         = now.z;
    r.lowest_hinge      = std::min(r.lowest_hinge, now.z);
    r.highest_hinge     = std::max(r.highest_hinge, now.z);
    r.angle_end         = now.angle;
    r.head_distance_end = grab.head_distance(now.angle);
    r.closing_tension_max = std::max(r.closing_tension_max, t_c);
    r.holding_tension_max = std::max(r.holding_tension_max, t_h);
    r.closing_tension_sum += t_c;
    r.holding_tension_sum += t_h;
    r.closing_hauled -= now.closing_paid_out - closing_paid;
    r.holding_hauled -= now.holding_paid_out - holding_paid;
    r.trolley_end       = trolley_x;
    ++r.steps;
    if (now.angle >= rig.design.closed_angle)
      {
        if (r.steps_at_closed_stop++ == 0 && r.angle_start < rig.design.closed_angle)
          r.hinge_when_closed = now.z;
      }
  }

  void RopeGrabDriver::set_velocities(Simulation &sim) const
  {
    for (const auto &[w, part] : parts)
      {
        Wall &wall            = sim.wall(w);
        wall.velocity         = moving ? Vec3(trolley_v, 0, grab.vertical_velocity(part, now)) : Vec3::Zero();
        wall.angular_velocity = moving ? Vec3(0, grab.angular_velocity(part, now), 0) : Vec3::Zero();
      }
  }
} // namespace abrade::dem

// --- parameters ---

namespace abrade::dem
{
  namespace
  {
    const std::vector<std::pair<std::string, RopeGrab::Part>> part_entries = {
      {"Right shell walls", RopeGrab::Part::right_shell},
      {"Left shell walls", RopeGrab::Part::left_shell},
      {"Lower head walls", RopeGrab::Part::lower_head},
      {"Upper head walls", RopeGrab::Part::upper_head}};

    /// 'phase: value, phase: value' with the phases among @p phases and the values in [lo, hi].
    std::map<std::string, double> phase_values(const ParameterSection &section, const std::string &key,
                                               const std::vector<std::string> &phases, double lo, double hi)
    {
      std::map<std::string, double> out;
      for (const std::string &item : io::list_items(section.text(key), ','))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            section.fail(key, "expected 'phase: value', got '" + item + "'");
          const std::string phase = io::trimmed(item.substr(0, colon)), value = io::trimmed(item.substr(colon + 1));
          if (std::find(phases.begin(), phases.end(), phase) == phases.end())
            section.fail(key, "'" + phase + "' is not one of Simulation/Phases");
          const std::optional<double> v = io::finite_number(value);
          if (!v || *v < lo || *v > hi)
            section.fail(key, "phase '" + phase + "': '" + value + "' is not a number in [" + io::format_number(lo) +
                                ", " + (hi == unbounded ? std::string("inf") : io::format_number(hi)) + "]");
          if (!out.emplace(phase, *v).second)
            section.fail(key, "phase '" + phase + "' is listed twice");
        }
      return out;
    }

    Eigen::Vector2d in_plane(const ParameterSection &section, const std::string &key)
    {
      const std::vector<double> v = section.numbers(key);
      return {v[0], v[1]};
    }
  } // namespace

  void declare_rope_grab_parameters(ParameterSection &p)
  {
    const std::string plane = " In the grab's plane of symmetry (x across towards the right shell, z up), from the "
                              "hinge, with the shells as the walls place them (open): 'x, z'.";
    for (const auto &[key, part] : part_entries)
      p.declare_text(key, "",
                     "Walls (names from Walls, comma separated) that ride on the " +
                       std::string(part == RopeGrab::Part::right_shell  ? "right shell (the +x one), turning about the hinge"
                                   : part == RopeGrab::Part::left_shell ? "left shell (the -x one), turning about the hinge"
                                   : part == RopeGrab::Part::lower_head ? "lower head (with the hinge)"
                                                                        : "upper head") +
                       "; a knife mounted on a shell (Mounted on) rides with its shell. The walls need no Motion.");
    p.declare_vector("Hinge", {0, 0, 0},
                     "[m] A point of the shells' hinge axis (along y) at the start: the shells' walls turn about it.");
    p.declare_number("Upper pin offset", 0.45, 0, unbounded,
                     "[m] Horizontal distance of the tie rods' pins on the upper head from the grab's axis. Range: >= 0.");
    p.declare_number("Tie rod length", 0.7, 1e-6, unbounded, "[m] Tie rod (corner post), pin to pin. Range: > 0.");
    p.declare_numbers("Shell pin", "0.42, 0.3", 2, 2, -unbounded, unbounded,
                      "[m] The right shell's tie-rod pin, outboard of its centre of mass if the grab is to "
                      "hang open under its weight." + plane);
    p.declare_number("Closed angle", 56.4, 0, 180,
                     "[deg] How far the shells turn from their pose at the start until their lips meet (the "
                     "closing stop). Range: [0, 180].");
    p.declare_number("Open angle", 0, -90, 0,
                     "[deg] The opening stop, from the pose at the start (0: the shells start fully open; "
                     "< 0: they open further). Range: [-90, 0].");
    p.declare_number("Falls", 4, 1, 100,
                     "[-] Parts of the closing rope reeved between the heads (its mechanical advantage on the "
                     "head distance). Range: [1, 100], whole.");
    p.declare_number("Lower head mass", 150, 0, unbounded, "[kg] The lower head with its sheaves. Range: >= 0.");
    p.declare_number("Upper head mass", 50, 0, unbounded,
                     "[kg] The upper head (crosshead) with its sheaves, and half the tie rods. Range: >= 0.");
    p.declare_number("Shell mass", 150, 1e-9, unbounded,
                     "[kg] Each shell with its knife (and half its tie rod). Range: > 0.");
    p.declare_numbers("Shell centre of mass", "0.33, 0.05", 2, 2, -unbounded, unbounded,
                      "[m] The right shell's centre of mass, knife included." + plane);
    p.declare_number("Shell inertia", 5, 0, unbounded,
                     "[kg m^2] Each shell's moment of inertia about its centre of mass, about the hinge's "
                     "direction. Range: >= 0.");
    p.declare_number("Closing rope stiffness", 1e6, 1, unbounded,
                     "[N/m] The closing rope as rigged, from the winch to the grab (E A / length). Range: > 0.");
    p.declare_number("Holding rope stiffness", 1e6, 1, unbounded,
                     "[N/m] The holding ropes together, from the winch to the upper head. Range: > 0.");
    p.declare_number("Rope damping ratio", 0.1, 0, 10,
                     "[-] Each rope's damping while taut, as a fraction of the critical damping of the whole "
                     "grab's mass on it: c = 2 ratio sqrt(k m). Range: [0, 10].");
    p.declare_number("Winch acceleration", 2, 0, unbounded,
                     "[m/s^2] How fast a winch's drum reaches the speed a phase asks for (a crane's winch "
                     "ramps up in a second or so; below g a lowered grab does not fall free of its ropes); 0: "
                     "at once. Range: >= 0.");
    p.declare_text("Closing winch speeds", "",
                   "[m/s] The closing winch's speed per phase, 'phase: speed, ...': hauling in > 0, paying out "
                   "< 0. A phase not listed: 0 (the brake holds).");
    p.declare_text("Closing winch pulls", "",
                   "[N] The closing winch's stall pull per phase, 'phase: pull, ...': beyond it the drum pays "
                   "out. 0: the rope is kept just slack, at no tension (a grab lowered on its holding ropes), "
                   "while the drum turns at its speed (the next phase's winch ramps from there). A phase not "
                   "listed: no limit.");
    p.declare_text("Trolley speeds", "",
                   "[m/s] The crane trolley's speed along x per phase, 'phase: speed, ...' (travel to a "
                   "hopper; < 0: along -x): the whole grab goes with it, hanging rigidly below it (no swing: "
                   "the payload feels the trolley's whole acceleration). A phase not listed: 0 (the trolley "
                   "stops, at Trolley acceleration).");
    p.declare_number("Trolley acceleration", 0.5, 0, unbounded,
                     "[m/s^2] How fast the trolley reaches the speed a phase asks for, and stops (a crane's "
                     "trolley: 0.3-1); 0: at once. Range: >= 0.");
    p.declare_text("Holding winch speeds", "", "[m/s] The holding winch's, as Closing winch speeds.");
    p.declare_text("Holding winch pulls", "",
                   "[N] The holding winch's, as Closing winch pulls (0 while the grab closes: the holding "
                   "ropes slack, the grab's weight on the material).");
  }

  RopeGrabRig parse_rope_grab_parameters(const ParameterSection &p, const std::vector<std::string> &phases)
  {
    RopeGrabRig rig;
    rig.phases = phases;
    for (const auto &[key, part] : part_entries)
      for (const std::string &name : io::list_items(p.text(key), ','))
        {
          for (const auto &[other, _] : rig.walls)
            if (other == name)
              p.fail(key, "wall '" + name + "' is named twice in the mechanism");
          rig.walls.emplace_back(name, part);
        }
    if (std::none_of(rig.walls.begin(), rig.walls.end(), [](const auto &w) { return w.second == RopeGrab::Part::right_shell; }) ||
        std::none_of(rig.walls.begin(), rig.walls.end(), [](const auto &w) { return w.second == RopeGrab::Part::left_shell; }))
      p.fail("Right shell walls", "a rope grab needs walls on both shells (Right shell walls, Left shell walls)");
    const auto hinge = p.vector("Hinge");
    rig.hinge        = Vec3(hinge[0], hinge[1], hinge[2]);

    RopeGrabDesign &d  = rig.design;
    d.upper_pin_offset = p.number("Upper pin offset");
    d.tie_rod_length   = p.number("Tie rod length");
    d.shell_pin        = in_plane(p, "Shell pin");
    d.closed_angle     = p.number("Closed angle") * M_PI / 180;
    d.open_angle       = p.number("Open angle") * M_PI / 180;
    const double falls = p.number("Falls");
    if (falls != std::round(falls))
      p.fail("Falls", "a number of rope parts is whole");
    d.falls                  = static_cast<int>(falls);
    d.lower_head_mass        = p.number("Lower head mass");
    d.upper_head_mass        = p.number("Upper head mass");
    d.shell_mass             = p.number("Shell mass");
    d.shell_centre           = in_plane(p, "Shell centre of mass");
    d.shell_inertia          = p.number("Shell inertia");
    d.closing_rope_stiffness = p.number("Closing rope stiffness");
    d.holding_rope_stiffness = p.number("Holding rope stiffness");
    d.winch_acceleration     = p.number("Winch acceleration");
    const double mass        = d.lower_head_mass + d.upper_head_mass + 2 * d.shell_mass;
    const double ratio       = p.number("Rope damping ratio");
    d.closing_rope_damping   = 2 * ratio * std::sqrt(d.closing_rope_stiffness * mass);
    d.holding_rope_damping   = 2 * ratio * std::sqrt(d.holding_rope_stiffness * mass);
    try
      {
        d.check();
      }
    catch (const RopeGrabDesignError &e)
      {
        p.fail(e.parameter, e.what());
      }

    const auto winches = [&](const std::string &speeds, const std::string &pulls) {
      std::map<std::string, Winch> out;
      for (const auto &[phase, v] : phase_values(p, speeds, phases, -100, 100))
        out[phase].speed = v;
      for (const auto &[phase, f] : phase_values(p, pulls, phases, 0, unbounded))
        out[phase].maximum_pull = f;
      return out;
    };
    rig.closing = winches("Closing winch speeds", "Closing winch pulls");
    rig.holding = winches("Holding winch speeds", "Holding winch pulls");
    rig.trolley = phase_values(p, "Trolley speeds", phases, -100, 100);
    rig.trolley_acceleration = p.number("Trolley acceleration");
    return rig;
  }
} // namespace abrade::dem
