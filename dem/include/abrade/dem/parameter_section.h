#pragma once
// A subsection of the parameter file as the DEM's plugins (wear laws, contact sub-models) see
// it, so that they declare, read and check their own parameters while the DEM library knows no
// parameter-file library (coupling/parameter_section.h maps it onto deal.II's ParameterHandler).
#include <string>

namespace abrade::dem
{
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
    /// An input error naming the entry @p name and where it was set.
    [[noreturn]] virtual void fail(const std::string &name, const std::string &why) const = 0;
  };

} // namespace abrade::dem
