#pragma once
// The text of a parameter file as deal.II's ParameterHandler reads it, line by line: which
// subsections a line is in and what it sets, for the reader's own messages (where a key is set)
// and for leaving out the entries of a wall's replaced geometry or motion.
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>

#include <string>
#include <utility>
#include <vector>

namespace abrade::coupling
{
  /// The lines of @p text.
  std::vector<std::string> lines_of(const std::string &text);

  /// @p line as deal.II reads it: a tab is a blank, and leading and trailing blanks go (its
  /// comment stays: deal.II joins continued lines first).
  std::string as_read(std::string line);

  /// Whether @p line (as_read) starts with keyword @p word in one of deal.II's spellings
  /// ("set", "SET"), followed by a blank.
  bool starts_with_keyword(const std::string &line, const std::string &word);

  /// What a line of a parameter file is. A line ending in '\' and the ones it continues into are
  /// one (deal.II trims each line and joins it with the next): the first holds what they say,
  /// and `last` is the last of them.
  struct LineEntry
  {
    std::vector<std::string> path;  ///< the subsections it is in
    std::string              key;   ///< the key it sets ("": none)
    std::string              value; ///< the value it gives the key, comment removed
    std::string              opens; ///< the subsection it opens ("": none)
    std::size_t              last = 0;
  };

  /// Every line of @p lines, as deal.II reads it ("set" and "SET", "subsection" and
  /// "SUBSECTION", "end" and "END").
  std::vector<LineEntry> entries_by_line(const std::vector<std::string> &lines);

  /// Whether @p key = @p value (in subsection @p path) is an entry of another geometry or motion
  /// than the wall's (@p lists) at that one's default: a no-op, left out.
  bool is_foreign_default(const DeclarationLists &lists, const std::vector<std::string> &path, const std::string &key,
                          const std::string &value);

  /// "Wall knife/Wear/Archard" + "/" + @p key: an entry's full name, as --set spells it.
  std::string entry_path(const std::vector<std::string> &path, const std::string &key);

  /// The entry a --set (or --vary) @p set names ("Section/Key=value", the value optional),
  /// spelt as the parameter file reads it now: each part trimmed, empty ones left out, and a
  /// renamed subsection or moved entry under its name now ("Knife / Length" is "Part/Length").
  /// Two spellings of one entry give the same text.
  std::string entry_as_now(const std::string &set);

  /// For @p key, an entry that moved ("Archard coefficient"), where it is now ("'Archard
  /// coefficient' moved: subsection Archard, set Coefficient (inside Wear: ...)."); "" for any
  /// other key. Said where the old spelling is set outside the subsection it moved from.
  std::string moved_entry_hint(const std::string &key);

  /// Entries, subsections and choices that moved keep working under their old spelling. A
  /// top-level subsection of an old name (`subsection Knife`, now `subsection Part`) is read
  /// under its name now, its line rewritten in place, and a --set of it likewise; so is a
  /// top-level choice of an old name (`set Job = knife`, now `part`). Each line of @p text
  /// that sets an entry that moved (`set Archard coefficient = W` in a wall's Wear) becomes the
  /// entry where it is now (`subsection Archard`, `set Coefficient = W`, `end`), in place, so
  /// that the last setting still wins; @p origin follows the new lines (a line continued with
  /// '\' becomes one, the lines it continued into blank). Each --set of @p overrides with an old
  /// path is rewritten likewise. Returns a note per old spelling read: where it was read
  /// ("file:line" or "--set '...'") and where it is now.
  struct MovedNote
  {
    std::string where, what;
    std::string text() const { return where + ": " + what; }
  };
  std::vector<MovedNote> read_moved_entries(std::string &text, std::vector<std::pair<std::string, int>> &origin,
                                            const std::string &file, std::vector<Override> &overrides);

  /// Leaves out of @p text (blanks, keeping its lines) the entries of a wall that belong to
  /// another geometry or motion than the wall's (@p lists), when they are
  ///  - that geometry's or motion's defaults (a file that lists every geometry's entries, as
  ///    `abrade params --format prm` writes them), silently, or
  ///  - the entries of the geometry or motion chosen when they were set (by the same block of
  ///    the wall's subsection, or before it), which a later choice replaced (an included base
  ///    case whose wall the including file, or a --set, made another
  ///    geometry: cases/knife_bed/lifetime.prm turns knife_bed.prm's chisel knife into the solid
  ///    model); each is named in a returned note.
  /// Any other entry of another geometry or motion stays, for the strict reading to refuse.
  /// @p origin: the file and line of each line of @p text (none: all of @p file).
  std::vector<std::string> leave_out_replaced_entries(std::string &text,
                                                      std::vector<std::pair<std::string, int>> origin,
                                                      const std::string &file, const DeclarationLists &lists,
                                                      const std::vector<Override> &overrides);
} // namespace abrade::coupling
