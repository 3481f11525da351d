#pragma once
// The contact law, composed from sub-models in the manner of LAMMPS' granular pair style:
//
//   normal + damping + tangential   Hertz-Mindlin (no slip) as EDEM defines it, with the
//                                   damping of Simulation/Damping model (hertz_mindlin.h);
//   rolling                         Simulation/Rolling model: constant torque (EDEM, the
//                                   default) or epsd (elastic-plastic spring-dashpot);
//   cohesion                        Simulation/Cohesion model: none (the default) or sjkr.
//
// A sub-model is a struct of static inline functions in its own header under contact_models/
// (its name, its documentation, the history it keeps per contact, the per-interaction
// parameters it declares and reads, and evaluate()). The choice is made once per step:
// with_contact_law() turns the run-time names into a ContactLaw<Rolling, Cohesion> type, and the
// pair kernel (pair_forces.cc) and the wall contacts (wall_forces.cc) are compiled for each
// combination, so there is no dispatch per contact and the batched pair loop still vectorises.
// Pairs and walls call the same ContactLaw::evaluate(): one source for each law.
//
// To add a rolling or cohesion model: write its header (copy epsd_rolling.h or
// sjkr_cohesion.h) and add its type to RollingModels or CohesionModels below
// (docs/developer-guide.md, "Add a contact sub-model").
#include <abrade/common/error.h>
#include <abrade/dem/contact_models/constant_torque_rolling.h>
#include <abrade/dem/contact_models/contact_state.h>
#include <abrade/dem/contact_models/epsd_rolling.h>
#include <abrade/dem/contact_models/hertz_mindlin.h>
#include <abrade/dem/contact_models/sjkr_cohesion.h>

#include <string>
#include <tuple>
#include <vector>

namespace abrade::dem
{
  namespace contact_models
  {
    /// The default cohesion model: none.
    struct NoCohesion
    {
      static constexpr const char *name          = "none";
      static constexpr const char *documentation = "no attraction";
      static constexpr bool        needs_area    = false;

      static void declare_parameters(ParameterSection &) {}
      static void parse_parameters(const ParameterSection &, Interaction &) {}
      [[gnu::always_inline]] static inline void evaluate(const ContactState &, const PairCoefficients &, ContactResponse &) {}
    };
  } // namespace contact_models

  // The sub-models a user can choose, one line each (the first is the default).
  using RollingModels  = std::tuple<contact_models::ConstantTorqueRolling, contact_models::EpsdRolling>;
  using CohesionModels = std::tuple<contact_models::NoCohesion, contact_models::SjkrCohesion>;

  /// Hertz-Mindlin with rolling model @p Rolling and cohesion model @p Cohesion.
  template <class Rolling, class Cohesion>
  struct ContactLaw
  {
    using Base                              = contact_models::HertzMindlin;
    static constexpr int  history           = Base::history + Rolling::history; ///< doubles per contact
    static constexpr bool needs_rotation    = Rolling::needs_rotation;
    static constexpr bool needs_area        = Cohesion::needs_area;
    static constexpr bool constant_torque   = std::is_same_v<Rolling, contact_models::ConstantTorqueRolling>;

    /// The force on body i of contact @p s; @p h: its history (history doubles), updated.
    [[gnu::always_inline]] static inline ContactResponse evaluate(const ContactState &s, const PairCoefficients &c, double dt, double *h)
    {
      ContactResponse r;
      Base::evaluate(s, c, dt, h, r);
      Cohesion::evaluate(s, c, r);
      Rolling::evaluate(s, c, dt, h + Base::history, r);
      return r;
    }
  };

  namespace detail
  {
    template <class Models, std::size_t k = 0, class F>
    void with_model(const std::string &name, const char *kind, F &&f)
    {
      if constexpr (k < std::tuple_size_v<Models>)
        {
          using M = std::tuple_element_t<k, Models>;
          if (name == M::name)
            return f(M{});
          return with_model<Models, k + 1>(name, kind, std::forward<F>(f));
        }
      else
        throw InputError("", std::string("unknown ") + kind + " model '" + name + "'");
    }

    template <class Models, std::size_t... k>
    std::vector<std::string> names_of(std::index_sequence<k...>)
    {
      return {std::tuple_element_t<k, Models>::name...};
    }
  } // namespace detail

  /// Calls @p f with ContactLaw<Rolling, Cohesion>{} for the models named in @p m.
  template <class F>
  void with_contact_law(const ContactModel &m, F &&f)
  {
    detail::with_model<RollingModels>(m.rolling, "rolling", [&](auto rolling) {
      detail::with_model<CohesionModels>(m.cohesion, "cohesion", [&](auto cohesion) {
        f(ContactLaw<decltype(rolling), decltype(cohesion)>{});
      });
    });
  }

  /// Calls @p f with every model of @p Models (declaring their parameters, listing them).
  template <class Models, class F>
  void for_each_model(F &&f)
  {
    std::apply([&](auto... m) { (f(m), ...); }, Models{});
  }

  template <class Models>
  std::vector<std::string> model_names()
  {
    return detail::names_of<Models>(std::make_index_sequence<std::tuple_size_v<Models>>{});
  }
} // namespace abrade::dem
