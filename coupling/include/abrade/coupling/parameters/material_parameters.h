#pragma once
// The subsections Material and Interaction that the particles and every wall have: elastic
// constants and density, and the contact's restitution, friction and optional sub-models
// (dem/contact_law.h), declared and read.
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/dem/material.h>

#include <string>
#include <vector>

namespace abrade::coupling
{
  /// Declares subsection Material with defaults @p G [Pa], @p nu, @p rho [kg/m^3]; with
  /// @p rotation_option, the particles' Rotation too.
  void declare_material(dealii::ParameterHandler &prm, double G, double nu, double rho, bool rotation_option);
  /// Declares subsection Interaction, defaults @p e and @p mu, for the contacts named by @p with.
  void declare_interaction(dealii::ParameterHandler &prm, double e, double mu, const std::string &with);

  /// Reads subsection Material of @p path (entered) as material @p name.
  dem::Material read_material(ParameterFile &f, const std::vector<std::string> &path, const std::string &name);
  /// Reads subsection Interaction of @p path (entered).
  dem::Interaction read_interaction(ParameterFile &f, const std::vector<std::string> &path);
} // namespace abrade::coupling
