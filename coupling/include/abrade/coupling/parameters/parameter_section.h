#pragma once
// A subsection of the parameter file as the DEM's plugins see it (dem::ParameterSection): their
// declarations become deal.II ParameterHandler entries, their reads come from it, and their
// refusals are input errors that name the file, the line and the entry.
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/dem/triangle_mesh.h>
#include <abrade/dem/wear_law.h>

#include <deal.II/base/parameter_handler.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  class PluginSection : public dem::ParameterSection
  {
  public:
    /// For declaring only (`abrade params`, the second pass of a file's reading): reads fail.
    explicit PluginSection(dealii::ParameterHandler &prm) : prm(prm) {}
    /// For reading the entries of the subsection @p path, which the caller has entered.
    PluginSection(ParameterFile &file, std::vector<std::string> path)
      : prm(file.handler()), file(&file), path(std::move(path))
    {}

    void   declare_number(const std::string &name, double value, double lo, double hi, const std::string &doc) override;
    double number(const std::string &name) const override;
    void   declare_vector(const std::string &name, const std::array<double, 3> &value, const std::string &doc) override;
    std::array<double, 3> vector(const std::string &name) const override;
    void                  declare_bool(const std::string &name, bool value, const std::string &doc) override;
    bool                  boolean(const std::string &name) const override;
    void        declare_text(const std::string &name, const std::string &value, const std::string &doc) override;
    std::string text(const std::string &name) const override;
    void        declare_choices(const std::string &name, const std::string &value,
                                const std::vector<std::string> &choices, const std::string &doc) override;
    std::vector<std::string> chosen(const std::string &name) const override;
    void declare_choice(const std::string &name, const std::string &value, const std::vector<std::string> &choices,
                        const std::string &doc) override;
    void declare_numbers(const std::string &name, const std::string &value, unsigned int least, unsigned int most,
                         double lo, double hi, const std::string &doc) override;
    std::vector<double> numbers(const std::string &name) const override;
    [[noreturn]] void fail(const std::string &name, const std::string &why) const override;

  private:
    /// Reads are for sections of a file only.
    void readable(const std::string &name) const;

    dealii::ParameterHandler &prm;
    ParameterFile            *file = nullptr;
    std::vector<std::string>  path;
  };

  /// Entry @p name of the entered subsection, a vector declared by PluginSection::declare_vector
  /// (its pattern checked three numbers).
  dem::Vec3 vector_entry(dealii::ParameterHandler &prm, const std::string &name);
} // namespace abrade::coupling
