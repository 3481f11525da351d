// Subsection Output (output_parameters.h): the output directory, the snapshots and force files,
// and the wear field with its profile and filter.
#include <abrade/dem/parameter_section.h>
#include <abrade/coupling/parameters/output_parameters.h>
#include <abrade/dem/wear_law.h>

#include <limits>

namespace abrade::coupling
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Selection;

  namespace
  {
    /// The volume fields of the registered laws ("archard_volume|oka_volume").
    std::string volume_field_names(const std::string &separator = ", ")
    {
      std::string names;
      for (const auto &law : dem::registered_wear_laws())
        for (const auto &field : law->fields())
          if (field.volume)
            names += (names.empty() ? "" : separator) + field.name;
      return names;
    }

    Selection volume_field_selection() { return Selection(volume_field_names("|")); }
  } // namespace

  void declare_output_parameters(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Anything(),
                      "Output directory (created if missing); `--output DIR` overrides it.");
    prm.declare_entry("Snapshot interval", "0.05", Double(0, dem::unbounded),
                      "[s] Simulated time between ParaView snapshots (particles and walls, .vtp in "
                      ".pvd series); 0: only at the end of each phase. Range: >= 0.");
    prm.declare_entry("Force interval", "0.001", Double(0, dem::unbounded),
                      "[s] Simulated time between rows of the wall force files "
                      "(walls/NAME_forces.csv); 0: every time step. Range: >= 0.");
    prm.declare_entry("Wear profile band", "0.01", Double(1e-6, dem::unbounded),
                      "[m] Height of the bands of walls/NAME_wear_profile.csv (the wear by height "
                      "above a wall's lowest point, by face direction, and its filtered peak "
                      "depth). Range: > 0.");
    prm.declare_entry("Wear field", "archard_volume", volume_field_selection(),
                      "The worn-volume field that the wear profile (walls/NAME_wear_profile.csv), the "
                      "lifetime loop (the part's wear depth), sweep, concepts and calibrate use: a "
                      "volume field of a wear law (" + volume_field_names() + "); the part's "
                      "Wear/Laws must include its law.");
    prm.declare_entry("Wear filter length", "0.0275", Double(0, dem::unbounded),
                      "[m] A fixed length of the surface filter for the filtered peak depth of "
                      "walls/NAME_wear_profile.csv (next to the filter over the largest particle "
                      "radius, the lifetime loop's default); the default is the thesis' "
                      "coarse-grained pellet radius, so that runs at several particle sizes "
                      "compare at one length. 0: none. Range: >= 0.");
    prm.declare_entry("Write particles", "true", Bool(),
                      "Whether snapshots include the particles (they dominate the output size).");
    prm.leave_subsection();
  }

  void read_output_parameters(ParameterFile &f, DemCase &c)
  {
    dealii::ParameterHandler &prm = f.handler();
    prm.enter_subsection("Output");
    c.snapshot_interval = prm.get_double("Snapshot interval");
    c.force_interval    = prm.get_double("Force interval");
    c.write_particles   = prm.get_bool("Write particles");
    c.wear_profile_band   = prm.get_double("Wear profile band");
    c.wear_filter_length  = prm.get_double("Wear filter length");
    c.wear_field          = prm.get("Wear field");
    prm.leave_subsection();
  }

  std::string output_directory(ParameterFile &f)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Output");
    const std::string directory = prm.get("Directory");
    prm.leave_subsection();
    return directory;
  }

  void set_output_directory(ParameterFile &f, const std::string &directory)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Output");
    prm.set("Directory", directory);
    prm.leave_subsection();
  }
} // namespace abrade::coupling
