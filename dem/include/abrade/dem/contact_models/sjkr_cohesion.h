#pragma once
// Cohesion as the simplified JKR model (LIGGGHTS' `cohesion sjkr`, the same law as EDEM's
// "Linear Cohesion"; not EDEM's full "Hertz-Mindlin with JKR"): an attraction k_c A along the normal while the bodies overlap,
// with k_c the cohesion energy density of the interaction [J/m^3] and A = pi a^2 the area of the
// circle in which the two spheres (a sphere and a plane) intersect,
//
//   pair:  A = pi/4 (-(d - ri - rj)) (d + ri - rj) (d - ri + rj) (d + ri + rj) / d^2,
//   wall:  A = pi (ri^2 - d^2),
//
// d the distance of the centres (of the centre from the wall). The Coulomb limit of the
// tangential force and the rolling limits use the repulsive normal force, as LIGGGHTS does by
// default (tangential_reduce off). No attraction beyond contact: the bodies separate at zero
// overlap, and the largest pull the contact holds is the minimum of F_el - k_c A over the
// overlap (-(2/3) pi^3 k_c^3 R*^2 / E*^2 for a small overlap, docs/physics.md).
#include <abrade/dem/contact_models/contact_state.h>
#include <abrade/dem/material.h>
#include <abrade/dem/parameter_section.h>

namespace abrade::dem::contact_models
{
  struct SjkrCohesion
  {
    static constexpr const char *name = "sjkr";
    static constexpr const char *documentation =
      "simplified JKR (LIGGGHTS' sjkr, EDEM's linear cohesion): an attraction Cohesion energy density x the "
      "contact area pi a^2";
    static constexpr bool needs_area = true; ///< reads ContactState::area

    static void declare_parameters(ParameterSection &p)
    {
      p.declare_number("Cohesion energy density", 0, 0, 1e15,
                       "[J/m^3] Cohesion model sjkr: k_c, the attraction per unit contact area (LIGGGHTS' "
                       "cohesionEnergyDensity). Range: >= 0.");
    }
    static void parse_parameters(const ParameterSection &p, Interaction &i)
    {
      i.cohesion_energy_density = p.number("Cohesion energy density");
    }

    [[gnu::always_inline]] static inline void evaluate(const ContactState &s, const PairCoefficients &c, ContactResponse &r)
    {
      r.normal = r.repulsion - c.cohesion_energy_density * s.area;
    }
  };
} // namespace abrade::dem::contact_models
