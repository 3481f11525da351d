// The subsections Material and Interaction of the particles and of every wall, declared and
// read (material_parameters.h).
#include <abrade/dem/parameter_section.h>
#include <abrade/coupling/parameters/material_parameters.h>
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/dem/contact_law.h>

#include <limits>
#include <string>

namespace abrade::coupling
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;

  void declare_material(ParameterHandler &prm, double G, double nu, double rho, bool rotation_option)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Shear modulus", std::to_string(G), Double(0, dem::unbounded),
                      "[Pa] Shear modulus G. Give either G or Young's modulus; when both are "
                      "non-zero, Young's modulus wins. Range: >= 0.");
    prm.declare_entry("Young's modulus", "0", Double(0, dem::unbounded),
                      "[Pa] Young's modulus E = 2 G (1 + nu); 0: use the shear modulus. Range: >= 0.");
    prm.declare_entry("Poisson's ratio", std::to_string(nu), Double(-0.999, 0.4999),
                      "[-] Poisson's ratio nu. Range: (-1, 0.5).");
    prm.declare_entry("Density", std::to_string(rho), Double(1e-12, dem::unbounded),
                      "[kg/m^3] Density. Range: > 0.");
    if (rotation_option)
      prm.declare_entry("Rotation", "false", Bool(),
                        "Whether particles rotate. false caps the angular velocity at 0 rad/s, "
                        "as the thesis' iron-ore pellet model does (a stand-in for non-spherical "
                        "shape).");
    prm.leave_subsection();
  }

  void declare_interaction(ParameterHandler &prm, double e, double mu, const std::string &with)
  {
    prm.enter_subsection("Interaction");
    prm.declare_entry("Restitution", std::to_string(e), Double(1e-6, 1),
                      "[-] Coefficient of restitution of " + with + " contacts. Range: (0, 1].");
    prm.declare_entry("Friction", std::to_string(mu), Double(0, dem::unbounded),
                      "[-] Static friction coefficient of " + with + " contacts (Coulomb limit of "
                      "the tangential force). Range: >= 0.");
    prm.declare_entry("Rolling friction", "0", Double(0, dem::unbounded),
                      "[-] Rolling friction coefficient of " + with + " contacts (EDEM constant "
                      "directional torque, or the epsd spring's limit mu_r R* |F_n|: Simulation/Rolling "
                      "model; acts only on rotating particles). Range: >= 0.");
    // the optional sub-models' own entries (contact_law.h)
    PluginSection section(prm);
    dem::for_each_model<dem::RollingModels>([&](auto m) { m.declare_parameters(section); });
    dem::for_each_model<dem::CohesionModels>([&](auto m) { m.declare_parameters(section); });
    prm.leave_subsection();
  }

  dem::Material read_material(ParameterFile &f, const std::vector<std::string> &path, const std::string &name)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Material");
    const double E = prm.get_double("Young's modulus"), G = prm.get_double("Shear modulus");
    const double nu = prm.get_double("Poisson's ratio"), rho = prm.get_double("Density");
    const bool   rot = path.size() == 1 && path[0] == "Particles" ? prm.get_bool("Rotation") : true;
    prm.leave_subsection();
    auto mp = path;
    mp.push_back("Material");
    if (E <= 0 && G <= 0)
      f.fail(mp, "Shear modulus", "give a positive shear modulus or Young's modulus");
    dem::Material m = E > 0 ? dem::Material{name, E, nu, rho, rot} : dem::Material::from_shear_modulus(name, G, nu, rho, rot);
    return m;
  }

  dem::Interaction read_interaction(ParameterFile &f, const std::vector<std::string> &path)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Interaction");
    dem::Interaction i{prm.get_double("Restitution"), prm.get_double("Friction"), prm.get_double("Rolling friction")};
    auto             ip = path;
    ip.push_back("Interaction");
    PluginSection section(f, ip);
    dem::for_each_model<dem::RollingModels>([&](auto m) { m.parse_parameters(section, i); });
    dem::for_each_model<dem::CohesionModels>([&](auto m) { m.parse_parameters(section, i); });
    prm.leave_subsection();
    return i;
  }
} // namespace abrade::coupling
