#pragma once
// The names a wear field's outputs go by, for the DEM that writes them and the report and
// studies that read them back without the DEM's classes: a field of removed volume
// ("archard_volume", "oka_volume", in m^3) has a per-triangle depth field, its volume over the
// triangle's area ("archard_depth"); a field that is a depth already ("finnie_wear", in m) is
// its own.
#include <string>

namespace abrade::io
{
  /// The depth field of volume field @p field: "archard_volume" -> "archard_depth" (a name
  /// without "_volume": "_depth" appended).
  inline std::string wear_depth_name(const std::string &field)
  {
    const std::string suffix = "_volume";
    const bool        ends   = field.size() > suffix.size() &&
                        field.compare(field.size() - suffix.size(), suffix.size(), suffix) == 0;
    return (ends ? field.substr(0, field.size() - suffix.size()) : field) + "_depth";
  }

  /// The per-triangle field of a snapshot that shows @p field as a depth: its depth field for
  /// a volume ("archard_volume" -> "archard_depth"), else the field itself ("finnie_wear").
  inline std::string wear_surface_field(const std::string &field)
  {
    const std::string suffix = "_volume";
    const bool        volume = field.size() > suffix.size() &&
                        field.compare(field.size() - suffix.size(), suffix.size(), suffix) == 0;
    return volume ? wear_depth_name(field) : field;
  }
} // namespace abrade::io
