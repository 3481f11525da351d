#pragma once
// A rope grab's mechanism (rope_grab.h) moving the DEM walls of its shells, their knives and its
// heads: every step it takes the particles' loads on those walls (forces, and torques about the
// hinge), advances the mechanism under them, gravity and its ropes, and gives each wall the
// velocity of the part it rides on. The mechanism moves in the cycle's phases; while a bed
// settles it is held still, hanging open on its holding ropes.
//
// The grab's plane of symmetry is the DEM's x-z plane, its hinge axis along y, gravity along -z.
// The walls are placed at the design's open pose (angle 0).
//
// A crane's trolley can carry the grab along x (travel to a hopper): the whole grab translates
// with the trolley, hanging rigidly below it (no swing). A uniform acceleration along x does no
// work on either degree of freedom: raising the grab moves nothing sideways, and closing moves
// the two shells (and their tie rods) sideways by equal and opposite amounts. The mechanism is
// therefore not changed by it; the particles feel the walls' whole acceleration (a grab
// swinging on its ropes would pass them less of it).
#include <abrade/dem/parameter_section.h>
#include <abrade/dem/rope_grab.h>
#include <abrade/dem/triangle_mesh.h>
#include <abrade/dem/wall_driver.h>

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace abrade::dem
{
  /// How a case rigs the mechanism.
  struct RopeGrabRig
  {
    RopeGrabDesign design;
    /// [m] A point of the hinge axis at the start (the shells' walls turn about it).
    Vec3 hinge = Vec3::Zero();
    /// The phases the mechanism moves in (the cycle's); in others it is held still.
    std::vector<std::string> phases;
    /// The winches per phase; a phase not listed: speed 0 (the brake holds), no pull limit.
    std::map<std::string, Winch> closing, holding;
    /// [m/s] The trolley's speed along +x per phase (a phase not listed: 0), reached at
    /// trolley_acceleration [m/s^2] (0: at once).
    std::map<std::string, double> trolley;
    double                        trolley_acceleration = 0.5;
    /// The walls it moves, by name, with the part each rides on.
    std::vector<std::pair<std::string, RopeGrab::Part>> walls;
  };

  /// The parameters of a rope grab (the subsection Grab mechanism of a case): declared with
  /// their units, read and checked. The wall lists name the walls as the file gives them (a
  /// knife mounted on a shell rides with it: the caller adds it).
  void        declare_rope_grab_parameters(ParameterSection &section);
  RopeGrabRig parse_rope_grab_parameters(const ParameterSection &section, const std::vector<std::string> &phases);

  class RopeGrabDriver : public WallDriver
  {
  public:
    /// Takes the walls of @p rig in @p sim: they become driven, turning about the hinge; throws
    /// InputError for a wall that is not there or has a motion of its own, or gravity not
    /// along -z.
    RopeGrabDriver(const RopeGrabRig &rig, Simulation &sim);

    void drive(Simulation &sim, double dt) override;
    void phase_changed(Simulation &sim, const std::string &phase) override;

    const RopeGrab        &mechanism() const { return grab; }
    /// The particles' generalised loads of the last step (vertical force [N], torque about the
    /// hinge in the closing sense [N m]).
    const Eigen::Vector2d &particle_loads() const { return loads; }
    const RopeGrab::State &state() const { return now; }
    /// [m] How far the trolley has carried the grab along x, and its speed [m/s].
    double trolley_position() const { return trolley_x; }
    double trolley_speed() const { return trolley_v; }
    /// The winches in @p phase.
    Winch closing_winch(const std::string &phase) const;
    Winch holding_winch(const std::string &phase) const;

    /// What the mechanism did in a phase.
    struct PhaseRecord
    {
      double hinge_start = 0, hinge_end = 0; ///< [m] hinge height
      double lowest_hinge  = std::numeric_limits<double>::infinity();
      double highest_hinge = -std::numeric_limits<double>::infinity();
      double angle_start = 0, angle_end = 0; ///< [rad] closing angle
      double head_distance_end = 0;          ///< [m]
      double closing_tension_max = 0, holding_tension_max = 0;   ///< [N]
      double closing_tension_sum = 0, holding_tension_sum = 0;   ///< [N] over the steps
      double closing_hauled = 0, holding_hauled = 0;             ///< [m] rope the winches took in (< 0: paid out)
      double trolley_start = 0, trolley_end = 0; ///< [m] the trolley's position
      /// [m] The hinge's height at the step the lips closed (NaN: the phase began closed, or
      /// they did not close in it).
      double hinge_when_closed = std::numeric_limits<double>::quiet_NaN();
      long   steps = 0;
      long   steps_at_closed_stop = 0; ///< steps that ended with the lips closed
    };
    /// Per phase of the cycle, in the order they ran.
    const std::vector<std::pair<std::string, PhaseRecord>> &phases() const { return records; }

  private:
    RopeGrab                                       grab;
    RopeGrab::State                                now;
    RopeGrabRig                                    rig;
    std::vector<std::pair<std::size_t, RopeGrab::Part>> parts; // wall index, part
    double                                         g = 9.81;
    bool                                           moving = false;
    double                                         trolley_x = 0, trolley_v = 0;
    Eigen::Vector2d                                loads  = Eigen::Vector2d::Zero();
    std::vector<std::pair<std::string, PhaseRecord>> records;

    void set_velocities(Simulation &sim) const;
  };
} // namespace abrade::dem
