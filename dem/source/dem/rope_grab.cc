// A rope grab's closing mechanism: linkage, Lagrange's equations in (z, angle), ropes and
// winches, stops (rope_grab.h).
#include <abrade/dem/rope_grab.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace abrade::dem
{
  namespace
  {
    /// @p v (x, z) turned by @p angle about +y: x' = x cos + z sin, z' = -x sin + z cos.
    Eigen::Vector2d turned(const Eigen::Vector2d &v, double angle)
    {
      const double c = std::cos(angle), s = std::sin(angle);
      return {v.x() * c + v.y() * s, -v.x() * s + v.y() * c};
    }

    std::string in_degrees(double angle) { return std::to_string(angle * 180 / M_PI) + " degrees"; }
  } // namespace

  void RopeGrabDesign::check() const
  {
    const auto fail = [](const std::string &parameter, const std::string &why) {
      throw RopeGrabDesignError(parameter, why);
    };
    if (!(tie_rod_length > 0))
      fail("Tie rod length", "the tie rods need a positive length");
    if (!(upper_pin_offset >= 0))
      fail("Upper pin offset", "the upper head's tie-rod pins need an offset >= 0 from the axis");
    if (falls < 1)
      fail("Falls", "the closing rope needs at least one fall between the heads");
    if (!(shell_mass > 0) || !(shell_inertia >= 0))
      fail("Shell mass", "the shells need a positive mass and an inertia >= 0");
    if (!(lower_head_mass >= 0) || !(upper_head_mass >= 0))
      fail("Lower head mass", "the heads need masses >= 0");
    if (!(closing_rope_stiffness >= 0) || !(holding_rope_stiffness >= 0) || !(closing_rope_damping >= 0) ||
        !(holding_rope_damping >= 0))
      fail("Closing rope stiffness", "rope stiffness and damping must be >= 0");
    if (!(winch_acceleration >= 0))
      fail("Winch acceleration", "the winches' acceleration must be >= 0");
    if (!(closed_angle > open_angle))
      fail("Closed angle", "the closed angle (" + in_degrees(closed_angle) + ") must exceed the open angle (" +
                             in_degrees(open_angle) + ")");
    // the tie rods reach the shells at every angle between the stops, and hauling the closing
    // rope in (a shorter head distance) closes the shells there: d' < 0 (no toggle point)
    const RopeGrab grab(*this, RopeGrab::unchecked);
    constexpr int samples = 64;
    for (int i = 0; i <= samples; ++i)
      {
        const double angle = open_angle + (closed_angle - open_angle) * i / samples;
        const Eigen::Vector2d p = grab.shell_pin(angle);
        if (std::abs(upper_pin_offset - p.x()) >= tie_rod_length)
          fail("Tie rod length", "the tie rods (" + std::to_string(tie_rod_length) +
                                   " m) do not reach the shells' pins at " + in_degrees(angle));
        if (!(grab.head_distance_slope(angle) < 0))
          fail("Shell pin", "the linkage passes its toggle point at " + in_degrees(angle) +
                              " (there, a shorter head distance does not close the shells): move the shells' "
                              "pins or lengthen the tie rods");
        // a mass matrix that cannot be inverted, or nearly (massless heads and shells without
        // inertia whose centres of mass are level with the hinge), leaves a motion without inertia
        const Eigen::Matrix2d m = grab.mass_matrix(angle);
        if (!(m.determinant() > 1e-3 * m(0, 0) * m(1, 1)))
          fail("Lower head mass", "the mechanism has a motion without inertia at " + in_degrees(angle) +
                                    " (its mass matrix is singular): give the heads mass or the shells inertia");
      }
    if (!(grab.head_distance(closed_angle) > 0))
      fail("Closed angle", "the heads meet before the shells close (head distance " +
                             std::to_string(grab.head_distance(closed_angle)) + " m when closed)");
  }

  RopeGrab::RopeGrab(const RopeGrabDesign &design, Unchecked)
    : d(design)
    , shell_radius_squared(design.shell_centre.squaredNorm())
  {}

  RopeGrab::RopeGrab(const RopeGrabDesign &design)
    : RopeGrab(design, unchecked)
  {
    design.check();
  }

  // --- kinematics ---

  Eigen::Vector2d RopeGrab::shell_pin(double angle) const { return turned(d.shell_pin, angle); }

  Eigen::Vector2d RopeGrab::shell_centre(double angle) const { return turned(d.shell_centre, angle); }

  // d = p_z + s with s = sqrt(l^2 - w^2), w = a - p_x; the pin turns as p' = (p_z, -p_x),
  // p'' = -p, so d' = -p_x + w p_z / s and d'' = -p_z - (p_z^2 + w p_x) / s - (w p_z)^2 / s^3.
  double RopeGrab::head_distance(double angle) const
  {
    const Eigen::Vector2d p = shell_pin(angle);
    const double          w = d.upper_pin_offset - p.x(), r = d.tie_rod_length * d.tie_rod_length - w * w;
    if (!(r >= 0))
      throw std::domain_error("rope grab: the tie rods do not reach the shells at " + in_degrees(angle));
    return p.y() + std::sqrt(r);
  }

  double RopeGrab::head_distance_slope(double angle) const
  {
    const Eigen::Vector2d p = shell_pin(angle);
    const double          w = d.upper_pin_offset - p.x();
    const double          s = std::sqrt(d.tie_rod_length * d.tie_rod_length - w * w);
    return -p.x() + w * p.y() / s;
  }

  double RopeGrab::head_distance_curvature(double angle) const
  {
    const Eigen::Vector2d p = shell_pin(angle);
    const double          w = d.upper_pin_offset - p.x();
    const double          s = std::sqrt(d.tie_rod_length * d.tie_rod_length - w * w);
    return -p.y() - (p.y() * p.y() + w * p.x()) / s - std::pow(w * p.y(), 2) / (s * s * s);
  }

  double RopeGrab::angle_at_head_distance(double distance) const
  {
    // head_distance falls monotonically between the stops (check()); bisection there, then
    // beyond the stops only if the distance asks for it
    double lo = d.open_angle, hi = d.closed_angle;
    const auto outside = [&] {
      throw std::domain_error("rope grab: no shell angle between the stops gives a head distance of " +
                              std::to_string(distance) + " m (open: " + std::to_string(head_distance(lo)) +
                              " m, closed: " + std::to_string(head_distance(hi)) + " m)");
    };
    if (distance > head_distance(lo) || distance < head_distance(hi))
      outside();
    for (int i = 0; i < 200 && hi - lo > 1e-15; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (head_distance(mid) > distance ? lo : hi) = mid;
      }
    return 0.5 * (lo + hi);
  }

  double RopeGrab::closing_rope_length(double z, double angle) const
  {
    return -z + (d.falls - 1) * head_distance(angle);
  }

  double RopeGrab::holding_rope_length(double z, double angle) const { return -z - head_distance(angle); }

  // --- dynamics ---
  //
  // The bodies' velocities in u = (z', angle'): lower head (z', 0); upper head (z' + d' angle');
  // right shell's centre of mass (0, z') + c' angle' with c' = (c_z, -c_x), spinning at angle'
  // (the left shell mirrored). Hence, with m the total mass,
  //   M = [ m                       m_u d' - 2 m_s c_x                  ]
  //       [ m_u d' - 2 m_s c_x      m_u d'^2 + 2 (m_s |c|^2 + I_s)      ]
  // and, M depending on the angle only, Lagrange's velocity terms are
  //   c = ( M_za' angle'^2,  1/2 M_aa' angle'^2 ),  M_za' = m_u d'' - 2 m_s c_z,  M_aa' = 2 m_u d' d''.

  Eigen::Matrix2d RopeGrab::mass_matrix(double angle) const
  {
    const double          slope = head_distance_slope(angle);
    const Eigen::Vector2d c     = shell_centre(angle);
    Eigen::Matrix2d       m;
    m(0, 0) = d.lower_head_mass + d.upper_head_mass + 2 * d.shell_mass;
    m(0, 1) = m(1, 0) = d.upper_head_mass * slope - 2 * d.shell_mass * c.x();
    m(1, 1) = d.upper_head_mass * slope * slope + 2 * (d.shell_mass * shell_radius_squared + d.shell_inertia);
    return m;
  }

  Eigen::Vector2d RopeGrab::velocity_terms(double angle, const Eigen::Vector2d &u) const
  {
    const double slope = head_distance_slope(angle), curvature = head_distance_curvature(angle);
    const double m_za_rate = d.upper_head_mass * curvature - 2 * d.shell_mass * shell_centre(angle).y();
    const double m_aa_rate = 2 * d.upper_head_mass * slope * curvature;
    const double w2        = u[1] * u[1];
    return {m_za_rate * w2, 0.5 * m_aa_rate * w2};
  }

  Eigen::Vector2d RopeGrab::load(Part part, double force_z, double torque_y, double angle) const
  {
    switch (part)
      {
        case Part::lower_head:
          return {force_z, 0};
        case Part::upper_head:
          return {force_z, force_z * head_distance_slope(angle)};
        case Part::right_shell:
          return {force_z, torque_y};
        case Part::left_shell:
          return {force_z, -torque_y};
      }
    return {0, 0};
  }

  double RopeGrab::vertical_velocity(Part part, const State &s) const
  {
    return part == Part::upper_head ? s.z_rate + s.head_distance_rate : s.z_rate;
  }

  double RopeGrab::angular_velocity(Part part, const State &s) const
  {
    switch (part)
      {
        case Part::right_shell:
          return s.angle_rate;
        case Part::left_shell:
          return -s.angle_rate;
        default:
          return 0;
      }
  }

  // --- ropes ---

  // A stalled winch (the rope stretched to its maximum pull) pays out as fast as the grab draws
  // the rope: the stretch stays, no damping, the maximum pull.
  double RopeGrab::tension(double stiffness, double damping, double stretch, double length_rate, double drum_speed,
                           double maximum_pull)
  {
    if (!(stretch > 0) || stiffness == 0)
      return 0;
    if (stiffness * stretch >= maximum_pull * (1 - 1e-12))
      return maximum_pull;
    return std::clamp(stiffness * stretch + damping * (length_rate + drum_speed), 0.0, maximum_pull);
  }

  double RopeGrab::closing_tension(const State &s, const Winch &closing) const
  {
    const double rate = -s.z_rate + (d.falls - 1) * head_distance_slope(s.angle) * s.angle_rate;
    return tension(d.closing_rope_stiffness, d.closing_rope_damping, closing_rope_length(s.z, s.angle) - s.closing_paid_out,
                   rate, s.closing_drum_speed, closing.maximum_pull);
  }

  double RopeGrab::holding_tension(const State &s, const Winch &holding) const
  {
    const double rate = -s.z_rate - head_distance_slope(s.angle) * s.angle_rate;
    return tension(d.holding_rope_stiffness, d.holding_rope_damping, holding_rope_length(s.z, s.angle) - s.holding_paid_out,
                   rate, s.holding_drum_speed, holding.maximum_pull);
  }

  // A winch whose maximum pull is below the rope's tension (a phase that asks for less, a
  // slack rope) lets go at once: the drum pays out to the maximum pull, taking the elastic
  // energy above it.
  void RopeGrab::release(double &paid_out, double length, const Winch &w, double stiffness, Work &ledger)
  {
    if (!(stiffness > 0) || !(stiffness * (length - paid_out) > w.maximum_pull))
      return;
    const double stretch = length - paid_out, least = length - w.maximum_pull / stiffness;
    ledger.winches -= 0.5 * stiffness * stretch * stretch - 0.5 * w.maximum_pull * w.maximum_pull / stiffness;
    paid_out = least;
  }

  // One rope over one step. The drum hauls in at its speed against the tension @p t of the
  // step's start; where that stretches the rope beyond the maximum pull, it then pays out (a
  // stalled winch slips on its brake or its motor's torque) at the maximum pull. A drum of
  // maximum pull 0 follows the rope: no tension, no work.
  void RopeGrab::wind(double &paid_out, double length_before, double length_after, double t, double dt,
                      double drum_speed, const Winch &w, double stiffness, double damping, Work &ledger)
  {
    if (w.maximum_pull == 0)
      {
        paid_out = length_after;
        return;
      }
    const double stretch = length_before - paid_out;
    paid_out -= drum_speed * dt;
    ledger.winches += t * drum_speed * dt;
    if (damping > 0 && stretch > 0) // the tension beyond k e, over the stretch's change
      ledger.damping += (t - stiffness * stretch) * ((length_after - paid_out) - stretch);
    if (stiffness > 0 && w.maximum_pull < std::numeric_limits<double>::infinity())
      {
        const double least = length_after - w.maximum_pull / stiffness;
        if (paid_out < least)
          {
            ledger.winches -= w.maximum_pull * (least - paid_out);
            paid_out = least;
          }
      }
  }

  void RopeGrab::tension_ropes(State &s, double closing, double holding) const
  {
    if (d.closing_rope_stiffness > 0)
      s.closing_paid_out = closing_rope_length(s.z, s.angle) - closing / d.closing_rope_stiffness;
    if (d.holding_rope_stiffness > 0)
      s.holding_paid_out = holding_rope_length(s.z, s.angle) - holding / d.holding_rope_stiffness;
  }

  // --- one step ---

  Eigen::Vector2d RopeGrab::acceleration(const State &s, const Eigen::Vector2d &particles, double g,
                                         const Winch &closing, const Winch &holding) const
  {
    return acceleration(s, particles, g, closing_tension(s, closing), holding_tension(s, holding),
                        mass_matrix(s.angle));
  }

  Eigen::Vector2d RopeGrab::acceleration(const State &s, const Eigen::Vector2d &particles, double g, double t_c,
                                         double t_h, const Eigen::Matrix2d &m) const
  {
    const double slope = head_distance_slope(s.angle);
    // the ropes' loads: -T grad L, with grad L_c = (-1, (n-1) d') and grad L_h = (-1, -d')
    const Eigen::Vector2d ropes(t_c + t_h, -(d.falls - 1) * slope * t_c + slope * t_h);
    const Eigen::Vector2d u(s.z_rate, s.angle_rate);
    // gravity: V = g (m z + m_u d + 2 m_s c_z), whose gradient is g times M's first column
    return m.partialPivLu().solve(particles - g * m.col(0) + ropes - velocity_terms(s.angle, u));
  }

  void RopeGrab::step(State &s, double dt, const Eigen::Vector2d &particles, double g, const Winch &closing,
                      const Winch &holding)
  {
    // the drums' speeds approach the winches', a drum that keeps its rope just slack (pull 0)
    // too: its motor turns at the speed it is given (a closing winch paying out as the grab
    // lands is reversed at the winch's acceleration, not stopped at once)
    s.closing_drum_speed = ramped(s.closing_drum_speed, closing.speed, d.winch_acceleration, dt);
    s.holding_drum_speed = ramped(s.holding_drum_speed, holding.speed, d.winch_acceleration, dt);
    const double rope_c = closing_rope_length(s.z, s.angle), rope_h = holding_rope_length(s.z, s.angle);
    release(s.closing_paid_out, rope_c, closing, d.closing_rope_stiffness, ledger);
    release(s.holding_paid_out, rope_h, holding, d.holding_rope_stiffness, ledger);
    const double t_c = closing_tension(s, closing), t_h = holding_tension(s, holding);
    const Eigen::Matrix2d m = mass_matrix(s.angle);
    Eigen::Vector2d u       = Eigen::Vector2d(s.z_rate, s.angle_rate) + dt * acceleration(s, particles, g, t_c, t_h, m);

    // The stops: the step ends at the stop, the vertical momentum M_zz z' + M_za angle' kept
    // (the velocity projected, in M's metric, onto the motions that keep the angle). Resting on
    // a stop this is the constraint force of a fixed angle, which does no work; arriving at one
    // it is a plastic impact, which loses the energy of the shells' approach, 1/2 M_eff angle'^2
    // with M_eff = M_aa - M_za^2 / M_zz (the angle's inertia with the grab free to move up or
    // down).
    const double next = s.angle + dt * u[1];
    if (next > d.closed_angle || next < d.open_angle)
      {
        const double          target = std::clamp(next, d.open_angle, d.closed_angle);
        const Eigen::Vector2d free   = u;
        u[1]                         = (target - s.angle) / dt;
        u[0] += m(0, 1) * (free[1] - u[1]) / m(0, 0);
        const double approach = (target - s.angle) * s.angle_rate > 0 ? s.angle_rate : 0.0;
        ledger.stops += 0.5 * (m(1, 1) - m(0, 1) * m(0, 1) / m(0, 0)) * approach * approach;
      }

    const double z0 = s.z, angle0 = s.angle;
    s.z_rate        = u[0];
    s.angle_rate    = u[1];
    const double d0 = head_distance(s.angle);
    s.z += dt * u[0];
    s.angle += dt * u[1];
    s.head_distance_rate = (head_distance(s.angle) - d0) / dt;
    ledger.loads += particles.dot(Eigen::Vector2d(s.z - z0, s.angle - angle0));

    wind(s.closing_paid_out, rope_c, closing_rope_length(s.z, s.angle), t_c, dt, s.closing_drum_speed, closing,
         d.closing_rope_stiffness, d.closing_rope_damping, ledger);
    wind(s.holding_paid_out, rope_h, holding_rope_length(s.z, s.angle), t_h, dt, s.holding_drum_speed, holding,
         d.holding_rope_stiffness, d.holding_rope_damping, ledger);
  }

  // --- energy ---

  double RopeGrab::kinetic_energy(const State &s) const
  {
    const Eigen::Vector2d u(s.z_rate, s.angle_rate);
    return 0.5 * u.dot(mass_matrix(s.angle) * u);
  }

  double RopeGrab::potential_energy(const State &s, double g) const
  {
    const double m = d.lower_head_mass + d.upper_head_mass + 2 * d.shell_mass;
    return g * (m * s.z + d.upper_head_mass * head_distance(s.angle) + 2 * d.shell_mass * shell_centre(s.angle).y());
  }

  double RopeGrab::rope_energy(const State &s) const
  {
    const auto elastic = [](double k, double stretch) { return stretch > 0 ? 0.5 * k * stretch * stretch : 0.0; };
    return elastic(d.closing_rope_stiffness, closing_rope_length(s.z, s.angle) - s.closing_paid_out) +
           elastic(d.holding_rope_stiffness, holding_rope_length(s.z, s.angle) - s.holding_paid_out);
  }
} // namespace abrade::dem
