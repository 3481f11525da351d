#pragma once
// A subsection of the parameter file as the DEM's plugins (wear laws, contact sub-models, wall
// motions; the coupling's wall geometries) see it, so that they declare, read and check their
// own parameters while the DEM library knows no parameter-file library
// (coupling/parameters/parameter_section.h maps it onto deal.II's ParameterHandler).
#include <array>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace abrade::dem
{
  /// The upper end of a number's range that has none (declare_number's @p hi, and deal.II's
  /// Double pattern's): the largest double.
  inline constexpr double unbounded = std::numeric_limits<double>::max();

  /// One subsection of the parameter file, as a plugin sees it: it declares its entries (numbers in
  /// a range, with a unit and a sentence of documentation), reads them back and refuses a value
  /// with a message that names the entry and where it was set.
  class ParameterSection
  {
  public:
    virtual ~ParameterSection() = default;
    /// Declares the number @p name (default @p value, allowed [@p lo, @p hi]); @p doc starts
    /// with the unit in brackets, as every abrade parameter's documentation does.
    virtual void declare_number(const std::string &name, double value, double lo, double hi,
                                const std::string &doc) = 0;
    virtual double number(const std::string &name) const = 0;

    // Entries other than numbers (a section that holds numbers only need not have them).
    /// Three numbers x, y, z.
    virtual void declare_vector(const std::string &name, const std::array<double, 3> &value, const std::string &doc)
    {
      unsupported(name);
    }
    virtual std::array<double, 3> vector(const std::string &name) const { unsupported(name); }
    virtual void declare_bool(const std::string &name, bool value, const std::string &doc) { unsupported(name); }
    virtual bool boolean(const std::string &name) const { unsupported(name); }
    /// Any text (a name, a list the plugin checks itself).
    virtual void declare_text(const std::string &name, const std::string &value, const std::string &doc)
    {
      unsupported(name);
    }
    virtual std::string text(const std::string &name) const { unsupported(name); }
    /// A comma-separated list of some of @p choices.
    virtual void declare_choices(const std::string &name, const std::string &value,
                                 const std::vector<std::string> &choices, const std::string &doc)
    {
      unsupported(name);
    }
    virtual std::vector<std::string> chosen(const std::string &name) const { unsupported(name); }
    /// One of @p choices (read with text()).
    virtual void declare_choice(const std::string &name, const std::string &value,
                                const std::vector<std::string> &choices, const std::string &doc)
    {
      unsupported(name);
    }
    /// From @p least to @p most comma-separated numbers in [@p lo, @p hi] (default @p value, as
    /// a parameter file writes it: "1, 1").
    virtual void declare_numbers(const std::string &name, const std::string &value, unsigned int least,
                                 unsigned int most, double lo, double hi, const std::string &doc)
    {
      unsupported(name);
    }
    virtual std::vector<double> numbers(const std::string &name) const { unsupported(name); }

    /// An input error naming the entry @p name and where it was set.
    [[noreturn]] virtual void fail(const std::string &name, const std::string &why) const = 0;

  private:
    [[noreturn]] static void unsupported(const std::string &name)
    {
      throw std::logic_error("parameter '" + name + "': this parameter section holds numbers only");
    }
  };

} // namespace abrade::dem
