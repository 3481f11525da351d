// A parameter file's text line by line, and the entries of a wall's replaced geometry or motion
// left out of it (parameter_text.h).
#include <abrade/common/list_items.h>
#include <abrade/coupling/parameters/parameter_renames.h>
#include <abrade/coupling/parameters/parameter_text.h>
#include <abrade/coupling/walls/wall_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <functional>
#include <map>
#include <sstream>

namespace abrade::coupling
{
  using dealii::Utilities::trim;

  std::string as_read(std::string line)
  {
    std::replace(line.begin(), line.end(), '\t', ' '); // (deal.II reads a tab as a blank)
    return trim(line);
  }

  bool starts_with_keyword(const std::string &line, const std::string &word)
  {
    std::string upper = word;
    for (auto &c : upper)
      c = char(std::toupper(static_cast<unsigned char>(c)));
    return line.rfind(word + " ", 0) == 0 || line.rfind(upper + " ", 0) == 0;
  }

  std::vector<std::string> lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    for (std::string l; std::getline(in, l);)
      lines.push_back(l);
    return lines;
  }

  std::vector<LineEntry> entries_by_line(const std::vector<std::string> &lines)
  {
    std::vector<LineEntry>   entries(lines.size());
    std::vector<std::string> path;
    for (std::size_t n = 0; n < lines.size();)
      {
        std::string joined;
        std::size_t last = n;
        for (;; ++last)
          {
            std::string t    = as_read(lines[last]);
            const bool  more = !t.empty() && t.back() == '\\' && last + 1 < lines.size();
            if (more)
              t.pop_back();
            joined += t;
            if (!more)
              break;
          }
        const std::string l = trim(joined.substr(0, joined.find('#')));
        for (std::size_t k = n; k <= last; ++k)
          entries[k].path = path, entries[k].last = last;
        if (starts_with_keyword(l, "subsection"))
          {
            entries[n].opens = trim(l.substr(11));
            path.push_back(entries[n].opens);
          }
        else if ((l == "end" || l == "END") && !path.empty())
          path.pop_back();
        else if (const auto eq = l.find('='); starts_with_keyword(l, "set") && eq != std::string::npos)
          {
            entries[n].key   = trim(l.substr(4, eq - 4));
            entries[n].value = trim(l.substr(eq + 1));
          }
        n = last + 1;
      }
    return entries;
  }

  bool is_foreign_default(const DeclarationLists &lists, const std::vector<std::string> &path, const std::string &key,
                          const std::string &value)
  {
    const auto f = foreign_entry(lists, path, key);
    return f && f->at_default(value);
  }

  namespace
  {
    using namespace renames;

    /// The subsection @p m is in now, from @p path, where it was.
    std::vector<std::string> now_in(const MovedEntry &m, std::vector<std::string> path)
    {
      if (*m.now)
        path.push_back(m.now);
      return path;
    }

    /// The renamed value a top-level entry @p key = @p value gives under its old name (nullptr:
    /// none).
    const RenamedValue *renamed_value(const std::vector<std::string> &path, const std::string &key,
                                      const std::string &value)
    {
      if (!path.empty())
        return nullptr;
      for (const auto &r : renamed_values)
        if (key == r.key && trim(value.substr(0, value.find('#'))) == r.old_value)
          return &r;
      return nullptr;
    }

    /// The renamed subsection a line opens at the top level, under an old name (nullptr: none).
    const RenamedSubsection *renamed_subsection(const LineEntry &entry)
    {
      if (!entry.path.empty())
        return nullptr;
      for (const auto &r : renamed_subsections)
        if (entry.opens == r.old_name)
          return &r;
      return nullptr;
    }

    const MovedEntry *moved_entry(const std::vector<std::string> &path, const std::string &key)
    {
      for (const auto &m : moved_entries)
        if (was_in(m, path) && key == m.old_key)
          return &m;
      return nullptr;
    }

  } // namespace

  std::string entry_path(const std::vector<std::string> &path, const std::string &key)
  {
    std::string s;
    for (const auto &p : path)
      s += p + "/";
    return s + key;
  }

  namespace
  {
    /// A --set's entry (@p path, @p key, @p value) rewritten as it is spelt now: a renamed
    /// subsection, a renamed choice, a moved entry. Returns the old spellings it met.
    struct OldSpellings
    {
      const RenamedSubsection *subsection = nullptr;
      const RenamedValue      *value      = nullptr;
      const MovedEntry        *moved      = nullptr;
    };
    OldSpellings to_now(std::vector<std::string> &path, std::string &key, std::string &value)
    {
      OldSpellings old;
      for (const auto &r : renamed_subsections)
        if (!path.empty() && path.front() == r.old_name)
          {
            old.subsection = &r;
            path.front()   = r.name;
          }
      if ((old.value = renamed_value(path, key, value)))
        value = old.value->value;
      if ((old.moved = moved_entry(path, key)))
        {
          path = now_in(*old.moved, path);
          key  = old.moved->key;
        }
      return old;
    }
  } // namespace

  std::string entry_as_now(const std::string &set)
  {
    std::vector<std::string> path = io::list_items(set.substr(0, set.find('=')), '/');
    if (path.empty())
      return "";
    std::string key = path.back(), value;
    path.pop_back();
    to_now(path, key, value);
    return entry_path(path, key);
  }

  std::string moved_entry_hint(const std::string &key)
  {
    for (const auto &m : moved_entries)
      if (key == m.old_key)
        return *m.now ? "'" + key + "' moved: subsection " + m.now + ", set " + m.key + " (inside " + m.in + ": " +
                          m.why + ")."
                      : "'" + key + "' is now '" + m.key + "' (in subsection " + m.in + "NAME: " + m.why + ").";
    return "";
  }

  namespace
  {
    /// What a note says of an old spelling read where it is now.
    std::string read_as(const MovedEntry &m, const std::vector<std::string> &path)
    {
      return entry_path(path, m.old_key) + " is read as " + entry_path(now_in(m, path), m.key) +
             (*m.now ? " (its place now; the old spelling still works)" : " (its name now; the old one still works)");
    }
    std::string read_as(const RenamedSubsection &r)
    {
      return std::string("subsection ") + r.old_name + " is read as subsection " + r.name +
             " (its name now; the old one still works)";
    }
    std::string read_as(const RenamedValue &r)
    {
      return std::string(r.key) + " = " + r.old_value + " is read as " + r.key + " = " + r.value +
             " (its name now; the old one still works)";
    }

    /// Each --set of @p overrides with an old spelling rewritten as it is now, a note each.
    void read_moved_overrides(std::vector<Override> &overrides, std::vector<MovedNote> &notes)
    {
      for (auto &o : overrides)
        {
          const std::string  where = "--set '" + o.text + "'";
          const OldSpellings old   = to_now(o.path, o.key, o.value);
          if (old.subsection)
            notes.push_back({where, read_as(*old.subsection)});
          if (old.value)
            notes.push_back({where, read_as(*old.value)});
          if (old.moved) // (read in the subsection that now holds old.moved->now)
            notes.push_back({where, read_as(*old.moved, *old.moved->now ? std::vector<std::string>(o.path.begin(), o.path.end() - 1)
                                                                        : o.path)});
        }
    }
  } // namespace

  std::vector<MovedNote> read_moved_entries(std::string &text, std::vector<std::pair<std::string, int>> &origin,
                                            const std::string &file, std::vector<Override> &overrides)
  {
    const std::vector<std::string>           lines   = lines_of(text);
    const auto                               entries = entries_by_line(lines);
    std::vector<std::pair<std::string, int>> from    = origin;
    for (std::size_t n = from.size(); n < lines.size(); ++n) // (no file: the embedded default case)
      from.emplace_back(file, int(n + 1));
    std::vector<MovedNote>                   notes;
    std::vector<std::string>                 out;
    std::vector<std::pair<std::string, int>> out_origin;
    const auto where = [&from](std::size_t n) { return from[n].first + ":" + std::to_string(from[n].second); };
    // line n (and the lines it continued into, left blank) rewritten as @p now
    const auto rewrite = [&](std::size_t &n, const std::vector<std::string> &now) {
      for (const std::string &l : now)
        {
          out.push_back(l);
          out_origin.push_back(from[n]);
        }
      for (std::size_t k = n + 1; k <= entries[n].last; ++k)
        {
          out.push_back("");
          out_origin.push_back(from[k]);
        }
      n = entries[n].last;
    };
    for (std::size_t n = 0; n < lines.size(); ++n)
      if (const RenamedSubsection *r = renamed_subsection(entries[n]))
        {
          notes.push_back({where(n), read_as(*r)});
          rewrite(n, {std::string("subsection ") + r->name});
        }
      else if (const RenamedValue *v = renamed_value(entries[n].path, entries[n].key, entries[n].value))
        {
          notes.push_back({where(n), read_as(*v)});
          rewrite(n, {std::string("set ") + v->key + " = " + v->value});
        }
      else if (const MovedEntry *m = moved_entry(entries[n].path, entries[n].key))
        {
          notes.push_back({where(n), read_as(*m, entries[n].path)});
          if (*m->now)
            rewrite(n, {std::string("subsection ") + m->now, std::string("  set ") + m->key + " = " + entries[n].value,
                        std::string("end")});
          else
            rewrite(n, {std::string("set ") + m->key + " = " + entries[n].value});
        }
      else
        {
          out.push_back(lines[n]);
          out_origin.push_back(from[n]);
        }
    read_moved_overrides(overrides, notes);
    if (notes.empty())
      return notes;
    text.clear();
    for (const auto &l : out)
      text += l + "\n";
    origin = out_origin;
    return notes;
  }

  namespace
  {
    /// "Geometry" or "Motion/Type" when @p key of subsection @p path is a wall's choice of that
    /// family, else "".
    std::string wall_choice_family(const std::vector<std::string> &path, const std::string &key)
    {
      if (path.size() == 1 && path[0].rfind("Wall ", 0) == 0 && key == "Geometry")
        return "Geometry";
      if (path.size() == 2 && path[0].rfind("Wall ", 0) == 0 && path[1] == "Motion" && key == "Type")
        return "Motion/Type";
      return "";
    }

    using WallFamily = std::pair<std::string, std::string>; // ("Wall NAME", family)

    /// Where each wall's final choice was made: the last line that made it ("file:line", @p where),
    /// or a --set.
    std::map<WallFamily, std::string> final_choices(const std::vector<LineEntry> &entries,
                                                    const std::vector<Override> &overrides,
                                                    const std::function<std::string(std::size_t)> &where)
    {
      std::map<WallFamily, std::string> final_choice;
      for (std::size_t n = 0; n < entries.size(); ++n)
        if (const auto family = wall_choice_family(entries[n].path, entries[n].key); !family.empty())
          final_choice[{entries[n].path[0], family}] = where(n);
      for (const auto &o : overrides)
        if (const auto family = wall_choice_family(o.path, o.key); !family.empty())
          final_choice[{o.path[0], family}] = "--set '" + o.text + "'";
      return final_choice;
    }

    /// The blocks of the walls' subsections (from one 'subsection Wall NAME' to its 'end', each
    /// keyed by its first line) and the choice each makes (its last), in effect for the whole
    /// block: a file written in alphabetical order (parameters.prm) sets Box min before Geometry.
    struct WallBlocks
    {
      std::vector<std::size_t>                                   block; ///< per line: its block
      std::map<std::pair<std::size_t, std::string>, std::string> choice; ///< (block, family): value
    };
    WallBlocks wall_blocks(const std::vector<LineEntry> &entries)
    {
      WallBlocks b;
      b.block.assign(entries.size(), 0);
      for (std::size_t n = 0; n < entries.size(); ++n)
        {
          const auto &p = entries[n].path;
          if (p.empty())
            continue;
          b.block[n] = n > 0 && !entries[n - 1].path.empty() && entries[n - 1].path[0] == p[0] ? b.block[n - 1] : n;
          if (const auto family = wall_choice_family(p, entries[n].key); !family.empty())
            b.choice[{b.block[n], family}] = entries[n].value;
        }
      return b;
    }

    /// A note per replaced choice: the entries left out, as entries of which geometry or motion,
    /// and what replaced it where.
    std::vector<std::string> left_out_notes(const std::map<std::vector<std::string>, std::vector<std::string>> &left_out)
    {
      std::vector<std::string> notes;
      for (const auto &[choice, keys] : left_out)
        {
          std::string list;
          for (const auto &k : keys)
            list += (list.empty() ? "" : ", ") + k;
          notes.push_back(choice[0] + ": left out, as entries of " + choice[1] + " = " + choice[2] + ", which " +
                          choice[4] + " replaced by " + choice[3] + ": " + list);
        }
      return notes;
    }
  } // namespace

  std::vector<std::string> leave_out_replaced_entries(std::string &text, std::vector<std::pair<std::string, int>> origin,
                                                      const std::string &file, const DeclarationLists &lists,
                                                      const std::vector<Override> &overrides)
  {
    std::vector<std::string> lines   = lines_of(text);
    const auto               entries = entries_by_line(lines);
    for (std::size_t n = origin.size(); n < lines.size(); ++n) // (no file: the embedded default case)
      origin.emplace_back(file, int(n + 1));
    const auto where = [&](std::size_t n) { return origin[n].first + ":" + std::to_string(origin[n].second); };
    std::map<WallFamily, std::string> final_choice = final_choices(entries, overrides, where);
    const WallBlocks                  blocks       = wall_blocks(entries);

    // the choice in effect at each line, from the wall's default on
    std::map<WallFamily, std::string> current;
    const auto choice_at = [&](const std::string &wall, const std::string &family) -> std::string & {
      const auto it = current.find({wall, family});
      if (it != current.end())
        return it->second;
      const WallChoices d = default_wall_choices(wall.substr(5));
      return current[{wall, family}] = family == "Geometry" ? d.geometry : d.motion;
    };
    // per wall, choice replaced and by what: "KEY (file:line)"
    std::map<std::vector<std::string>, std::vector<std::string>> left_out;
    for (std::size_t n = 0; n < lines.size(); ++n)
      {
        const LineEntry &e = entries[n];
        if (e.key.empty() || e.path.empty())
          continue;
        if (const auto family = wall_choice_family(e.path, e.key); !family.empty())
          {
            choice_at(e.path[0], family) = e.value;
            continue;
          }
        const auto f = foreign_entry(lists, e.path, e.key);
        if (!f)
          continue; // (the wall's own, or no plugin's)
        const std::string &family     = f->entry.family;
        const auto         in_block   = blocks.choice.find({blocks.block[n], family});
        const std::string  then       = in_block != blocks.choice.end() ? in_block->second : choice_at(e.path[0], family);
        const bool         is_default = f->at_default(e.value);
        if (!is_default && !f->entry.defaults.count(then))
          continue; // (another's entry, not replaced: the strict reading refuses it)
        if (!is_default)
          left_out[{e.path[0], family, then, f->ours, final_choice[{e.path[0], family}]}].push_back(
            e.key + " (" + where(n) + ")");
        for (std::size_t k = n; k <= e.last; ++k)
          lines[k].clear();
      }
    text.clear();
    for (const auto &l : lines)
      text += l + "\n";
    return left_out_notes(left_out);
  }
} // namespace abrade::coupling
