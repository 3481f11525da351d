// The registry of wear laws (wear_law.h). The laws themselves are in wear_laws/, a library of
// their own linked whole.
#include <abrade/common/error.h>
#include <abrade/common/wear_field_names.h>
#include <abrade/dem/wear_law.h>

#include <algorithm>
#include <array>

namespace abrade::dem
{
  namespace
  {
    using Registry = io::PluginRegistry<WearLaw>;

    /// A law's subsection held in a map (defaults, then the values given).
    class MapSection : public ParameterSection
    {
    public:
      explicit MapSection(std::string law) : law(std::move(law)) {}
      void declare_number(const std::string &name, double value, double lo, double hi, const std::string &) override
      {
        entries[name] = {value, lo, hi};
      }
      double number(const std::string &name) const override
      {
        const auto e = entries.find(name);
        if (e == entries.end())
          fail(name, "no such parameter");
        return e->second[0];
      }
      [[noreturn]] void fail(const std::string &name, const std::string &why) const override
      {
        throw InputError("wear law " + law, "'" + name + "': " + why);
      }
      void set(const std::string &name, double value)
      {
        const auto e = entries.find(name);
        if (e == entries.end())
          fail(name, "no such parameter");
        if (!(value >= e->second[1] && value <= e->second[2]))
          fail(name, std::to_string(value) + " is out of range");
        e->second[0] = value;
      }

    private:
      std::string                               law;
      std::map<std::string, std::array<double, 3>> entries; // value, lo, hi
    };
  } // namespace

  std::string WearField::depth_name() const { return io::wear_depth_name(name); }

  WearLawRegistration::WearLawRegistration(std::unique_ptr<WearLaw> (*make)()) { Registry::add(make, "wear law"); }

  const std::vector<std::unique_ptr<WearLaw>> &registered_wear_laws()
  {
    static const std::vector<std::unique_ptr<WearLaw>> laws = Registry::make_all();
    return laws;
  }

  std::string wear_law_names(const std::string &separator)
  {
    std::string names;
    for (const auto &law : registered_wear_laws())
      names += (names.empty() ? "" : separator) + law->name();
    return names;
  }

  std::unique_ptr<WearLaw> make_wear_law(const std::string &name)
  {
    if (auto law = Registry::make(name))
      return law;
    throw InputError("", "unknown wear law '" + name + "': the wear laws are " + wear_law_names());
  }

  std::unique_ptr<WearLaw> make_wear_law(const std::string &name, const std::map<std::string, double> &values,
                                         const WearContext &context)
  {
    auto       law = make_wear_law(name);
    MapSection section(name);
    law->declare_parameters(section);
    for (const auto &[key, value] : values)
      section.set(key, value);
    law->parse_parameters(section, context);
    return law;
  }

  const WearLaw *wear_law_of_field(const std::string &field)
  {
    for (const auto &law : registered_wear_laws())
      for (const auto &f : law->fields())
        if (f.name == field)
          return law.get();
    return nullptr;
  }
} // namespace abrade::dem
