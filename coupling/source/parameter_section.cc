// A subsection of the parameter file as the DEM's plugins see it: their declarations and reads,
// their refusals naming the file, line and entry (parameter_section.h).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameter_section.h>

#include <limits>

namespace abrade::coupling
{
  void PluginSection::declare_number(const std::string &name, double value, double lo, double hi,
                                     const std::string &doc)
  {
    prm.declare_entry(name, io::format_number(value, 15), dealii::Patterns::Double(lo, hi), doc);
  }

  double PluginSection::number(const std::string &name) const
  {
    if (!file)
      throw RunError("parameter '" + name + "' read from a section that was only declared");
    return prm.get_double(name);
  }

  void PluginSection::fail(const std::string &name, const std::string &why) const
  {
    if (!file)
      throw RunError("parameter '" + name + "': " + why);
    file->fail(path, name, why);
  }
} // namespace abrade::coupling
