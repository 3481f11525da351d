#pragma once
// The names of the lifetime outputs that hold the chosen wear field's volume (Output/Wear field):
// named after the field, so that an Oka run's trajectory says oka_volume, not archard_volume.
#include <string>

namespace abrade::coupling::lifetime
{
  struct WearFieldColumns
  {
    WearFieldColumns() = default;
    /// For the volume field @p field of a wear law ("archard_volume", "oka_volume").
    explicit WearFieldColumns(const std::string &field)
      : volume(field), swept_over("swept_over_" + law_of(field)), worn_over("worn_over_" + law_of(field))
    {}

    std::string volume = "archard_volume";         ///< the field's volume (per update; per phase: _PHASE)
    std::string swept_over = "swept_over_archard"; ///< the volume the surface swept over it
    std::string worn_over  = "worn_over_archard";  ///< the volume worn over the whole life's

  private:
    static std::string law_of(const std::string &field)
    {
      const std::string suffix = "_volume";
      return field.size() > suffix.size() && field.compare(field.size() - suffix.size(), suffix.size(), suffix) == 0
               ? field.substr(0, field.size() - suffix.size())
               : field;
    }
  };
} // namespace abrade::coupling::lifetime
