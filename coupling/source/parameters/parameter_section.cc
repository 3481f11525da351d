// A subsection of the parameter file as the DEM's plugins see it: their declarations and reads,
// their refusals naming the file, line and entry (parameter_section.h).
#include <abrade/dem/parameter_section.h>
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/parameter_section.h>

#include <deal.II/base/utilities.h>

#include <limits>

namespace abrade::coupling
{
  void PluginSection::declare_number(const std::string &name, double value, double lo, double hi,
                                     const std::string &doc)
  {
    prm.declare_entry(name, io::format_number(value, 15), dealii::Patterns::Double(lo, hi), doc);
  }

  void PluginSection::readable(const std::string &name) const
  {
    if (!file)
      throw RunError("parameter '" + name + "' read from a section that was only declared");
  }

  double PluginSection::number(const std::string &name) const
  {
    readable(name);
    return prm.get_double(name);
  }

  void PluginSection::declare_vector(const std::string &name, const std::array<double, 3> &value,
                                     const std::string &doc)
  {
    prm.declare_entry(name,
                      io::format_number(value[0], 15) + ", " + io::format_number(value[1], 15) + ", " +
                        io::format_number(value[2], 15),
                      dealii::Patterns::List(dealii::Patterns::Double(-dem::unbounded, dem::unbounded), 3, 3), doc + " Three numbers: x, y, z.");
  }

  std::array<double, 3> PluginSection::vector(const std::string &name) const
  {
    readable(name);
    const dem::Vec3 v = vector_entry(prm, name);
    return {v[0], v[1], v[2]};
  }

  dem::Vec3 vector_entry(dealii::ParameterHandler &prm, const std::string &name)
  {
    const auto v = dealii::Utilities::split_string_list(prm.get(name));
    return {std::stod(v[0]), std::stod(v[1]), std::stod(v[2])};
  }

  void PluginSection::declare_bool(const std::string &name, bool value, const std::string &doc)
  {
    prm.declare_entry(name, value ? "true" : "false", dealii::Patterns::Bool(), doc);
  }

  bool PluginSection::boolean(const std::string &name) const
  {
    readable(name);
    return prm.get_bool(name);
  }

  void PluginSection::declare_text(const std::string &name, const std::string &value, const std::string &doc)
  {
    prm.declare_entry(name, value, dealii::Patterns::Anything(), doc);
  }

  std::string PluginSection::text(const std::string &name) const
  {
    readable(name);
    return dealii::Utilities::trim(prm.get(name));
  }

  void PluginSection::declare_choices(const std::string &name, const std::string &value,
                                      const std::vector<std::string> &choices, const std::string &doc)
  {
    std::string names;
    for (const auto &c : choices)
      names += (names.empty() ? "" : "|") + c;
    prm.declare_entry(name, value, dealii::Patterns::List(dealii::Patterns::Selection(names)), doc);
  }

  std::vector<std::string> PluginSection::chosen(const std::string &name) const
  {
    readable(name);
    std::vector<std::string> out;
    for (auto &s : dealii::Utilities::split_string_list(prm.get(name)))
      if (!s.empty())
        out.push_back(s);
    return out;
  }

  void PluginSection::declare_choice(const std::string &name, const std::string &value,
                                     const std::vector<std::string> &choices, const std::string &doc)
  {
    std::string names;
    for (const auto &c : choices)
      names += (names.empty() ? "" : "|") + c;
    prm.declare_entry(name, value, dealii::Patterns::Selection(names), doc);
  }

  void PluginSection::declare_numbers(const std::string &name, const std::string &value, unsigned int least,
                                      unsigned int most, double lo, double hi, const std::string &doc)
  {
    prm.declare_entry(name, value, dealii::Patterns::List(dealii::Patterns::Double(lo, hi), least, most), doc);
  }

  std::vector<double> PluginSection::numbers(const std::string &name) const
  {
    readable(name);
    std::vector<double> out;
    for (const auto &s : dealii::Utilities::split_string_list(prm.get(name)))
      if (!s.empty())
        out.push_back(std::stod(s)); // (the pattern checked them)
    return out;
  }

  void PluginSection::fail(const std::string &name, const std::string &why) const
  {
    if (!file)
      throw RunError("parameter '" + name + "': " + why);
    file->fail(path, name, why);
  }
} // namespace abrade::coupling
