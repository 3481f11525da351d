#pragma once
// The parameters as earlier abrades printed them. A run's parameters.prm, and the hash a
// lifetime checkpoint keeps, are the printed parameters (deal.II's ShortPRM: every entry,
// sorted, aligned); an earlier abrade printed the same parameters under the names and in the
// places of its layout (parameter_renames.h). Written back so, an earlier run's directory is
// recognised as the same parameters: `run DIR/parameters.prm --output DIR` and `--resume` go on
// in it.
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// @p printed (ParameterFile::canonical_text()'s) as each earlier layout printed it, the
  /// latest first (layout current_layout - 1, ..., 0): every rename and move of a later layout
  /// undone, in deal.II's sorted and aligned form, and the entries a later layout dropped put
  /// back with the values they had (a fixed wall's velocity table: its wall's default).
  std::vector<std::string> earlier_printings(const std::string &printed);
} // namespace abrade::coupling
