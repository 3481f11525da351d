// Every parameter of a case declared (names, defaults, units, ranges, documentation) and read
// into the DEM's and the FEM's structs, with the checks that need more than one value
// (parameters.h).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/coupling/parameter_choices.h>
#include <abrade/coupling/parameter_section.h>
#include <abrade/coupling/material_parameters.h>
#include <abrade/coupling/walls/grab_mechanism.h>
#include <abrade/coupling/walls/wall_parameters.h>
#include <abrade/dem/contact_law.h>
#include <abrade/coupling/parameters.h>
#include <abrade/coupling/lifetime/end_of_life_criterion.h>
#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/coupling/run_size.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/coarse_graining.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <filesystem>

namespace abrade::coupling
{
  using dealii::ParameterHandler;
  using dealii::Patterns::Anything;
  using dealii::Patterns::Bool;
  using dealii::Patterns::Double;
  using dealii::Patterns::FileName;
  using dealii::Patterns::Integer;
  using dealii::Patterns::List;
  using dealii::Patterns::Selection;
  using dealii::Utilities::split_string_list;
  using dealii::Utilities::trim;
  using dem::Vec3;

  namespace
  {
    constexpr double huge = std::numeric_limits<double>::max();

    void declare_vector(ParameterHandler &prm, const std::string &name, const std::string &def,
                        const std::string &doc)
    {
      prm.declare_entry(name, def, List(Double(-huge, huge), 3, 3), doc + " Three numbers: x, y, z.");
    }

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

    Vec3 get_vector(ParameterHandler &prm, const std::string &name)
    {
      const auto v = split_string_list(prm.get(name));
      return Vec3(std::stod(v[0]), std::stod(v[1]), std::stod(v[2]));
    }

    const Choices<dem::DampingModel> damping_models = {{"edem", dem::DampingModel::edem},
                                                       {"calibrated", dem::DampingModel::calibrated}};
    const Choices<bool> error_policies = {{"stop", true}, {"continue", false}}; // stop on error?
    const Choices<dem::SizeDistribution::Kind> size_distributions = {
      {"constant", dem::SizeDistribution::Kind::constant},
      {"uniform", dem::SizeDistribution::Kind::uniform},
      {"normal", dem::SizeDistribution::Kind::normal}};
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

    std::vector<std::string> get_list(ParameterHandler &prm, const std::string &name)
    {
      std::vector<std::string> out;
      for (auto &s : split_string_list(prm.get(name)))
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
    prm.declare_entry("Walls", "container, knife", List(Anything()),
                      "Names of the walls (triangle meshes). Each name gets a subsection "
                      "'Wall NAME' with its geometry, material and motion.");
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
    prm.declare_entry("Job", "dem", Selection(jobs), "What `abrade run` does. " + job_doc + ".");
    declare_lists(prm);
    std::string names;
    for (const auto &w : lists.walls)
      names += (names.empty() ? "" : ", ") + w;
    prm.set("Walls", names);

    prm.enter_subsection("Knife");
    prm.declare_entry("Geometry", "parametric", Selection("parametric|file"),
                      "parametric: the grab knife below; file: a solid from File (.msh, .step/.stp, "
                      ".iges/.igs, or a closed .stl).");
    prm.declare_entry("File", "", Anything(), "Solid file when Geometry = file; relative to the parameter file.");
    prm.declare_entry("Length", "0.4", Double(1e-6, huge), "[m] Knife length (x). Range: > 0.");
    prm.declare_entry("Height", "0.5", Double(1e-6, huge), "[m] Knife height (z). Range: > 0.");
    prm.declare_entry("Thickness", "0.03", Double(1e-6, huge), "[m] Plate thickness (y). Range: > 0.");
    prm.declare_entry("Bevel height", "0.04", Double(1e-6, huge),
                      "[m] Height of the bevel that forms the edge; with the thickness it sets the "
                      "edge angle. Range: (0, Height).");
    prm.declare_entry("Bevel side", "both", selection_of(bevel_sides),
                      "both: chisel edge in the middle; plus / minus: bevel on the +y / -y face only.");
    prm.declare_entry("Tip radius", "0", Double(0, huge), "[m] Rounding of the edge; 0: sharp. Range: [0, Thickness/2).");
    prm.declare_entry("Lip height", "0", Double(0, huge),
                      "[m] Height of a ridge on the +y face above the bevel that holds back a "
                      "protective layer of material; 0: none. Range: >= 0.");
    prm.declare_entry("Lip width", "0", Double(0, huge), "[m] How far the ridge stands out of the face. Range: >= 0.");
    prm.declare_entry("Lip offset", "0", Double(0, huge), "[m] Distance of the ridge above the bevel. Range: >= 0.");
    prm.declare_entry("Mesh size", "0.015", Double(1e-6, huge), "[m] Target tetrahedron size. Range: > 0.");
    prm.declare_entry("File scale", "1", Double(1e-12, huge),
                      "[-] Geometry = file: multiplies the file's coordinates. STL and .msh files have no unit "
                      "(0.001: the file is in millimetres); STEP/IGES files declare theirs, which is converted "
                      "to metres on import (leave 1; another value multiplies on top, with a warning). A .msh "
                      "of hexahedra is split into tetrahedra. Range: > 0.");
    prm.declare_entry("Maximum cells", "3000000", Double(0, huge),
                      "[-] Refuse a knife that would need more tetrahedra than this (estimated before meshing "
                      "from its volume and Mesh size: about 8.5 V / h^3), with a Mesh size that fits; 0: no "
                      "limit. Range: >= 0.");
    prm.declare_entry("Density", "7800", Double(1e-6, huge), "[kg/m^3] Density of the knife steel (mass). Range: > 0.");
    prm.declare_entry("Solid", "all", Anything(),
                      "Geometry = file, a CAD file with several solids: 'all' takes them all as one part, a "
                      "number the solid of that number (the knife job lists them).");
    declare_vector(prm, "Rotation axis", "0, 0, 1",
                   "[-] Geometry = file: the axis of the rotation that brings the part from the file's "
                   "(assembly) coordinates into the knife's frame (edge along x at the bottom, height along "
                   "z); through the origin, right-handed. A mounted part is then centred on its shell's lip "
                   "along x and z by its bounding box; across the lip its y = 0 plane lies on the lip's line.");
    prm.declare_entry("Rotation angle", "0", Double(-360, 360),
                      "[deg] Geometry = file: the angle of that rotation. The part's point p becomes "
                      "R (File scale x p) + Offset: scaled, rotated about the origin, then moved. Range: "
                      "[-360, 360].");
    declare_vector(prm, "Offset", "0, 0, 0", "[m] Geometry = file: moves the part after its rotation.");
    prm.declare_entry("Place", "", Anything(),
                      "Geometry = file: moves the rotated part by its bounding box before Offset, so that a "
                      "part from a CAD assembly need not be measured first: ','-separated 'centred' (the box's "
                      "centre to x = y = 0), 'centred in x' (or y, z), 'lowest point at z = V' [m]; e.g. "
                      "'lowest point at z = 0, centred'. The move is logged. Empty: none.");
    prm.declare_entry("Clamped faces", "", Anything(),
                      "Geometry = file: the faces bolted or welded to the shell, which the mesh motion holds "
                      "and which do not wear; selectors separated by ';': 'group NAME' (a physical group of "
                      "a .msh, by name or number, or a CAD face by its number), 'box x0, y0, z0, x1, y1, z1' "
                      "(faces whose centre lies in the box, in metres, in the knife's frame after scale and "
                      "placement), 'normal nx, ny, nz[, angle]' (faces whose outward normal is within angle "
                      "degrees, default 10, of the direction), 'cylinder px, py, pz, ax, ay, az, r[, tolerance]' "
                      "(faces on the cylinder of radius r about the axis through p along a: a bore or a pin, "
                      "whose CAD face may be split in halves; the facets' centres r from the axis within the "
                      "tolerance, default 0.15 r, their normals across it). Empty: none (every face wears). "
                      "The knife job lists the part's faces.");
    prm.declare_entry("Wearable faces", "", Anything(),
                      "Geometry = file: the faces that wear (selectors as for Clamped faces); faces that "
                      "neither list takes are held. Empty: every face that is not clamped wears.");
    prm.declare_entry("Minimum mesh quality", "0.05", Double(0, 1),
                      "[-] Geometry = file: a mesh whose smallest scaled Jacobian is below this is optimised "
                      "once more (Gmsh's optimisers, harder) and, if still below, reported with the place of "
                      "its worst cell. Range: [0, 1].");
    prm.leave_subsection();

    prm.enter_subsection("Lifetime");
    prm.declare_entry("Tonnes per cycle", "10", Double(0, 1e6),
                      "[t] Material handled per operating cycle (the tonnes axis of the trajectory); 0: "
                      "the DEM's payload, the most mass above Simulation/Payload height at the end of a "
                      "phase, measured at every update (a grab: a knife that burrows worse takes less). "
                      "Range: [0, 1e6] (the largest grabs take tens of tonnes a cycle: a million is "
                      "a unit mistake).");
    prm.declare_entry("Seeds", "1", List(Integer(0)),
                      "Bed seeds of the replicate DEM cycles run at every update; their wear is "
                      "averaged. Every update settles fresh beds, their seeds derived from these and the "
                      "update number (the first update's are these seeds themselves, whose beds are kept in "
                      "beds/), so that the updates are independent samples for the life's interval "
                      "(docs/lifetime.md). Three or more give an interval from the first update on.");
    prm.declare_entry("Cycles per update", "0", Integer(0),
                      "Real cycles one update stands for; 0: adaptive, so that the largest depth "
                      "increment is 'Depth increment fraction' of the mesh size. Range: >= 0.");
    prm.declare_entry("Depth increment fraction", "0.05", Double(1e-6, 1),
                      "[-] Adaptive updates: largest depth increment per update over the mesh size. Range: (0, 1].");
    prm.declare_entry("Smoothing radius", "0", Double(0, huge),
                      "[m] Length of the wear filter: the per-cycle wear is smoothed over the knife's "
                      "surface with a Gaussian of this length in the distance along the surface (it never "
                      "crosses the plate), conserving the volume. It stands for the particle's footprint; "
                      "0: the largest particle radius (DEM wear), none (analytic wear). Range: >= 0.");
    prm.declare_entry("Recession points", "0.2, 0, 0", List(List(Double(-huge, huge), 3, 3), 1, 100, ";"),
                      "[m] Points of the knife (in its own coordinates: x along the length from 0, y "
                      "across the thickness from its middle, z up from the edge), separated by ';', whose "
                      "recession (how far the surface point that was there on the fresh knife has moved, "
                      "interpolated: at a chisel's tip, the tip's recession along its bisector) the trajectory "
                      "follows: column point_recession for the first, point_recession_2, ... for the "
                      "others. Default: the middle of the edge of the default knife.");
    prm.declare_entry("Gauge height", "0", Double(0, huge),
                      "[m] Where the plate's thickness is gauged, above the design's edge; 0: one plate "
                      "thickness above where the design's middle section first reaches its full thickness "
                      "(a chisel's bevel top, whose worn corner rises as the faces beside it wear). "
                      "Range: >= 0.");
    prm.declare_entry("Gauge stations", "41", Integer(2, 10000),
                      "Stations along the part's length (its x axis) where the edge recession and the plate "
                      "thickness are gauged, evenly spaced from end to end of the part as it is (the end ones "
                      "one Knife/Mesh size inside its ends: the corners as far as the mesh resolves them). "
                      "Range: [2, 10000].");
    lifetime::declare_wear_sources(prm); // (Wear source and each source's own: lifetime/wear_sources/)
    lifetime::declare_end_of_life_criteria(prm); // (Maximum depth, ...: each criterion's own, lifetime/criteria/)
    prm.declare_entry("Target tonnes", "0", Double(0, huge),
                      "[t] Stop when this many tonnes are handled; 0: no target. Range: >= 0.");
    prm.declare_entry("Maximum updates", "20", Integer(1), "Stop after this many updates. Range: >= 1.");
    prm.declare_entry("Target interval", "0", Double(0, 1),
                      "[-] The life's 95 % interval asked for, as a relative half-width (0.1: +-10 %); "
                      "while the interval is wider, the next updates draw more beds (the seeds' beds "
                      "settled again in further rounds), up to Maximum beds. The summary says what was "
                      "achieved. 0: the Seeds' beds at every update. Range: [0, 1).");
    prm.declare_entry("Maximum beds", "12", Integer(1, 1000),
                      "Target interval: the most beds an update draws. Range: [1, 1000].");
    prm.declare_entry("Calibration", "", Anything(),
                      "[file] calibration.json of abrade calibrate (relative to this file): the best-ranked "
                      "run's fitted wear coefficient (W) replaces the knife's, every cycle's wear scaled by "
                      "their ratio, and the fit's standard error enters the life's interval as its "
                      "component 'calibration' (to first order the life goes as 1/W). The fit holds for the "
                      "footprint it was made with (the calibrated run's Smoothing radius): another one is "
                      "warned about. DEM wear only. Empty: the case's W, no calibration component.");
    prm.declare_entry("Profile planes", "0.5", List(Double(0, 1)),
                      "Cross-sections of the knife written per update (knife/profile_N.csv and .png), "
                      "at these fractions of the knife's length (planes normal to its length).");
    prm.leave_subsection();

    prm.enter_subsection("Output");
    prm.declare_entry("Directory", "output", Anything(),
                      "Output directory (created if missing); `--output DIR` overrides it.");
    prm.declare_entry("Snapshot interval", "0.05", Double(0, huge),
                      "[s] Simulated time between ParaView snapshots (particles and walls, .vtp in "
                      ".pvd series); 0: only at the end of each phase. Range: >= 0.");
    prm.declare_entry("Force interval", "0.001", Double(0, huge),
                      "[s] Simulated time between rows of the wall force files "
                      "(walls/NAME_forces.csv); 0: every time step. Range: >= 0.");
    prm.declare_entry("Wear profile band", "0.01", Double(1e-6, huge),
                      "[m] Height of the bands of walls/NAME_wear_profile.csv (the wear by height "
                      "above a wall's lowest point, by face direction, and its filtered peak "
                      "depth). Range: > 0.");
    prm.declare_entry("Wear field", "archard_volume", volume_field_selection(),
                      "The worn-volume field that the wear profile (walls/NAME_wear_profile.csv), the "
                      "lifetime loop (the knife's wear depth), sweep, concepts and calibrate use: a "
                      "volume field of a wear law (" + volume_field_names() + "); the knife's "
                      "Wear/Laws must include its law.");
    prm.declare_entry("Wear filter length", "0.0275", Double(0, huge),
                      "[m] A fixed length of the surface filter for the filtered peak depth of "
                      "walls/NAME_wear_profile.csv (next to the filter over the largest particle "
                      "radius, the lifetime loop's default); the default is the thesis' "
                      "coarse-grained pellet radius, so that runs at several particle sizes "
                      "compare at one length. 0: none. Range: >= 0.");
    prm.declare_entry("Write particles", "true", Bool(),
                      "Whether snapshots include the particles (they dominate the output size).");
    prm.leave_subsection();

    prm.enter_subsection("Simulation");
    prm.declare_entry("Time step", "0", Double(0, 1),
                      "[s] Time step; 0: 'Rayleigh fraction' times the Rayleigh time step of the "
                      "smallest particle. Range: [0, 1].");
    prm.declare_entry("Maximum particle-steps", "1e12", Double(0, huge),
                      "[-] Refuse a run (one operating cycle, with its settling) that needs more particle-steps "
                      "than this, estimated from the particles, the time step and the phases before the bed is "
                      "generated (about 28 hours at 1e7 particle-steps/s); 0: no limit. Range: >= 0.");
    prm.declare_entry("Rayleigh fraction", "0.2", Double(1e-6, 1),
                      "[-] Time step as a fraction of the Rayleigh time step (EDEM recommends 0.2 "
                      "for dense packings, 0.4 for loose ones). Range: (0, 1].");
    declare_vector(prm, "Gravity", "0, 0, -9.81", "[m/s^2] Gravitational acceleration.");
    prm.declare_entry("Characteristic velocity", "1.5", Double(1e-9, huge),
                      "[m/s] Impact speed used to check the time step against the Hertz contact "
                      "time (a warning is printed when dt exceeds a tenth of it). Range: > 0.");
    prm.declare_entry("Skin", "0", Double(0, huge),
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
    prm.declare_entry("Rebalance threshold", "1.1", Double(1, huge),
                      "[-] Under mpirun the particles are spread over the ranks by recursive "
                      "coordinate bisection; the domains are cut again at a neighbour-list build "
                      "when the rank with the most particles owns more than this times the mean. "
                      "Range: >= 1.");
    declare_vector(prm, "Domain min", "-1000, -1000, -1000",
                   "[m] Lower corner of the simulation domain; a particle outside it is lost.");
    declare_vector(prm, "Domain max", "1000, 1000, 1000", "[m] Upper corner of the simulation domain.");
    prm.declare_entry("Maximum overlap fraction", "0.2", Double(0, 1),
                      "[-] An overlap larger than this fraction of the particle radius is reported "
                      "(usually a time step that is too large). Range: [0, 1].");
    prm.declare_entry("On error", "stop", selection_of(error_policies),
                      "What a lost particle or an excessive overlap does: stop the run with an "
                      "error, or print a warning and continue (lost particles are removed). A NaN "
                      "always stops the run.");
    prm.declare_entry("Phases", "penetration: 0.2666667, travel: 0.8",
                      dealii::Patterns::Map(Anything(), Double(0, huge), 0, 1000, ",", ":"),
                      "[s] The operating cycle as named phases with durations, in order: "
                      "'name: duration, name: duration'. Walls take their velocity per phase "
                      "name (Wall NAME/Motion/Velocities); wear and forces are reported per phase.");
    prm.declare_entry("Payload height", "", Anything(),
                      "[m] Payload of a grab: at the end of every phase, the mass of the particles "
                      "whose centre is above this height is reported (summary.json, per phase: "
                      "mass_above_payload_height); empty: not reported. Set it above the pile, so "
                      "that after hoisting it counts what the grab holds.");
    prm.leave_subsection();

    prm.enter_subsection("Particles");
    declare_material(prm, 1e8, 0.25, 3700, true);
    declare_interaction(prm, 0.6, 0.5, "particle-particle");
    prm.enter_subsection("Generation");
    declare_vector(prm, "Region min", "-0.97, -0.97, 0.03", "[m] Lower corner of the fill box.");
    declare_vector(prm, "Region max", "0.97, 0.97, 0.85", "[m] Upper corner of the fill box.");
    prm.declare_entry("Region mesh", "", Anything(),
                      "Optional closed surface mesh (STL/OBJ/PLY/VTK/VTP); particles are placed only "
                      "inside it (and inside the fill box). Empty: the box alone.");
    prm.declare_entry("Size distribution", "constant", selection_of(size_distributions),
                      "Particle radius distribution: constant (Radius), uniform in [Minimum radius, "
                      "Maximum radius], or normal (mean Radius, Standard deviation) truncated to "
                      "[Minimum radius, Maximum radius].");
    prm.declare_entry("Radius", "0.0275", Double(1e-9, huge),
                      "[m] Particle radius (constant), or the mean of the normal distribution. "
                      "The thesis' coarse-grained pellets (docs/physics.md): 0.0275. Range: > 0.");
    prm.declare_entry("Minimum radius", "0", Double(0, huge), "[m] Smallest radius (uniform, normal). Range: >= 0.");
    prm.declare_entry("Maximum radius", "0", Double(0, huge), "[m] Largest radius (uniform, normal). Range: >= 0.");
    prm.declare_entry("Standard deviation", "0", Double(0, huge), "[m] Of the normal distribution. Range: >= 0.");
    prm.declare_entry("Count", "0", Integer(0),
                      "Number of particles to generate; 0: use the solid fraction. Range: >= 0.");
    prm.declare_entry("Solid fraction", "0.35", Double(0, 0.5),
                      "[-] Particle volume over fill-region volume, used when Count = 0. "
                      "Range: [0, 0.5]; random placement (then a sweep of the free space) reaches "
                      "about 0.35 in a box, then the particles are poured.");
    prm.declare_entry("Seed", "1", Integer(0), "Random seed of the placement and sizes. Range: >= 0.");
    declare_vector(prm, "Initial velocity", "0, 0, -0.5", "[m/s] Velocity of the generated particles.");
    prm.leave_subsection();
    prm.enter_subsection("Coarse graining");
    prm.declare_entry("Factor", "1", Double(1e-3, 1e3),
                      "[-] Coarse-graining ratio f: every simulated particle is f times the size of "
                      "the real one and stands for f^3 of them. Particles/Generation describes the "
                      "real particles: its radii are multiplied by f and its Count (of real "
                      "particles) divided by f^3, so the bulk mass stays; Simulation/Skin is "
                      "multiplied by f and Particles/Settling/Kinetic energy threshold by f^3; "
                      "density, moduli, restitution and friction stay (Hertz-Mindlin contacts of "
                      "scaled spheres keep the bulk's stresses, bulk density and angle of repose); "
                      "the time step follows from the scaled radius. Parameters that stay in "
                      "absolute units (a fixed Time step, a Layer probe Thickness, Lifetime/"
                      "Smoothing radius, an imported bed) are named in a warning. What coarse "
                      "graining does to wear: docs/coarse-graining.md. Range: [0.001, 1000].");
    declare_vector(prm, "Fine region min", "0, 0, 0",
                   "[m] Multi-level coarse graining (a prototype): a box of the fill region that is "
                   "filled with particles coarse-grained by Fine region factor instead (its share of "
                   "the real Count by volume), say around a tool's path. Equal corners: none.");
    declare_vector(prm, "Fine region max", "0, 0, 0", "[m] Upper corner of the fine region.");
    prm.declare_entry("Fine region factor", "1", Double(1e-3, 1e3),
                      "[-] Coarse-graining ratio inside the fine region (smaller than Factor). The time "
                      "step follows the finer particles; a wall's contact layer and the wear filter "
                      "follow the largest radius unless set. Range: [0.001, 1000].");
    prm.leave_subsection();
    prm.enter_subsection("Settling");
    prm.declare_entry("Kinetic energy threshold", "1e-4", Double(0, huge),
                      "[J] The poured bed counts as settled when the mean kinetic energy per "
                      "particle falls below this. Range: >= 0.");
    prm.declare_entry("Maximum time", "1.0", Double(0, huge),
                      "[s] Longest settling time (the run goes on, with a warning, if the bed has "
                      "not settled by then). Range: >= 0.");
    prm.declare_entry("Bed file", "", Anything(),
                      "Settled-bed file. If it exists, the bed is loaded from it and no particles "
                      "are generated; otherwise the bed is generated, settled and saved there, so "
                      "later runs (and every operating cycle) start from the same bed. A relative "
                      "path is relative to the output directory; a new bed is not written out of it "
                      "('..'): a bed shared between runs is named by an absolute path. Empty: generate every time. "
                      "A file ending in .csv, .dump, .lammpstrj or .liggghts is a bed made elsewhere "
                      "and is imported as it is (not settled again, never written; relative to the "
                      "parameter file): a CSV table with columns x, y, z and radius or diameter [m] "
                      "(optional: id, vx, vy, vz, wx, wy, wz), or a LIGGGHTS/LAMMPS text dump "
                      "(dump custom with id x y z radius or diameter; its last snapshot). Every "
                      "particle gets Particles/Material; masses follow from its density.");
    prm.leave_subsection();
    prm.leave_subsection();

    for (const auto &name : lists.walls)
      {
        const auto chosen = lists.wall_choices.find(name);
        declare_wall(prm, name, chosen == lists.wall_choices.end() ? nullptr : &chosen->second);
      }
    declare_grab_mechanism(prm);
  }

  // -----------------------------------------------------------------------------------------------

  namespace
  {
    /// Particles/Coarse graining: the rules of dem/coarse_graining.h on the generation, the
    /// skin and the settling threshold, and a warning for each parameter that stays in absolute
    /// units (those of the walls: read_dem_case, with the walls).
    void apply_coarse_graining(ParameterFile &f, DemCase &c)
    {
      const double g = c.coarse_graining;
      if (g == 1)
        return;
      const std::vector<std::string> gp = {"Particles", "Generation"};
      const long   real_count           = c.fill.count;
      const double count                = dem::coarse_grain(g, c.fill, c.settings);
      c.settle_ke = dem::coarse_grain_energy(g, c.settle_ke); // a kinetic energy per particle
      if (real_count > 0 && count < 1)
        f.fail(gp, "Count", std::to_string(real_count) + " real particles make " + io::format_number(count) +
                              " particles coarse-grained by " + io::format_number(g) + ": too few for a bed");
      for (const auto &w : dem::coarse_graining_warnings(g, c.settings))
        c.warnings.push_back(w);
      if (g < 1)
        c.warnings.push_back("Particles/Coarse graining/Factor = " + io::format_number(g) +
                             " is below 1: the simulated particles are smaller than the real ones");
      if (dem::is_imported_bed(c.bed_file))
        c.warnings.push_back("the imported bed " + c.bed_file + " is used as it is: its radii are not scaled by "
                             "Particles/Coarse graining/Factor");
      auto &prm = f.handler();
      prm.enter_subsection("Lifetime");
      if (const double r = prm.get_double("Smoothing radius"); r > 0)
        c.warnings.push_back("Lifetime/Smoothing radius is fixed (" + io::format_number(r) + " m) while the particles "
                             "are coarse-grained: 0 ties the wear filter to the simulated radius");
      prm.leave_subsection();
    }
  } // namespace

  DemCase read_dem_case(ParameterFile &f)
  {
    ParameterHandler &prm = f.handler();
    DemCase           c;
    c.notes = f.notes();

    prm.enter_subsection("Output");
    c.snapshot_interval = prm.get_double("Snapshot interval");
    c.force_interval    = prm.get_double("Force interval");
    c.write_particles   = prm.get_bool("Write particles");
    c.wear_profile_band   = prm.get_double("Wear profile band");
    c.wear_filter_length  = prm.get_double("Wear filter length");
    c.wear_field          = prm.get("Wear field");
    prm.leave_subsection();

    prm.enter_subsection("Simulation");
    auto &s                   = c.settings;
    s.time_step               = prm.get_double("Time step");
    s.rayleigh_fraction       = prm.get_double("Rayleigh fraction");
    s.gravity                 = get_vector(prm, "Gravity");
    s.characteristic_velocity = prm.get_double("Characteristic velocity");
    s.skin                    = prm.get_double("Skin");
    s.damping   = get_choice(prm, "Damping model", damping_models);
    s.contact.rolling  = prm.get("Rolling model");
    s.contact.cohesion = prm.get("Cohesion model");
    s.threads   = prm.get_integer("Threads");
    s.shares    = prm.get_integer("Shares");
    s.adapt_threads = prm.get_bool("Adapt threads");
    s.rebalance_threshold = prm.get_double("Rebalance threshold");
    s.domain_min = get_vector(prm, "Domain min");
    s.domain_max = get_vector(prm, "Domain max");
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
    if (const std::string h = prm.get("Payload height"); !h.empty())
      {
        try
          {
            c.payload_height = std::stod(h);
          }
        catch (const std::exception &)
          {
            f.fail({"Simulation"}, "Payload height", "'" + h + "' is not a number");
          }
      }
    prm.leave_subsection();
    if (!(s.domain_min.array() < s.domain_max.array()).all())
      f.fail({"Simulation"}, "Domain max", "must exceed Domain min in x, y and z");
    if (c.phases.empty())
      f.fail({"Simulation"}, "Phases", "at least one phase is needed");

    prm.enter_subsection("Particles");
    c.particle_material    = read_material(f, {"Particles"}, "particles");
    c.particle_interaction = read_interaction(f, {"Particles"});
    prm.enter_subsection("Generation");
    const std::vector<std::string> gp = {"Particles", "Generation"};
    auto &fill                       = c.fill;
    fill.box_min                     = get_vector(prm, "Region min");
    fill.box_max                     = get_vector(prm, "Region max");
    c.region_mesh_file               = f.path_beside(prm.get("Region mesh"));
    const std::string dist           = prm.get("Size distribution");
    fill.sizes.kind   = get_choice(prm, "Size distribution", size_distributions);
    fill.sizes.radius = prm.get_double("Radius");
    fill.sizes.min    = prm.get_double("Minimum radius");
    fill.sizes.max    = prm.get_double("Maximum radius");
    fill.sizes.std    = prm.get_double("Standard deviation");
    fill.count        = prm.get_integer("Count");
    fill.solid_fraction = prm.get_double("Solid fraction");
    fill.seed           = prm.get_integer("Seed");
    fill.velocity       = get_vector(prm, "Initial velocity");
    prm.leave_subsection();
    if (!(fill.box_min.array() < fill.box_max.array()).all())
      f.fail(gp, "Region max", "must exceed Region min in x, y and z");
    // particles placed outside the domain are lost at the first step: a fill box outside it
    // gave a run of 0 particles and exit 0
    if (!(fill.box_min.array() >= s.domain_min.array()).all() || !(fill.box_max.array() <= s.domain_max.array()).all())
      f.fail(gp, "Region max", "the fill box (Region min .. Region max) must lie inside Simulation/Domain min .. max");
    if (dist != "constant" && !(fill.sizes.min > 0 && fill.sizes.max > fill.sizes.min))
      f.fail(gp, "Maximum radius", "a " + dist + " distribution needs 0 < Minimum radius < Maximum radius");
    if (dist == "normal" && !(fill.sizes.std > 0))
      f.fail(gp, "Standard deviation", "must be positive for a normal distribution");
    prm.enter_subsection("Coarse graining");
    c.coarse_graining = prm.get_double("Factor");
    const Vec3   fine_lo = get_vector(prm, "Fine region min"), fine_hi = get_vector(prm, "Fine region max");
    const double fine_factor = prm.get_double("Fine region factor");
    prm.leave_subsection();
    if (fine_lo != fine_hi)
      {
        const std::vector<std::string> cg = {"Particles", "Coarse graining"};
        if (!(fine_factor < c.coarse_graining))
          f.fail(cg, "Fine region factor", "must be smaller than Factor (" + io::format_number(c.coarse_graining) + ")");
        if (!c.region_mesh_file.empty())
          f.fail(cg, "Fine region max", "a fine region needs a fill box without Region mesh");
        if (!(fine_lo.array() < fine_hi.array()).all() || !(fine_lo.array() < fill.box_max.array()).all() ||
            !(fine_hi.array() > fill.box_min.array()).all())
          f.fail(cg, "Fine region max", "must exceed Fine region min and overlap the fill box");
        c.fine_fill         = dem::split_off_region(fill, fine_lo, fine_hi);
        dem::Settings unused = c.settings; // (the skin follows Factor)
        dem::coarse_grain(fine_factor, *c.fine_fill, unused);
        c.warnings.push_back("multi-level coarse graining (a prototype): particles coarse-grained by " +
                             io::format_number(fine_factor) + " in the fine region, by " +
                             io::format_number(c.coarse_graining) +
                             " elsewhere; contact layers and the wear filter follow the largest radius unless set");
      }
    prm.enter_subsection("Settling");
    c.settle_ke       = prm.get_double("Kinetic energy threshold");
    c.settle_max_time = prm.get_double("Maximum time");
    c.bed_file        = prm.get("Bed file");
    if (dem::is_imported_bed(c.bed_file)) // another code's bed: an input, next to the parameter file
      {
        c.bed_file = f.path_beside(c.bed_file);
        if (!std::ifstream(c.bed_file))
          f.fail({"Particles", "Settling"}, "Bed file",
                 "no bed to import at '" + c.bed_file + "' (a .csv table or a LIGGGHTS/LAMMPS dump is read, never "
                 "written; abrade's own beds end in .bed)");
      }
    prm.leave_subsection();
    prm.leave_subsection();
    if (!dem::is_imported_bed(c.bed_file) && std::filesystem::path(c.bed_file).is_relative())
      {
        // a relative bed is the run's own, in its output directory: one that would be written
        // out of it ('../x.bed', not there yet) is refused; reading one from anywhere is fine,
        // and a bed shared between runs is named by an absolute path, on purpose
        prm.enter_subsection("Output");
        const std::filesystem::path output = prm.get("Directory");
        prm.leave_subsection();
        const std::filesystem::path bed(c.bed_file);
        const bool escapes = std::any_of(bed.begin(), bed.end(), [](const std::filesystem::path &part) { return part == ".."; });
        if (escapes && !std::filesystem::exists(output / bed))
          f.fail({"Particles", "Settling"}, "Bed file",
                 "'" + c.bed_file + "' would be written out of the output directory (a relative bed file is the run's "
                 "own, inside it): name a bed shared between runs by its absolute path");
      }
    apply_coarse_graining(f, c);
    prm.enter_subsection("Simulation");
    c.max_particle_steps = prm.get_double("Maximum particle-steps");
    prm.leave_subsection();
    check_run_size(c, f); // a run of years, or of more memory than there is, is refused here

    for (const auto &name : get_list(prm, "Walls"))
      c.walls.push_back(read_wall(f, name, c));
    mount_knives(f, c);
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
