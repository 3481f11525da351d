#pragma once
// The closing mechanism of a rope grab (a four-rope clamshell grab), as a grab maker builds it:
//
//            holding ropes        closing rope (to the crane's closing winch)
//                 |    |              |
//          +------o----o--------------o------+   upper head (crosshead): the holding ropes'
//          |  a   |                          |   eyes, the closing rope's upper sheaves
//          o------+ tie-rod pins (+-a)       o
//           \                               /    tie rods (corner posts), length l, from the
//            \      n falls of the         /     upper head to a pin on each shell
//             \     closing rope between  /
//              o    the heads            o       shell pins (on the shells' outer tops)
//             (  right shell   o   left shell )  lower head: the shells' common hinge axis
//              \_______________|_____________/   and the lower sheaves
//                            lips (knives)
//
// Hauling the closing rope in draws the lower head up towards the upper head; the tie rods
// then push the shells' outer tops down and out, and the shells turn about the hinge until
// their lips meet. Paying it out while the holding ropes carry the upper head lets the lower
// head and the shells sink under their weight: the grab opens.
//
// The mechanism moves in its plane of symmetry (x across, from the hinge towards the right
// shell; z up; the hinge axis along y) with two degrees of freedom (generalised coordinates):
//   z      the hinge's height [m], and
//   angle  the shells' closing angle [rad]: the right shell turned by +angle about +y from its
//          open pose (its lip towards the middle), the left shell by -angle (its mirror image).
// The upper head stays on the grab's axis (no swinging), so its height above the hinge, the
// head distance d(angle), follows from the linkage:  |(a, d) - p(angle)| = l, where p is the
// right shell's pin. Both shells therefore turn by the same angle.
//
// Masses: the lower head, the upper head, each shell with its knife (mass, centre of mass and
// moment of inertia about it); the tie rods are massless (add their mass to the upper head and
// the shells, half each). Kinetic energy T = 1/2 u^T M(angle) u with u = (z', angle'); the
// equations of motion are Lagrange's, M u' + c(angle, u) = Q, with Q the generalised loads of
// gravity, the ropes and the particles (virtual work: load() turns a part's force and torque
// into Q).
//
// Ropes: elastic (stiffness k [N/m] as rigged, and a viscous damping [N s/m] while taut),
// slack below zero stretch. The closing rope's length below the crane is
// L_c = -z + (n - 1) d + const (n falls between the heads, one line up from the upper head), the
// holding ropes' L_h = -z - d + const; a rope's tension is k (L - lambda) (+ damping) where
// lambda, the length the winch has paid out, changes at the drum's speed, which approaches the
// speed asked for at the winch's acceleration. A winch pulls at most its maximum pull: beyond it,
// the drum pays out (a stall: the tension stays at the maximum pull). A winch of maximum pull 0
// lets its drum follow the rope at no tension (the rope kept just slack).
//
// Stops: the shells cannot close past the angle at which their lips meet, nor open past the
// angle given as fully open; reaching one is a plastic impact (the shells stop; the vertical
// momentum is kept).
//
// The integration is the DEM's (semi-implicit Euler): velocities from the loads at the start of
// the step, then positions with the new velocities.
#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace abrade::dem
{
  /// The mechanism's dimensions (in its plane: x across, z up, from the hinge) and masses.
  struct RopeGrabDesign
  {
    // --- linkage [m] ---
    double          upper_pin_offset = 0; ///< a: horizontal distance of the tie-rod pins on the upper head from the axis
    double          tie_rod_length   = 0; ///< l: pin to pin
    Eigen::Vector2d shell_pin = Eigen::Vector2d::Zero(); ///< right shell's tie-rod pin, from the hinge, open pose (angle 0)
    double          closed_angle = 0; ///< [rad] angle at which the lips meet (the closing stop)
    double          open_angle   = 0; ///< [rad] the opening stop (0: the pose given is fully open; < 0: beyond it)
    int             falls        = 4; ///< n: parts of the closing rope between the heads

    // --- masses ---
    double          lower_head_mass = 0; ///< [kg]
    double          upper_head_mass = 0; ///< [kg]
    double          shell_mass      = 0; ///< [kg] each shell with its knife
    Eigen::Vector2d shell_centre = Eigen::Vector2d::Zero(); ///< right shell's centre of mass, from the hinge, open pose [m]
    double          shell_inertia = 0; ///< [kg m^2] each shell's moment of inertia about its centre of mass (axis y)

    // --- ropes ---
    double closing_rope_stiffness = 0; ///< [N/m] as rigged, winch to grab
    double closing_rope_damping   = 0; ///< [N s/m]
    double holding_rope_stiffness = 0; ///< [N/m] all holding ropes together
    double holding_rope_damping   = 0; ///< [N s/m]
    /// [m/s^2] How fast a winch's drum changes speed towards the one asked for (0: at once).
    double winch_acceleration = 0;

    /// Throws RopeGrabDesignError naming what is wrong (a linkage that cannot be assembled
    /// between the stops or passes its toggle point, a non-positive mass, masses whose matrix
    /// is singular, ...) and the parameter to change.
    void check() const;
  };

  /// A design that cannot work: what is wrong, and the parameter (as the Grab mechanism
  /// subsection names it) to change.
  struct RopeGrabDesignError : std::invalid_argument
  {
    RopeGrabDesignError(const std::string &parameter, const std::string &what)
      : std::invalid_argument("rope grab: " + what)
      , parameter(parameter)
    {}
    std::string parameter;
  };

  /// @p speed one step @p dt closer to @p target at @p acceleration (0: at once): a winch's
  /// drum, a crane's trolley.
  inline double ramped(double speed, double target, double acceleration, double dt)
  {
    const double most = acceleration > 0 ? acceleration * dt : std::numeric_limits<double>::infinity();
    return std::clamp(target, speed - most, speed + most);
  }

  /// What a winch does in a phase of the cycle.
  struct Winch
  {
    double speed        = 0; ///< [m/s] hauling in (> 0) or paying out (< 0)
    /// [N] Stall pull. 0: the rope is kept just slack (neither pull nor slack length) while the
    /// drum turns at its speed, from which a later phase's winch ramps.
    double maximum_pull = std::numeric_limits<double>::infinity();
  };

  class RopeGrab
  {
  public:
    /// The parts the DEM's walls ride on.
    enum class Part
    {
      lower_head,  ///< moves with the hinge
      upper_head,  ///< moves with the hinge plus the head distance's change
      right_shell, ///< turns by +angle about +y about the hinge
      left_shell   ///< turns by -angle about +y about the hinge
    };

    struct State
    {
      double z          = 0; ///< [m] hinge height
      double angle      = 0; ///< [rad] closing angle
      double z_rate     = 0; ///< [m/s]
      double angle_rate = 0; ///< [rad/s]
      double closing_paid_out = 0; ///< [m] lambda_c (same reference as closing_rope_length())
      double holding_paid_out = 0; ///< [m] lambda_h
      /// [m/s] The head distance's change over the last step, over the step (the upper head's
      /// walls move with z_rate plus this, so that they follow the chord of d exactly).
      double head_distance_rate = 0;
      double closing_drum_speed = 0; ///< [m/s] hauling in > 0 (it approaches the winch's speed)
      double holding_drum_speed = 0; ///< [m/s]
    };

    /// Bookkeeping of the work done on the mechanism (energy()'s ledger).
    struct Work
    {
      double winches   = 0; ///< [J] by the winches on the ropes (- the integral of T d lambda)
      double damping   = 0; ///< [J] dissipated in the ropes' damping (>= 0)
      double loads     = 0; ///< [J] by the loads given to step() (the particles)
      double stops     = 0; ///< [J] lost at the stops (>= 0)
    };

    /// Checks the design (RopeGrabDesign::check()).
    explicit RopeGrab(const RopeGrabDesign &design);
    /// Tag: one made without checking its design (what check() itself uses).
    struct Unchecked
    {};
    static constexpr Unchecked unchecked{};
    RopeGrab(const RopeGrabDesign &design, Unchecked);

    const RopeGrabDesign &design() const { return d; }

    // --- kinematics ---
    /// The right shell's tie-rod pin, from the hinge, at @p angle (the left one is its mirror image).
    Eigen::Vector2d shell_pin(double angle) const;
    /// The right shell's centre of mass, from the hinge.
    Eigen::Vector2d shell_centre(double angle) const;
    /// Height of the upper head's tie-rod pins above the hinge; throws std::domain_error where
    /// the tie rods cannot reach.
    double head_distance(double angle) const;
    /// d head_distance / d angle and its second derivative.
    double head_distance_slope(double angle) const;
    double head_distance_curvature(double angle) const;
    /// The closing angle at head distance @p distance (the inverse of head_distance(), on the
    /// branch of the design's open pose); throws std::domain_error outside the linkage's reach.
    double angle_at_head_distance(double distance) const;
    /// Rope lengths below the crane, up to a constant (see the opening comment).
    double closing_rope_length(double z, double angle) const;
    double holding_rope_length(double z, double angle) const;

    // --- dynamics ---
    /// M(angle), for u = (z', angle').
    Eigen::Matrix2d mass_matrix(double angle) const;
    /// The velocity-dependent terms c(angle, u) of Lagrange's equations.
    Eigen::Vector2d velocity_terms(double angle, const Eigen::Vector2d &u) const;
    /// The generalised load of a force's z component @p force_z and a torque's y component
    /// @p torque_y (about the hinge for the shells) acting on @p part.
    Eigen::Vector2d load(Part part, double force_z, double torque_y, double angle) const;
    /// Vertical velocity of @p part's reference point (the hinge; the upper head's pins, over
    /// the last step: the chord of d) and its angular velocity about +y.
    double vertical_velocity(Part part, const State &s) const;
    double angular_velocity(Part part, const State &s) const;

    /// Rope tensions [N] in state @p s (its drums' speeds), the winches' maximum pulls those of
    /// @p closing / @p holding.
    double closing_tension(const State &s, const Winch &closing) const;
    double holding_tension(const State &s, const Winch &holding) const;
    /// u' = M^-1 (Q - c) in state @p s: the particles' generalised load @p particles, gravity
    /// @p g, the ropes' tensions with the winches moving at @p closing and @p holding.
    Eigen::Vector2d acceleration(const State &s, const Eigen::Vector2d &particles, double g, const Winch &closing,
                                 const Winch &holding) const;

    /// One step of @p dt: the generalised load @p particles (the DEM's, at the step's start),
    /// gravity @p g, the winches' speeds and pulls.
    void step(State &s, double dt, const Eigen::Vector2d &particles, double g, const Winch &closing,
              const Winch &holding);

    /// Paid-out lengths that make the ropes carry @p closing and @p holding tension [N] in
    /// state @p s (their damping aside): to start a cycle with the grab hanging.
    void tension_ropes(State &s, double closing, double holding) const;

    /// Kinetic, gravitational (relative to z = 0) and elastic rope energy [J].
    double kinetic_energy(const State &s) const;
    double potential_energy(const State &s, double g) const;
    double rope_energy(const State &s) const;
    double energy(const State &s, double g) const
    {
      return kinetic_energy(s) + potential_energy(s, g) + rope_energy(s);
    }
    /// The work done on the mechanism since it was made (energy(now) - energy(start) equals
    /// winches - damping + loads - stops up to the integration's error).
    const Work &work() const { return ledger; }

  private:
    RopeGrabDesign d;
    double         shell_radius_squared; // |shell centre|^2, the same in every pose
    Work           ledger;

    static double tension(double stiffness, double damping, double stretch, double length_rate, double drum_speed,
                          double maximum_pull);
    /// acceleration() with the ropes' tensions and the mass matrix already at hand (step()).
    Eigen::Vector2d acceleration(const State &s, const Eigen::Vector2d &particles, double g, double t_c, double t_h,
                                 const Eigen::Matrix2d &m) const;
    static void   release(double &paid_out, double length, const Winch &w, double stiffness, Work &ledger);
    static void   wind(double &paid_out, double length_before, double length_after, double t, double dt,
                       double drum_speed, const Winch &w, double stiffness, double damping, Work &ledger);
  };
} // namespace abrade::dem
