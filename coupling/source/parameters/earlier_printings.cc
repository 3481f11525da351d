// The printed parameters under each earlier layout (earlier_printings.h): the text read into a
// tree of subsections, each later layout's renames and moves undone on it, printed again as
// deal.II prints (entries first, then subsections, each sorted by its mangled name; the keys of
// a subsection padded to its longest).
#include <abrade/coupling/parameters/earlier_printings.h>
#include <abrade/coupling/parameters/parameter_renames.h>
#include <abrade/coupling/walls/wall_parameters.h>

#include <algorithm>
#include <map>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    /// One subsection of the printed parameters.
    struct Section
    {
      std::map<std::string, std::string> entries;     ///< key -> value
      std::map<std::string, Section>     subsections; ///< name -> its entries

      /// The entry @p key moved out of it (empty when absent).
      std::string take(const std::string &key)
      {
        const auto it = entries.find(key);
        if (it == entries.end())
          return {};
        std::string value = it->second;
        entries.erase(it);
        return value;
      }
    };

    Section read_printed(const std::string &printed)
    {
      Section               top;
      std::vector<Section *> open = {&top};
      std::istringstream     in(printed);
      for (std::string line; std::getline(in, line);)
        {
          const std::size_t first = line.find_first_not_of(' ');
          if (first == std::string::npos)
            continue;
          const std::string l = line.substr(first);
          if (l.rfind("subsection ", 0) == 0)
            open.push_back(&open.back()->subsections[l.substr(11)]);
          else if (l == "end" && open.size() > 1)
            open.pop_back();
          else if (const std::size_t eq = l.find(" = "); l.rfind("set ", 0) == 0 && eq != std::string::npos)
            {
              std::string key = l.substr(4, eq - 4);
              key.erase(key.find_last_not_of(' ') + 1);
              open.back()->entries[key] = l.substr(eq + 3);
            }
        }
      return top;
    }

    /// deal.II's name for @p s in its tree, which it sorts by: letters and digits kept, any
    /// other character '_' and its two hexadecimal digits ("Box min": "Box_20min").
    std::string mangled(const std::string &s)
    {
      static const char *hex = "0123456789abcdef";
      std::string        u;
      for (const unsigned char c : s)
        if ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))
          u.push_back(char(c));
        else
          u += {'_', hex[c / 16], hex[c % 16]};
      return u;
    }

    template <class Map>
    std::vector<typename Map::const_pointer> in_printed_order(const Map &m)
    {
      std::vector<typename Map::const_pointer> sorted;
      for (const auto &kv : m)
        sorted.push_back(&kv);
      std::sort(sorted.begin(), sorted.end(),
                [](const auto *a, const auto *b) { return mangled(a->first) < mangled(b->first); });
      return sorted;
    }

    void print(const Section &s, const std::string &indent, std::string &out)
    {
      std::size_t width = 0;
      for (const auto &[key, value] : s.entries)
        width = std::max(width, key.size());
      for (const auto *e : in_printed_order(s.entries))
        out += indent + "set " + e->first + std::string(width - e->first.size(), ' ') + " = " + e->second + "\n";
      for (const auto *sub : in_printed_order(s.subsections))
        {
          out += indent + "subsection " + sub->first + "\n";
          print(sub->second, indent + "  ", out);
          out += indent + "end\n";
        }
    }

    bool is_wall(const std::string &name) { return name.rfind("Wall ", 0) == 0; }

    /// The entries a layout dropped that were printed before it, put back: in layout 3 the
    /// velocity table became the motions' own that follow it; a wall of another motion (fixed)
    /// printed it with its wall's default.
    void put_back_dropped_entries(int layout, Section &top)
    {
      if (layout != 3)
        return;
      for (auto &[name, wall] : top.subsections)
        if (is_wall(name))
          if (const auto motion = wall.subsections.find("Motion"); motion != wall.subsections.end())
            {
              auto &entries = motion->second.entries;
              if (!entries.count("Velocities"))
                entries["Velocities"] = wall_defaults(name.substr(5)).velocities;
              if (!entries.count("Angular velocities"))
                entries["Angular velocities"] = "";
            }
    }

    /// The entries @p layout added, taken out where they have their default (an earlier abrade
    /// could not have printed another value).
    void take_out_added_entries(int layout, Section &top)
    {
      for (const auto &a : renames::added_entries)
        {
          if (a.layout != layout)
            continue;
          Section          *s = &top;
          std::stringstream path(a.path);
          for (std::string name; s && std::getline(path, name, '/');)
            {
              const auto it = s->subsections.find(name);
              s             = it == s->subsections.end() ? nullptr : &it->second;
            }
          if (s && s->entries.count(a.key) && s->entries[a.key] == a.value)
            s->entries.erase(a.key);
        }
    }

    /// @p top as the layout before @p layout printed it.
    void undo_layout(int layout, Section &top)
    {
      take_out_added_entries(layout, top);
      for (const auto &m : renames::moved_entries)
        if (m.layout == layout)
          for (auto &[name, section] : top.subsections)
            {
              if (!renames::was_in(m, {name}))
                continue; // (the moves of nested subsections, a wall's Wear, are older than any layout)
              Section *now = &section;
              if (*m.now)
                {
                  const auto sub = section.subsections.find(m.now);
                  if (sub == section.subsections.end())
                    continue;
                  now = &sub->second;
                }
              if (now->entries.count(m.key))
                section.entries[m.old_key] = now->take(m.key);
              if (*m.now && now->entries.empty() && now->subsections.empty())
                section.subsections.erase(m.now);
            }
      put_back_dropped_entries(layout, top);
      for (const auto &r : renames::renamed_values)
        if (r.layout == layout && top.entries.count(r.key) && top.entries[r.key] == r.value)
          top.entries[r.key] = r.old_value;
      for (const auto &r : renames::renamed_subsections)
        if (const auto it = top.subsections.find(r.name); r.layout == layout && it != top.subsections.end())
          {
            Section moved = std::move(it->second);
            top.subsections.erase(it);
            top.subsections[r.old_name] = std::move(moved);
          }
    }
  } // namespace

  std::vector<std::string> earlier_printings(const std::string &printed)
  {
    Section                  top = read_printed(printed);
    std::vector<std::string> texts;
    for (int layout = renames::current_layout; layout > 0; --layout)
      {
        undo_layout(layout, top);
        texts.emplace_back();
        print(top, "", texts.back());
      }
    return texts;
  }
} // namespace abrade::coupling
