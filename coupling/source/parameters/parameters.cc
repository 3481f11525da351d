// The parameters of a case composed from their owners (parameters.h): the top-level lists and
// the Job, then each subsection declared and read by the file of what it configures (Part:
// part_parameters.cc; Lifetime: lifetime/lifetime_settings.cc; Output, Simulation, Particles:
// their *_parameters.cc; Wall NAME: walls/wall_parameters.cc; Grab mechanism:
// walls/grab_mechanism.cc), in the order their checks run; and the DEM simulation built from
// what was read.
#include <abrade/common/format_number.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/lifetime/lifetime_settings.h>
#include <abrade/coupling/parameters/output_parameters.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/coupling/parameters/particle_parameters.h>
#include <abrade/coupling/parameters/run_size.h>
#include <abrade/coupling/parameters/simulation_parameters.h>
#include <abrade/coupling/walls/grab_mechanism.h>
#include <abrade/coupling/walls/wall_parameters.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cctype>

namespace abrade::coupling
{
  using dealii::ParameterHandler;

  namespace
  {
    std::vector<std::string> get_list(ParameterHandler &prm, const std::string &name)
    {
      std::vector<std::string> out;
      for (auto &s : dealii::Utilities::split_string_list(prm.get(name)))
        if (!s.empty())
          out.push_back(s);
      return out;
    }
  } // namespace

  std::string bad_name(const std::string &name)
  {
    // names become file and column names (walls/NAME_wear.csv): no paths, no separators
    if (name.empty() || name.size() > 64 ||
        !std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '_' || c == '-'; }))
      return "'" + name.substr(0, 64) +
             "' is not a name: up to 64 letters, digits, '_' and '-' (names become file names)";
    return "";
  }

  void declare_lists(ParameterHandler &prm)
  {
    const WallDefaults knife = wall_defaults("knife");
    prm.declare_entry("Walls", "container, knife", dealii::Patterns::List(dealii::Patterns::Anything()),
                      "Names of the walls (triangle meshes). Each name gets a subsection 'Wall NAME' with its "
                      "geometry, material and motion. A wall is a fixed " + knife.choices.geometry +
                        " without wear laws unless its subsection says otherwise, but for a wall named knife, "
                        "whose defaults are the default case's knife's: Motion/Type = " + knife.choices.motion +
                        ", Motion/Velocities = " + knife.velocities + ", Wear/Laws = " + knife.wear_laws +
                        ", Layer probe/Enabled = " + (knife.probe ? "true" : "false") +
                        ", Interaction/Friction = " + io::format_number(knife.friction) +
                        " (its Geometry a " + knife.choices.geometry + " too: give its shape).");
  }

  DeclarationLists read_lists(ParameterHandler &prm)
  {
    DeclarationLists l;
    l.walls = get_list(prm, "Walls");
    return l;
  }

  void declare_parameters(ParameterHandler &prm, const DeclarationLists &lists)
  {
    std::string jobs, job_doc; // (the registered jobs: jobs.h)
    for (const auto &job : make_jobs())
      {
        jobs += (jobs.empty() ? "" : "|") + job->name();
        job_doc += (job_doc.empty() ? "" : "; ") + job->name() + ": " + job->documentation();
      }
    prm.declare_entry("Job", "dem", dealii::Patterns::Selection(jobs), "What `abrade run` does. " + job_doc + ".");
    declare_lists(prm);
    std::string names;
    for (const auto &w : lists.walls)
      names += (names.empty() ? "" : ", ") + w;
    prm.set("Walls", names);

    declare_part_parameters(prm);
    lifetime::declare_lifetime_parameters(prm);
    declare_output_parameters(prm);
    declare_simulation_parameters(prm);
    declare_particle_parameters(prm);

    for (const auto &name : lists.walls)
      {
        const auto chosen = lists.wall_choices.find(name);
        declare_wall(prm, name, chosen == lists.wall_choices.end() ? nullptr : &chosen->second);
      }
    declare_grab_mechanism(prm);
  }

  // -----------------------------------------------------------------------------------------------

  DemCase read_dem_case(ParameterFile &f)
  {
    ParameterHandler &prm = f.handler();
    DemCase           c;
    c.notes = f.notes();

    read_output_parameters(f, c);
    read_simulation_parameters(f, c);
    read_particle_parameters(f, c);
    check_run_size(c, f); // a run of years, or of more memory than there is, is refused here

    for (const auto &name : get_list(prm, "Walls"))
      c.walls.push_back(read_wall(f, name, c));
    mount_parts(f, c, read_part_length(f));
    read_grab_mechanism(f, c);
    return c;
  }

  std::shared_ptr<dem::RopeGrabDriver> build_simulation(const DemCase &c, dem::Simulation &sim)
  {
    const int particle_material = sim.add_material(c.particle_material);
    sim.set_interaction(particle_material, particle_material, c.particle_interaction);
    for (const auto &wc : c.walls)
      {
        dem::Wall w    = wc.wall;
        w.material     = sim.add_material(wc.material);
        sim.set_interaction(particle_material, w.material, wc.interaction);
        sim.add_wall(std::move(w));
      }
    if (!c.grab_mechanism)
      return nullptr;
    auto driver = std::make_shared<dem::RopeGrabDriver>(*c.grab_mechanism, sim);
    sim.add_driver(driver);
    return driver;
  }
} // namespace abrade::coupling
