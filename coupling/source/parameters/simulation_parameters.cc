// Subsection Simulation (simulation_parameters.h): the time step, the contact law's sub-models,
// threads and ranks, the domain, what an error does, the operating cycle's phases and the
// payload height.
#include <abrade/dem/parameter_section.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/parameter_choices.h>
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/coupling/parameters/simulation_parameters.h>
#include <abrade/dem/contact_law.h>

#include <deal.II/base/utilities.h>

#include <limits>
#include <strings.h>

namespace abrade::coupling
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dealii::Patterns::Selection;
  using dealii::Utilities::split_string_list;
  using dealii::Utilities::trim;

  namespace
  {
    /// The names of a list of contact sub-models as an entry pattern, and their documentation.
    template <class Models>
    Selection model_selection()
    {
      std::string names;
      for (const auto &n : dem::model_names<Models>())
        names += (names.empty() ? "" : "|") + n;
      return Selection(names);
    }

    template <class Models>
    std::string model_documentation()
    {
      std::string doc;
      dem::for_each_model<Models>([&](auto m) {
        doc += (doc.empty() ? "" : "; ") + std::string(m.name) + ": " + m.documentation;
      });
      return doc;
    }

    const Choices<dem::DampingModel> damping_models = {{"edem", dem::DampingModel::edem},
                                                       {"calibrated", dem::DampingModel::calibrated}};
    const Choices<bool> error_policies = {{"stop", true}, {"continue", false}}; // stop on error?
  } // namespace

  void declare_simulation_parameters(dealii::ParameterHandler &prm)
  {
    PluginSection section(prm);
    prm.enter_subsection("Simulation");
    prm.declare_entry("Time step", "0", Double(0, 1),
                      "[s] Time step; 0: 'Rayleigh fraction' times the Rayleigh time step of the "
                      "smallest particle. Range: [0, 1].");
    prm.declare_entry("Maximum particle-steps", "1e12", Double(0, dem::unbounded),
                      "[-] Refuse a run (one operating cycle, with its settling) that needs more particle-steps "
                      "than this, estimated from the particles, the time step and the phases before the bed is "
                      "generated (about 28 hours at 1e7 particle-steps/s); 0: no limit. Range: >= 0.");
    prm.declare_entry("Rayleigh fraction", "0.2", Double(1e-6, 1),
                      "[-] Time step as a fraction of the Rayleigh time step (EDEM recommends 0.2 "
                      "for dense packings, 0.4 for loose ones). Range: (0, 1].");
    section.declare_vector("Gravity", {0, 0, -9.81}, "[m/s^2] Gravitational acceleration.");
    prm.declare_entry("Characteristic velocity", "1.5", Double(1e-9, dem::unbounded),
                      "[m/s] Impact speed used to check the time step against the Hertz contact "
                      "time (a warning is printed when dt exceeds a tenth of it). Range: > 0.");
    prm.declare_entry("Skin", "0", Double(0, dem::unbounded),
                      "[m] Verlet skin of the neighbour lists; 0: 0.2 x the smallest radius. The "
                      "lists are rebuilt when a particle or wall has moved far enough to bring a new "
                      "pair into contact. Range: >= 0.");
    prm.declare_entry("Damping model", "edem", selection_of(damping_models),
                      "edem: damping from the restitution as EDEM/LIGGGHTS document it (the "
                      "rebound restitution of a Hertz contact then differs slightly from the input); "
                      "calibrated: damping chosen so that a Hertz contact rebounds with exactly the "
                      "input restitution.");
    prm.declare_entry("Rolling model", dem::model_names<dem::RollingModels>()[0], model_selection<dem::RollingModels>(),
                      "The contact law's rolling resistance (docs/physics.md): " +
                        model_documentation<dem::RollingModels>() +
                        ". Its limit comes from each Interaction's Rolling friction.");
    prm.declare_entry("Cohesion model", dem::model_names<dem::CohesionModels>()[0], model_selection<dem::CohesionModels>(),
                      "The contact law's cohesion (docs/physics.md): " + model_documentation<dem::CohesionModels>() +
                        ". Its strength comes from each Interaction's entries.");
    prm.declare_entry("Threads", "0", Integer(0, 1024),
                      "Most threads that work on a step; 0: all available (OMP_NUM_THREADS or the "
                      "cores). Range: >= 0. Under mpirun: threads per MPI rank (0: the machine's share "
                      "of each rank). At most Shares of them are used. The results do not depend on "
                      "it: the same case gives the same bits with any number of threads.");
    prm.declare_entry("Shares", "4", Integer(1, 1024),
                      "The shares each step's work is cut into, each summed in a fixed order: they "
                      "fix the arithmetic, so a case gives the same bits on any machine and with "
                      "any Threads (the exception: the number of MPI ranks, which cuts the domain). "
                      "More threads than shares are not used: on a machine with more cores per rank, "
                      "raise it (8 shares cost 7-10 % on one or two threads against 2, 4 shares 0-3 %; "
                      "docs/benchmarks.md) or run more MPI ranks. Range: >= 1.");
    prm.declare_entry("Adapt threads", "true", Bool(),
                      "Work with fewer of the threads while that is faster: on a busy machine (another "
                      "process on a core) a thread that shares a core holds the others up at every "
                      "step. The run measures its steps and tries one thread fewer or more now and "
                      "then (a few per cent of the time); the log says when it ran on fewer. The "
                      "results are the same bits either way. false: always all threads.");
    prm.declare_entry("Rebalance threshold", "1.1", Double(1, dem::unbounded),
                      "[-] Under mpirun the particles are spread over the ranks by recursive "
                      "coordinate bisection; the domains are cut again at a neighbour-list build "
                      "when the rank with the most particles owns more than this times the mean. "
                      "Range: >= 1.");
    section.declare_vector("Domain min", {-1000, -1000, -1000},
                   "[m] Lower corner of the simulation domain; a particle outside it is lost.");
    section.declare_vector("Domain max", {1000, 1000, 1000}, "[m] Upper corner of the simulation domain.");
    prm.declare_entry("Maximum overlap fraction", "0.2", Double(0, 1),
                      "[-] An overlap larger than this fraction of the particle radius is reported "
                      "(usually a time step that is too large). Range: [0, 1].");
    prm.declare_entry("On error", "stop", selection_of(error_policies),
                      "What a lost particle or an excessive overlap does: stop the run with an "
                      "error, or print a warning and continue (lost particles are removed). A NaN "
                      "always stops the run.");
    prm.declare_entry("Phases", "penetration: 0.2666667, travel: 0.8",
                      dealii::Patterns::Map(Anything(), Double(0, dem::unbounded), 0, 1000, ",", ":"),
                      "[s] The operating cycle as named phases with durations, in order: "
                      "'name: duration, name: duration'. Walls take their velocity per phase "
                      "name (Wall NAME/Motion/Velocities); wear and forces are reported per phase.");
    prm.declare_entry("Payload height", "", Anything(),
                      "[m] Payload of a grab: at the end of every phase, the mass of the particles "
                      "whose centre is above this height is reported (summary.json, per phase: "
                      "mass_above_payload_height); empty: not reported. Set it above the pile, so "
                      "that after hoisting it counts what the grab holds.");
    prm.leave_subsection();
  }

  void read_simulation_parameters(ParameterFile &f, DemCase &c)
  {
    dealii::ParameterHandler &prm = f.handler();
    prm.enter_subsection("Simulation");
    auto &s                   = c.settings;
    s.time_step               = prm.get_double("Time step");
    s.rayleigh_fraction       = prm.get_double("Rayleigh fraction");
    s.gravity                 = vector_entry(prm, "Gravity");
    s.characteristic_velocity = prm.get_double("Characteristic velocity");
    s.skin                    = prm.get_double("Skin");
    s.damping   = get_choice(prm, "Damping model", damping_models);
    s.contact.rolling  = prm.get("Rolling model");
    s.contact.cohesion = prm.get("Cohesion model");
    s.threads   = prm.get_integer("Threads");
    s.shares    = prm.get_integer("Shares");
    s.adapt_threads = prm.get_bool("Adapt threads");
    s.rebalance_threshold = prm.get_double("Rebalance threshold");
    s.domain_min = vector_entry(prm, "Domain min");
    s.domain_max = vector_entry(prm, "Domain max");
    s.max_overlap_fraction = prm.get_double("Maximum overlap fraction");
    s.stop_on_error        = get_choice(prm, "On error", error_policies);
    for (const auto &item : split_string_list(prm.get("Phases")))
      {
        const auto colon = item.find(':');
        c.phases.emplace_back(trim(item.substr(0, colon)), std::stod(item.substr(colon + 1)));
        if (const std::string why = bad_name(c.phases.back().first); !why.empty())
          f.fail({"Simulation"}, "Phases", why);
        for (std::size_t k = 0; k + 1 < c.phases.size(); ++k)
          if (strcasecmp(c.phases[k].first.c_str(), c.phases.back().first.c_str()) == 0)
            f.fail({"Simulation"}, "Phases", "'" + c.phases.back().first + "' is listed twice (names are compared "
                                                                            "ignoring case)");
      }
    c.max_particle_steps = prm.get_double("Maximum particle-steps");
    prm.leave_subsection();
    c.payload_height = read_payload_height(f);
    if (!(s.domain_min.array() < s.domain_max.array()).all())
      f.fail({"Simulation"}, "Domain max", "must exceed Domain min in x, y and z");
    if (c.phases.empty())
      f.fail({"Simulation"}, "Phases", "at least one phase is needed");
  }

  int read_thread_count(ParameterFile &f, const dem::Parallel &ranks)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Simulation");
    const int threads = prm.get_integer("Threads");
    prm.leave_subsection();
    return threads > 0 ? threads : dem::default_thread_count(ranks);
  }

  std::optional<double> read_payload_height(ParameterFile &f)
  {
    auto &prm = f.handler();
    prm.enter_subsection("Simulation");
    const std::string h = prm.get("Payload height");
    prm.leave_subsection();
    if (h.empty())
      return std::nullopt;
    try
      {
        return std::stod(h);
      }
    catch (const std::exception &)
      {
        f.fail({"Simulation"}, "Payload height", "'" + h + "' is not a number");
      }
  }
} // namespace abrade::coupling
