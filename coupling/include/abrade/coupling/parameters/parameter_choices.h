#pragma once
// Enumerations in parameter files, spelled once: a list of (name, value) pairs gives both the
// entry's pattern (selection_of) and the value a name stands for (get_choice), so that no
// ternary chain of string comparisons can fall through to a wrong default.
#include <abrade/common/error.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <utility>
#include <vector>

namespace abrade::coupling
{
  template <typename T>
  using Choices = std::vector<std::pair<std::string, T>>;

  /// The entry pattern "name1|name2|...".
  template <typename T>
  dealii::Patterns::Selection selection_of(const Choices<T> &choices)
  {
    std::string names;
    for (const auto &c : choices)
      names += (names.empty() ? "" : "|") + c.first;
    return dealii::Patterns::Selection(names);
  }

  /// What @p value stands for among @p choices (@p name: the entry it was read from, whose
  /// pattern, selection_of(@p choices), checked it).
  template <typename T>
  T choice_named(const std::string &value, const std::string &name, const Choices<T> &choices)
  {
    for (const auto &c : choices)
      if (c.first == value)
        return c.second;
    throw RunError("parameter '" + name + "' = '" + value + "' passed its pattern but names no choice");
  }

  /// The value of entry @p name of the current subsection.
  template <typename T>
  T get_choice(dealii::ParameterHandler &prm, const std::string &name, const Choices<T> &choices)
  {
    return choice_named(prm.get(name), name, choices);
  }
} // namespace abrade::coupling
