#pragma once
// Materials, particle-particle / particle-wall interaction properties, and the contact
// coefficients precomputed per pair of materials (shared/reference/physics.md, section 1).
#include <string>

namespace abrade::dem
{
  struct Material
  {
    std::string name;
    double      youngs_modulus = 0; ///< E [Pa]
    double      poisson_ratio  = 0; ///< nu [-]
    double      density        = 0; ///< rho [kg/m^3]
    /// false: angular velocity is capped at 0 (the thesis' non-rotating pellets: docs/physics.md).
    bool rotation = true;

    double shear_modulus() const { return youngs_modulus / (2 * (1 + poisson_ratio)); }
    static Material from_shear_modulus(const std::string &name, double G, double nu, double rho,
                                       bool rotation = true);
  };

  /// Properties of an interaction between two materials.
  struct Interaction
  {
    double restitution      = 0.6; ///< e in (0, 1]
    double friction         = 0.5; ///< static friction coefficient mu_s
    double rolling_friction = 0.0; ///< mu_r (the rolling model's limit torque mu_r |F_n| r)
    // parameters of the optional contact sub-models (contact_law.h; each declares and reads its own)
    double cohesion_energy_density = 0.0; ///< k_c [J/m^3] of the sjkr cohesion model
    double rolling_damping         = 0.3; ///< eta_r [-] of the epsd rolling model
  };

  /// The run-time choice of contact sub-models (contact_law.h; Simulation/Rolling model,
  /// Simulation/Cohesion model).
  struct ContactModel
  {
    std::string rolling  = "constant torque";
    std::string cohesion = "none";
  };

  /// How the normal/tangential damping follows from the restitution coefficient.
  enum class DampingModel
  {
    edem,       ///< beta = ln e / sqrt(ln^2 e + pi^2), as documented by EDEM and LIGGGHTS
    calibrated, ///< damping chosen so that a Hertz contact rebounds with exactly e
  };

  /// Everything the Hertz-Mindlin kernel needs for one pair of materials.
  struct PairCoefficients
  {
    double e_star           = 0; ///< effective Young's modulus E*
    double g_star           = 0; ///< effective shear modulus G*
    double damping          = 0; ///< c = damping * sqrt(S m*)  (= -2 sqrt(5/6) beta for edem)
    double sqrt_2e          = 0; ///< sqrt(2 E*): S_n m* = 2 E* sqrt(R* d) m*
    double sqrt_8g          = 0; ///< sqrt(8 G*)
    double friction         = 0;
    double rolling_friction = 0;
    double restitution      = 1;
    double cohesion_energy_density = 0;
    double rolling_damping         = 0;
  };

  PairCoefficients make_pair_coefficients(const Material &a, const Material &b,
                                          const Interaction &i, DampingModel model);

  /// EDEM's beta (negative for e < 1, zero for e = 1).
  double edem_beta(double restitution);

  /// Restitution that the damping factor @p damping (c = damping sqrt(S_n m*)) gives for a Hertz
  /// contact; velocity independent. Found by integrating the dimensionless contact ODE.
  double hertz_restitution(double damping);

  /// Inverse of hertz_restitution(), by bisection.
  double calibrated_damping(double restitution);
} // namespace abrade::dem
