// Reading a parameter file: includes, --set overrides, two passes (the lists that shape the
// declarations, then everything), every parser error as a one-line InputError (parameter_file.h).
#include <abrade/common/error.h>
#include <abrade/common/input_file.h>
#include <abrade/common/file_extension.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/coupling/parameters/parameter_text.h>
#include <abrade/coupling/walls/wall_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    // deal.II's parser messages span several lines and start with "Line <N> of file <F>";
    // turn them into "F:N: message" on one line. @p file: the name the text was parsed under,
    // known exactly (a path may hold ": " or ">"); else the first such name.
    std::string one_line(const dealii::ExceptionBase &e, const std::string &file = "")
    {
      std::ostringstream s;
      e.print_info(s);
      std::string msg = std::regex_replace(s.str(), std::regex("\\s+"), " ");
      msg             = std::regex_replace(msg, std::regex("^ +| +$"), "");
      std::smatch m;
      if (!file.empty() && std::regex_match(msg, m, std::regex("Line <(\\d+)> of file <(.*)")))
        {
          // (deal.II 9.4 omits the '>' after the file name in ExcNoSubsection)
          const std::string rest = m[2].str();
          for (const std::string end : {">: ", ": "})
            if (rest.compare(0, file.size() + end.size(), file + end) == 0)
              return file + ":" + m[1].str() + ": " + rest.substr(file.size() + end.size());
        }
      if (std::regex_match(msg, m, std::regex("Line <(\\d+)> of file <(.*?)>?: (.*)")))
        msg = m[2].str() + ":" + m[1].str() + ": " + m[3].str();
      return msg;
    }

    std::string read_text(const std::string &file)
    {
      std::ifstream in(file);
      if (!in)
        throw InputError(file, "cannot read the parameter file (permissions?)");
      std::ostringstream s;
      if (in.peek() != std::ifstream::traits_type::eof() && !(s << in.rdbuf()))
        throw InputError(file, "cannot read the parameter file");
      std::string text = s.str();
      // a UTF-8 byte order mark (Windows editors write one) is no part of the first line
      if (text.compare(0, 3, "\xEF\xBB\xBF") == 0)
        text.erase(0, 3);
      return text;
    }

    constexpr std::size_t max_line_length = 20000;

    /// Appends @p file's lines to @p text, every `include FILE` line replaced by that file's
    /// lines (relative to @p file's directory), recording where each line comes from.
    /// A file included twice at every level of a chain doubles the work per level (an "include
    /// bomb": 22 levels took minutes): no case needs more than this many inclusions in all.
    constexpr std::size_t max_inclusions = 1000;

    void expand_includes(const std::string &file, std::vector<std::string> &chain, std::string &text,
                         std::vector<std::pair<std::string, int>> &origin, std::size_t &inclusions)
    {
      const std::string canonical = std::filesystem::weakly_canonical(file).string();
      if (chain.size() >= 32)
        throw InputError(file, "includes nested more than 32 deep");
      if (++inclusions > max_inclusions)
        throw InputError(file, "more than " + std::to_string(max_inclusions) +
                                 " files included in all (a file included several times is counted each time: "
                                 "files that include the same file twice, level after level?)");
      chain.push_back(canonical);
      std::istringstream in(read_text(file));
      std::string        line;
      const auto         base = std::filesystem::path(file).parent_path();
      for (int n = 1; std::getline(in, line); ++n)
        {
          // deal.II matches values with regular expressions, which overflow the stack on
          // megabyte values: no parameter needs more than this
          if (line.size() > max_line_length)
            throw InputError(file + ":" + std::to_string(n), "a line of " + std::to_string(line.size()) +
                                                               " characters, more than " +
                                                               std::to_string(max_line_length));
          const std::string t = as_read(line.substr(0, line.find('#')));
          if (starts_with_keyword(t, "include"))
            {
              std::filesystem::path included(dealii::Utilities::trim(t.substr(8)));
              if (included.is_relative())
                included = base / included;
              const std::string where = file + ":" + std::to_string(n);
              try
                {
                  io::require_input_file(included.string(), "included file");
                }
              catch (const InputError &e)
                {
                  throw InputError(where, e.what());
                }
              if (std::find(chain.begin(), chain.end(), std::filesystem::weakly_canonical(included).string()) !=
                  chain.end())
                {
                  std::string how;
                  for (const auto &c : chain)
                    how += std::filesystem::path(c).filename().string() + " -> ";
                  throw InputError(where, "includes " + included.filename().string() + " again (" + how +
                                            included.filename().string() +
                                            "): a file cannot include itself, directly or through others");
                }
              expand_includes(included.string(), chain, text, origin, inclusions);
              continue;
            }
          text += line + "\n";
          origin.emplace_back(file, n);
        }
      chain.pop_back();
    }

  } // namespace

  std::vector<std::string> ParameterFile::files_read() const
  {
    std::vector<std::string> files;
    if (!file.empty())
      files.push_back(file);
    for (const auto &[f, line] : origin)
      if (std::find(files.begin(), files.end(), f) == files.end())
        files.push_back(f);
    return files;
  }

  Override parse_override(const std::string &text)
  {
    if (text.size() > max_line_length)
      throw InputError("--set '" + text.substr(0, 40) + "...'", "a value of " + std::to_string(text.size()) +
                                                                   " characters, more than " +
                                                                   std::to_string(max_line_length));
    const auto eq = text.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError("--set '" + text + "'", "expected \"Section/Subsection/Key=value\"");
    Override o;
    o.text  = text;
    o.value = dealii::Utilities::trim(text.substr(eq + 1));
    auto parts = dealii::Utilities::split_string_list(text.substr(0, eq), '/');
    o.key      = parts.back();
    parts.pop_back();
    o.path = parts;
    return o;
  }

  namespace
  {
    /// Says whose entry @p key of subsection @p path is, when it is not the reader's (an entry of
    /// another wall geometry or motion: foreign_entry_hint), or "".
    using EntryHint = std::function<std::string(const std::vector<std::string> &path, const std::string &key)>;

    /// The key of deal.II's "No entry with name <KEY> was declared" (or "" for other messages).
    std::string undeclared_key(const std::string &msg)
    {
      for (const std::string start : {"No entry with name <", "entry <"})
        if (const auto a = msg.find(start); a != std::string::npos)
          if (const auto b = msg.find('>', a); b != std::string::npos &&
                                               (msg.find("was declared") != std::string::npos ||
                                                msg.find("not yet declared") != std::string::npos))
            return msg.substr(a + start.size(), b - a - start.size());
      return "";
    }

    /// deal.II's "No entry with name <KEY> was declared", with where KEY is now when it is an
    /// entry that moved (moved_entry_hint), so that an older file says what to write instead.
    std::string with_rename_hint(const std::string &msg)
    {
      const std::string hint = moved_entry_hint(undeclared_key(msg));
      return hint.empty() ? msg : msg + " " + hint;
    }

    void apply_override(dealii::ParameterHandler &prm, const Override &o, bool lenient, const EntryHint &hint = {})
    {
      std::size_t entered = 0;
      try
        {
          for (const auto &s : o.path)
            {
              prm.enter_subsection(s);
              ++entered;
            }
          prm.set(o.key, o.value);
        }
      catch (const dealii::ExceptionBase &e)
        {
          for (; entered > 0; --entered)
            prm.leave_subsection();
          if (lenient)
            return;
          const std::string msg = with_rename_hint(one_line(e));
          throw InputError("--set '" + o.text + "'", msg + (hint && !undeclared_key(msg).empty() ? hint(o.path, o.key) : ""));
        }
      for (; entered > 0; --entered)
        prm.leave_subsection();
    }

    /// Parses @p text (of @p file, includes expanded); an error names the file and line the
    /// offending line comes from (@p origin).
    void parse_into(dealii::ParameterHandler &prm, const std::string &file, const std::string &text, bool lenient,
                    const std::vector<std::pair<std::string, int>> &origin, const EntryHint &hint = {})
    {
      std::istringstream in(text);
      try
        {
          prm.parse_input(in, file, "", lenient);
        }
      catch (const dealii::ExceptionBase &e)
        {
          std::string msg = one_line(e, file);
          if (msg.rfind(file + ":", 0) == 0)
            {
              const std::string rest = msg.substr(file.size() + 1);
              const auto        colon = rest.find(':');
              std::size_t       used  = 0;
              long              n     = 0;
              try
                {
                  n = std::stol(rest.substr(0, colon), &used);
                }
              catch (const std::exception &)
                {
                  used = 0;
                }
              const bool line_known = colon != std::string::npos && used == colon && n >= 1;
              if (line_known && std::size_t(n) <= origin.size())
                msg = origin[n - 1].first + ":" + std::to_string(origin[n - 1].second) + rest.substr(colon);
              if (const std::string key = undeclared_key(msg); line_known && hint && !key.empty())
                {
                  const auto entries = entries_by_line(lines_of(text));
                  if (std::size_t(n) <= entries.size())
                    msg += hint(entries[n - 1].path, key);
                }
            }
          throw InputError("", with_rename_hint(msg));
        }
    }
  } // namespace

  ParameterFile::ParameterFile(const std::string &f, const std::vector<std::string> &set)
    : file(f.empty() ? "<default case>" : f)
  {
    if (f.empty())
      text = default_case_text();
    else
      {
        io::require_input_file(f, "parameter file");
        std::vector<std::string> chain;
        std::size_t              inclusions = 0;
        expand_includes(f, chain, text, origin, inclusions);
      }
    for (const auto &s : set)
      overrides.push_back(parse_override(s));
    // entries that moved, read where they are now
    const std::vector<MovedNote> moved = read_moved_entries(text, origin, file, overrides);

    // pass 1: the lists that shape the declarations
    dealii::ParameterHandler lists;
    declare_lists(lists);
    parse_into(lists, file, text, true, origin);
    for (const auto &o : overrides)
      apply_override(lists, o, true);
    DeclarationLists l = read_lists(lists);
    check_wall_list(l, overrides);
    // ... and each wall's geometry and motion, which decide the entries it has
    dealii::ParameterHandler choices;
    declare_wall_choices(choices, l.walls);
    parse_into(choices, file, text, true, origin);
    for (const auto &o : overrides)
      apply_override(choices, o, true);
    l.wall_choices = read_wall_choices(choices, l.walls);
    notes_.clear();
    for (const auto &note : moved)
      notes_.push_back(note.text());
    for (auto &note : leave_out_replaced_entries(text, origin, file, l, overrides))
      notes_.push_back(note);
    overrides.erase(std::remove_if(overrides.begin(), overrides.end(),
                                   [&l](const Override &o) { return is_foreign_default(l, o.path, o.key, o.value); }),
                    overrides.end());

    // pass 2: everything, strictly
    declare_parameters(prm, l);
    const EntryHint hint = [&l](const std::vector<std::string> &path, const std::string &key) {
      return foreign_entry_hint(l, path, key);
    };
    try
      {
        parse_into(prm, file, text, false, origin, hint);
        for (const auto &o : overrides)
          apply_override(prm, o, false, hint);
      }
    catch (const InputError &e)
      {
        // a bad value given by an old spelling: deal.II names the entry by its new name, the
        // user wrote the old one
        const std::string what = e.what();
        for (const auto &note : moved)
          if (what.rfind(note.where + ": ", 0) == 0)
            throw InputError("", what + " (" + note.what + ")");
        throw;
      }
  }

  void ParameterFile::check_wall_list(const DeclarationLists &l, const std::vector<Override> &overrides) const
  {
    // every wall is a subsection of some sixty parameters and a triangle mesh in every contact
    // search: thousands are a mistake (a list pasted by accident), not a case
    constexpr std::size_t most_walls = 1000;
    const std::string     where      = locate({}, "Walls");
    if (l.walls.size() > most_walls)
      throw InputError(where, "Walls: " + std::to_string(l.walls.size()) + " walls listed, more than " +
                                std::to_string(most_walls) + " (one name per wall, separated by commas)");
    std::set<std::string> seen; // (in lower case: 'W' and 'w' are one file on some file systems)
    for (const auto &name : l.walls)
      {
        if (const std::string why = bad_name(name); !why.empty())
          throw InputError(where, "Walls: " + why);
        if (!seen.insert(io::lower_case(name)).second)
          throw InputError(where, "Walls: '" + name + "' is listed twice (names are compared ignoring case)");
      }
    // a wall the file lists without its subsection would be a default 2 m box, silently
    const bool listed_here = where != file ||
                             std::any_of(overrides.begin(), overrides.end(),
                                         [](const Override &o) { return o.path.empty() && o.key == "Walls"; });
    if (!listed_here)
      return;
    std::set<std::string> sections; // the file's top-level subsections (an empty one's end line is in it)
    for (const auto &line : entries_by_line(lines_of(text)))
      if (!line.path.empty())
        sections.insert(line.path[0]);
    for (const auto &o : overrides)
      if (!o.path.empty())
        sections.insert(o.path[0]);
    for (const auto &name : l.walls)
      if (!sections.count("Wall " + name))
        throw InputError(where, "Walls: '" + name + "' is listed, but there is no 'subsection Wall " +
                                                name + "' for it (its geometry, material and motion)");
  }

  ParameterFile::ParameterFile() : file("<defaults>")
  {
    declare_parameters(prm, DeclarationLists());
  }

  std::string ParameterFile::locate(const std::vector<std::string> &path, const std::string &key) const
  {
    // the --set that gives it, or the last "set KEY" inside PATH (the one that takes effect), in
    // the file it comes from
    for (auto o = overrides.rbegin(); o != overrides.rend(); ++o)
      if (o->path == path && o->key == key)
        return "--set '" + o->text + "'";
    const auto  entries = entries_by_line(lines_of(text));
    std::string where   = file;
    for (std::size_t n = 0; n < entries.size(); ++n)
      if (entries[n].path == path && entries[n].key == key)
        where = n < origin.size() ? origin[n].first + ":" + std::to_string(origin[n].second)
                                  : file + ":" + std::to_string(n + 1);
    return where;
  }

  void ParameterFile::fail(const std::vector<std::string> &path, const std::string &key,
                           const std::string &message) const
  {
    throw InputError(locate(path, key), entry_path(path, key) + ": " + message);
  }

  std::string ParameterFile::canonical_text()
  {
    std::ostringstream s;
    prm.print_parameters(s, dealii::ParameterHandler::ShortPRM);
    return s.str();
  }

  // (the file's own layer, below the subsections' owners: it blanks Output/Directory itself,
  // as output_parameters.h would, without depending on them)
  std::string ParameterFile::identity_text()
  {
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Directory");
    prm.set("Directory", "");
    prm.leave_subsection();
    const std::string text = canonical_text();
    prm.enter_subsection("Output");
    prm.set("Directory", directory);
    prm.leave_subsection();
    return text;
  }
  std::string ParameterFile::path_beside(const std::string &path) const
  {
    if (path.empty() || std::filesystem::path(path).is_absolute() || file.empty() || file.front() == '<')
      return path;
    return (std::filesystem::path(file).parent_path() / path).string();
  }
} // namespace abrade::coupling
