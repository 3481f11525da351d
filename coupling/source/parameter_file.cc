#include <abrade/common/error.h>
#include <abrade/coupling/parameter_file.h>
#include <abrade/coupling/parameters.h>

#include <deal.II/base/utilities.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    // deal.II's parser messages span several lines and start with "Line <N> of file <F>";
    // turn them into "F:N: message" on one line.
    std::string one_line(const dealii::ExceptionBase &e)
    {
      std::ostringstream s;
      e.print_info(s);
      std::string msg = std::regex_replace(s.str(), std::regex("\\s+"), " ");
      msg             = std::regex_replace(msg, std::regex("^ +| +$"), "");
      std::smatch m;
      // (deal.II 9.4 omits the '>' after the file name in ExcNoSubsection)
      if (std::regex_match(msg, m, std::regex("Line <(\\d+)> of file <(.*?)>?: (.*)")))
        msg = m[2].str() + ":" + m[1].str() + ": " + m[3].str();
      return msg;
    }

    std::string read_text(const std::string &file)
    {
      std::ifstream in(file);
      std::ostringstream s;
      s << in.rdbuf();
      return s.str();
    }

    template <typename F>
    void translating_errors(F &&f)
    {
      try
        {
          f();
        }
      catch (const abrade::InputError &)
        {
          throw;
        }
      catch (const dealii::ExceptionBase &e)
        {
          throw InputError("", one_line(e));
        }
    }
  } // namespace

  Override parse_override(const std::string &text)
  {
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
    void apply_override(dealii::ParameterHandler &prm, const Override &o, bool lenient)
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
          throw InputError("--set '" + o.text + "'", one_line(e));
        }
      for (; entered > 0; --entered)
        prm.leave_subsection();
    }

    void parse_into(dealii::ParameterHandler &prm, const std::string &file, const std::string &text,
                    bool lenient)
    {
      std::istringstream in(text);
      translating_errors([&] { prm.parse_input(in, file, "", lenient); });
    }
  } // namespace

  ParameterFile::ParameterFile(const std::string &f, const std::vector<std::string> &set)
    : file(f.empty() ? "<default case>" : f)
  {
    if (f.empty())
      text = default_case_text();
    else
      {
        if (!std::filesystem::exists(f))
          throw InputError(f, "parameter file not found");
        if (!std::filesystem::is_regular_file(f))
          throw InputError(f, "not a regular file");
        text = read_text(f);
        // `include FILE` is relative to this file's directory, not to the working directory
        std::istringstream in(text);
        std::string        line, resolved;
        const auto         base = std::filesystem::path(f).parent_path();
        while (std::getline(in, line))
          {
            const std::string t = dealii::Utilities::trim(line);
            if ((t.rfind("include ", 0) == 0 || t.rfind("INCLUDE ", 0) == 0) &&
                std::filesystem::path(dealii::Utilities::trim(t.substr(8))).is_relative())
              line = "include " + (base / dealii::Utilities::trim(t.substr(8))).string();
            resolved += line + "\n";
          }
        text = resolved;
      }
    std::vector<Override> overrides;
    for (const auto &s : set)
      overrides.push_back(parse_override(s));

    // pass 1: the lists that shape the declarations
    dealii::ParameterHandler lists;
    declare_lists(lists);
    parse_into(lists, file, text, true);
    for (const auto &o : overrides)
      apply_override(lists, o, true);
    const DeclarationLists l = read_lists(lists);

    // pass 2: everything, strictly
    declare_parameters(prm, l);
    parse_into(prm, file, text, false);
    for (const auto &o : overrides)
      apply_override(prm, o, false);
  }

  ParameterFile::ParameterFile() : file("<defaults>")
  {
    declare_parameters(prm, DeclarationLists());
  }

  std::string ParameterFile::locate(const std::vector<std::string> &path, const std::string &key) const
  {
    // Walk the file's subsection structure and find "set KEY" inside PATH.
    std::istringstream       in(text);
    std::string              line;
    std::vector<std::string> current;
    int                      n = 0;
    while (std::getline(in, line))
      {
        ++n;
        std::string l = dealii::Utilities::trim(line.substr(0, line.find('#')));
        if (l.rfind("subsection ", 0) == 0)
          current.push_back(dealii::Utilities::trim(l.substr(11)));
        else if (l == "end" && !current.empty())
          current.pop_back();
        else if (l.rfind("set ", 0) == 0 && current == path)
          {
            const auto eq = l.find('=');
            if (eq != std::string::npos && dealii::Utilities::trim(l.substr(4, eq - 4)) == key)
              return file + ":" + std::to_string(n);
          }
      }
    return file;
  }

  void ParameterFile::fail(const std::vector<std::string> &path, const std::string &key,
                           const std::string &message) const
  {
    std::string full;
    for (const auto &p : path)
      full += p + "/";
    throw InputError(locate(path, key), full + key + ": " + message);
  }

  std::string ParameterFile::canonical_text()
  {
    std::ostringstream s;
    prm.print_parameters(s, dealii::ParameterHandler::ShortPRM);
    return s.str();
  }
} // namespace abrade::coupling
