#pragma once
// Every entry, subsection and choice of the parameter files that was renamed or moved, with the
// printed layout it began (a layout: the parameters as one generation of abrade printed them,
// in a run's parameters.prm and a lifetime checkpoint's hash). Two readers: an older file is
// read under today's names (parameter_text.h, read_moved_entries), and today's printing is
// written back as each earlier layout printed it (earlier_printings.h), so that an earlier
// abrade's run directory is resumed and rerun.
#include <string>
#include <vector>

namespace abrade::coupling::renames
{
  /// The layouts, oldest first: 0, the earliest an abrade still reads back; 1, subsection Knife
  /// named Part; 2, Job = knife named part; 3, the wear sources' entries in their own
  /// subsections of Lifetime, the mounting entries named for any part and the velocity table the
  /// motions' own that follow it (a fixed wall has none); 4, a multi-level bed's Fine region
  /// pours. Today's is the last.
  inline constexpr int current_layout = 5;

  /// An entry that moved: key @p old_key of a subsection named @p in (every top-level
  /// subsection whose name begins so, where @p in ends in a blank: "Wall ") is now @p key of
  /// its subsection @p now (empty: of the same subsection, renamed), because @p why, since
  /// @p layout.
  struct MovedEntry
  {
    const char *in, *old_key, *now, *key, *why;
    int         layout;
  };
  // each plugin's parameters moved into its own subsection: a wear law's in Wear, a wear
  // source's in Lifetime; the part on a shell's lip need not be a knife
  inline constexpr const char *law_has_one    = "each wear law has its subsection";
  inline constexpr const char *source_has_one = "each wear source has its subsection";
  inline constexpr const char *not_a_knife    = "the part mounted need not be a knife";
  inline constexpr MovedEntry  moved_entries[] = {
    {"Wear", "Archard coefficient", "Archard", "Coefficient", law_has_one, 0},
    {"Wear", "Finnie coefficient", "Finnie", "Coefficient", law_has_one, 0},
    {"Lifetime", "Analytic wear rate", "Analytic", "Wear rate", source_has_one, 3},
    {"Lifetime", "Analytic wear is", "Analytic", "Wear is", source_has_one, 3},
    {"Lifetime", "Analytic seed scatter", "Analytic", "Seed scatter", source_has_one, 3},
    {"Lifetime", "Replay run", "Replay", "Run", source_has_one, 3},
    {"Lifetime", "Ranks per bed", "DEM", "Ranks per bed", source_has_one, 3},
    {"Wall ", "Knife mount", "", "Mounted on", not_a_knife, 3},
    {"Wall ", "Knife protrusion", "", "Protrusion", not_a_knife, 3}};

  /// Whether subsection @p path (its names from the top) is one that entry @p m was in.
  inline bool was_in(const MovedEntry &m, const std::vector<std::string> &path)
  {
    const std::string in = m.in;
    if (in.back() == ' ')
      return path.size() == 1 && path[0].rfind(in, 0) == 0;
    return !path.empty() && path.back() == in;
  }

  /// A top-level subsection that was renamed: @p old_name is now @p name, since @p layout.
  struct RenamedSubsection
  {
    const char *old_name, *name;
    int         layout;
  };
  // the part that wears need not be a knife (a liner, a bucket's lip)
  inline constexpr RenamedSubsection renamed_subsections[] = {{"Knife", "Part", 1}};

  /// A choice of a top-level entry that was renamed: @p key = @p old_value is now @p key =
  /// @p value, since @p layout.
  struct RenamedValue
  {
    const char *key, *old_value, *value;
    int         layout;
  };
  // the job that builds the part alone (the part need not be a knife)
  inline constexpr RenamedValue renamed_values[] = {{"Job", "knife", "part", 2}};

  /// An entry that was added: @p key of subsection @p path ("Particles/Coarse graining"),
  /// printed as @p value by default, since @p layout (the layouts before did not print it).
  struct AddedEntry
  {
    const char *path, *key, *value;
    int         layout;
  };
  // a multi-level bed poured again, refilled by what its fine region lacked (4); the DEM after a
  // replay's worn state (5)
  inline constexpr AddedEntry added_entries[] = {{"Particles/Coarse graining", "Fine region pours", "3", 4},
                                                 {"Lifetime/Replay", "DEM from", "0", 5}};
} // namespace abrade::coupling::renames
