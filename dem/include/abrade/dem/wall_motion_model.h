#pragma once
// Wall motions as plugins: what `Wall NAME/Motion/Type` chooses. A motion is a class in a file
// of its own in dem/source/dem/wall_motions/ that says
//
//  - how the engine moves the wall (kind(): never, by prescribed velocities, or as a rigid
//    body whose free degrees of freedom answer to the particles' forces and gravity),
//  - which parameters it takes (declared, read and checked through dem::ParameterSection, in
//    the subsection section() of Wall NAME/Motion, or in Motion itself when that is empty), and
//  - the velocity it prescribes in each phase of the cycle, at each time into the phase
//    (velocity(): by default the wall's table, Motion/Velocities and Angular velocities),
//
// and registers itself there with one line:
//
//   ABRADE_REGISTER_WALL_MOTION(Prescribed);
//
// A wall holds the motion it was given (WallMotion::model); the engine asks it for the
// velocities when a phase begins and, for a motion whose velocity changes within a phase
// (time_dependent()), at the middle of every step (Wall::advance()). One virtual call per wall
// and step: nothing per contact.
#include <abrade/common/plugin_registry.h>
#include <abrade/dem/parameter_section.h>
#include <abrade/dem/wall.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::dem
{
  /// What a motion may need to know of the case when it reads its parameters.
  struct MotionContext
  {
    std::vector<std::string> phases; ///< Simulation/Phases' names, in order
  };

  class WallMotionModel
  {
  public:
    virtual ~WallMotionModel() = default;
    /// The name written in Motion/Type ("prescribed").
    virtual std::string name() const = 0;
    /// What it does, a phrase for Motion/Type's documentation ("velocities per phase"; empty:
    /// the name says it).
    virtual std::string documentation() const = 0;
    /// How the engine moves the wall.
    virtual WallMotion::Kind kind() const = 0;
    /// The subsection of Wall NAME/Motion its parameters are in (empty: Motion itself).
    virtual std::string section() const { return {}; }
    virtual void        declare_parameters(ParameterSection &) const {}
    /// Reads (and checks) its parameters for one wall into itself and @p motion.
    virtual void parse_parameters(const ParameterSection &, const MotionContext &, WallMotion &) {}

    /// The velocity it prescribes @p time [s] into phase @p phase (for a rigid body: of the
    /// degrees of freedom that are not free). Default: the wall's table, constant in a phase.
    virtual PhaseVelocity velocity(const WallMotion &motion, const std::string &phase, double time) const;
    /// Whether velocity() changes within a phase (asked every step, at its middle).
    virtual bool time_dependent() const { return false; }
  };

  /// The wall's velocity table, for the motions that follow one (prescribed; a rigid body's
  /// degrees of freedom that are not free): Motion/Velocities and Angular velocities, "phase:
  /// x, y, z; phase: x, y, z", constant in a phase, phases not listed at rest. Declared by the
  /// motion that takes it, in its declare_parameters().
  void declare_velocity_table(ParameterSection &p);
  /// Reads the table into @p motion's phases; a phase that is not one of @p c's (nor "settle")
  /// or a velocity that is not three finite numbers is refused through @p p.
  void read_velocity_table(const ParameterSection &p, const MotionContext &c, WallMotion &motion);

  using WallMotionFactory = std::unique_ptr<WallMotionModel> (*)();

  /// The registered motions' names in the order of their names ("fixed", "prescribed", ...).
  std::vector<std::string> wall_motion_names();
  /// One new instance of every registered motion, in that order (to declare their parameters).
  std::vector<std::unique_ptr<WallMotionModel>> make_wall_motions();
  /// A new motion of that name; nullptr if there is none.
  std::unique_ptr<WallMotionModel> make_wall_motion(const std::string &name);

  /// Adds a motion (ABRADE_REGISTER_WALL_MOTION); a name registered twice is a bug.
  struct WallMotionRegistration
  {
    explicit WallMotionRegistration(WallMotionFactory make);
  };
} // namespace abrade::dem

/// One line in a motion's file registers it (at namespace scope).
#define ABRADE_REGISTER_WALL_MOTION(Class)                                                                \
  ABRADE_REGISTER_PLUGIN(::abrade::dem::WallMotionRegistration, ::abrade::dem::WallMotionModel, Class)
