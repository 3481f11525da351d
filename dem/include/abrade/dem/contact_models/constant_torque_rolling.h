#pragma once
// Rolling resistance as EDEM's constant directional torque (EDEM's "type A"; Ai et al. 2011,
// model A): a torque of magnitude mu_r |F_n| r_i against each body's spin. The sub-model hands
// the magnitude mu_r |F_n| on; the time integration applies it to each body's spin as a
// braking that never reverses it (simulation.cc, spin_kick), which keeps a jammed particle from
// chattering.
#include <abrade/dem/contact_models/contact_state.h>
#include <abrade/dem/material.h>
#include <abrade/dem/parameter_section.h>

#include <cmath>

namespace abrade::dem::contact_models
{
  struct ConstantTorqueRolling
  {
    static constexpr const char *name = "constant torque";
    static constexpr const char *documentation =
      "EDEM's constant directional torque mu_r |F_n| r against each particle's spin (never reversing it)";
    static constexpr int  history        = 0;
    static constexpr bool needs_rotation = false; ///< reads ContactState::wx.. and rolling_inertia

    static void declare_parameters(ParameterSection &) {}
    static void parse_parameters(const ParameterSection &, Interaction &) {}

    [[gnu::always_inline]] static inline void evaluate(const ContactState &, const PairCoefficients &c, double, double *, ContactResponse &r)
    {
      r.rolling_limit = c.rolling_friction * std::abs(r.repulsion);
      r.mx = r.my = r.mz = 0;
    }
  };
} // namespace abrade::dem::contact_models
