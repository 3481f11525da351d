#pragma once
// A wall: a triangle mesh with a material and a rigid motion, plus what the particles do to it
// (total force and torque, per-triangle impulses). The reference geometry never changes; the
// current vertex positions are pose(reference) and are updated every step.
#include <abrade/dem/triangle_mesh.h>

#include <Eigen/Core>

#include <array>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace abrade::dem
{
  class WallMotionModel;

  /// Velocity of a wall during one named phase of the operating cycle.
  struct PhaseVelocity
  {
    Vec3 velocity         = Vec3::Zero(); ///< [m/s]
    Vec3 angular_velocity = Vec3::Zero(); ///< [rad/s] about the wall's current centre
  };

  struct WallMotion
  {
    enum class Kind
    {
      fixed,      ///< never moves
      prescribed, ///< piecewise-constant velocity per phase (piecewise-linear position)
      rigid_body, ///< free degrees of freedom driven by gravity and particle forces
      driven      ///< moved by a mechanism (wall_driver.h), which sets its velocities every step
    };
    Kind kind = Kind::fixed;
    /// The motion chosen by Motion/Type (wall_motion_model.h), which prescribes the velocities;
    /// none: the velocity table below, constant in each phase.
    std::shared_ptr<const WallMotionModel> model;
    /// Rotation centre (a hinge point), moves with the wall. Torques are taken about it.
    Vec3 centre = Vec3::Zero();
    /// Prescribed velocities; phases not listed keep the wall at rest. For a rigid body, the
    /// degrees of freedom that are not free follow this table.
    std::map<std::string, PhaseVelocity> phases;

    // rigid body
    double               mass    = 0;             ///< [kg]
    Vec3                 inertia = Vec3::Zero();  ///< principal moments about centre [kg m^2]
    std::array<bool, 6>  free{};                  ///< tx, ty, tz, rx, ry, rz
    bool                 gravity = true;          ///< does gravity act on the body
    /// Walls with the same (non-empty) body name move as one rigid body: their forces and
    /// torques (about their common centre) add up, as do their masses and inertias (a grab's
    /// two shells on one hinge, free to sink or rise together).
    std::string           body;
    /// Phases in which the free degrees of freedom are free (empty: all); in the others the
    /// wall follows its velocity table in every degree of freedom (a grab hoisted by its crane).
    std::set<std::string> free_phases;
  };

  struct Wall
  {
    std::string  name;
    TriangleMesh mesh;         ///< reference geometry
    int          material = 0; ///< index into the simulation's materials
    WallMotion   motion;

    // --- state ---
    Eigen::Matrix3d   rotation    = Eigen::Matrix3d::Identity();
    Vec3              translation = Vec3::Zero();
    Vec3              velocity         = Vec3::Zero();
    Vec3              angular_velocity = Vec3::Zero();
    std::vector<double> current;   ///< current vertex positions, x y z interleaved
    std::vector<double> at_build;  ///< vertex positions at the last neighbour-list build

    // --- loads (from particles, this step) ---
    bool free_in_phase = true;  ///< set by set_phase
    std::string phase;          ///< the phase set by set_phase
    double      time_in_phase = 0; ///< [s] since set_phase
    Vec3 force  = Vec3::Zero(); ///< total force on the wall [N]
    Vec3 torque = Vec3::Zero(); ///< about the current centre [N m]
    std::vector<double> normal_impulse;     ///< per triangle, accumulated |F_n| dt [N s]
    std::vector<double> tangential_impulse; ///< per triangle, accumulated |F_t| dt [N s]

    Vec3 current_centre() const { return motion.centre + translation; }
    /// Velocity of the wall's material point at @p p.
    Vec3 velocity_at(const Vec3 &p) const
    {
      return velocity + angular_velocity.cross(p - current_centre());
    }

    /// Sizes the state arrays and places the wall at its reference pose.
    void initialise();
    /// Sets the velocity the current phase prescribes (rigid bodies: the prescribed DOFs only).
    void set_phase(const std::string &phase);
    /// Advances the pose by dt with the current (angular) velocity and updates vertex positions;
    /// a motion whose velocity changes within the phase sets it at the step's middle first.
    void advance(double dt);
    /// Rigid body: velocity update from the loads @p f and @p t (this step's, of this wall or of
    /// its whole body) on @p mass and @p inertia, and gravity.
    void accelerate(const Vec3 &gravity, double dt, const Vec3 &f, const Vec3 &t, double mass, const Vec3 &inertia);
    /// Whether the free degrees of freedom are free in the current phase.
    bool free_now() const { return motion.kind == WallMotion::Kind::rigid_body && free_in_phase; }
    /// Largest vertex displacement since the last neighbour-list build.
    double max_displacement_since_build() const;
    void   mark_build() { at_build = current; }
    /// Unit normal of triangle @p t in its current position.
    Vec3 current_normal(std::size_t t) const
    {
      const auto &tri = mesh.triangles[t];
      const Vec3  a(&current[3 * tri[0]]), b(&current[3 * tri[1]]), c(&current[3 * tri[2]]);
      return (b - a).cross(c - a).normalized();
    }
    /// Current geometry of the wall as a mesh (reference topology).
    TriangleMesh current_mesh() const;

  private:
    /// Sets the velocities of the prescribed degrees of freedom (all, unless free now).
    void prescribe(const PhaseVelocity &pv);
  };
} // namespace abrade::dem
