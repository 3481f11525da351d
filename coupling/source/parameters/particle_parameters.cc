// Subsection Particles (particle_parameters.h): the particles' material and contacts, how the
// bed is generated (the fill region and the sizes), coarse graining, and the settling with its
// bed file.
#include <abrade/dem/parameter_section.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/material_parameters.h>
#include <abrade/coupling/parameters/output_parameters.h>
#include <abrade/coupling/parameters/parameter_choices.h>
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/coupling/parameters/particle_parameters.h>
#include <abrade/dem/bed_import.h>
#include <abrade/dem/coarse_graining.h>
#include <abrade/dem/generation.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>

namespace abrade::coupling
{
  using dealii::Patterns::Anything;
  using dealii::Patterns::Double;
  using dealii::Patterns::Integer;
  using dem::Vec3;

  namespace
  {
    const Choices<dem::SizeDistribution::Kind> size_distributions = {
      {"constant", dem::SizeDistribution::Kind::constant},
      {"uniform", dem::SizeDistribution::Kind::uniform},
      {"normal", dem::SizeDistribution::Kind::normal}};

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
    }

    /// Multi-level coarse graining: the lengths and energies tied to the particle size follow
    /// the finest level (the particles the tools meet; a skin of the bulk's would make the
    /// finer particles' neighbour lists hold f_bulk / f_fine times their reach), the settling
    /// threshold the mean particle mass of the levels together.
    void follow_the_finest_level(DemCase &c)
    {
      if (c.finer_levels.empty())
        return;
      const double g = c.coarse_graining, fine = c.finer_levels.front().factor;
      c.settings.skin *= fine / g; // coarse_grain scaled it by g
      // the levels' counts (with Count 0 those the solid fraction gives, as the generator counts)
      double count = dem::expected_particles(c.fill), mass = count * g * g * g; // in real particles' masses
      for (const auto &level : c.finer_levels)
        {
          const double n = dem::expected_particles(level.fill);
          count += n, mass += n * std::pow(level.factor, 3);
        }
      if (count > 0) // the mean kinetic energy per particle scales as the mean mass
        c.settle_ke *= mass / count / (g * g * g);
    }
  } // namespace

  namespace
  {
    /// Particles/Generation: the fill box, the sizes and their distribution, the count, the seed
    /// and the initial velocity.
    void declare_generation(dealii::ParameterHandler &prm, PluginSection &section)
    {
      prm.enter_subsection("Generation");
      section.declare_vector("Region min", {-0.97, -0.97, 0.03}, "[m] Lower corner of the fill box.");
      section.declare_vector("Region max", {0.97, 0.97, 0.85}, "[m] Upper corner of the fill box.");
      prm.declare_entry("Region mesh", "", Anything(),
                        "Optional closed surface mesh (STL/OBJ/PLY/VTK/VTP); particles are placed only "
                        "inside it (and inside the fill box). Empty: the box alone.");
      prm.declare_entry("Size distribution", "constant", selection_of(size_distributions),
                        "Particle radius distribution: constant (Radius), uniform in [Minimum radius, "
                        "Maximum radius], or normal (mean Radius, Standard deviation) truncated to "
                        "[Minimum radius, Maximum radius].");
      prm.declare_entry("Radius", "0.0275", Double(1e-9, dem::unbounded),
                        "[m] Particle radius (constant), or the mean of the normal distribution. "
                        "The thesis' coarse-grained pellets (docs/physics.md): 0.0275. Range: > 0.");
      prm.declare_entry("Minimum radius", "0", Double(0, dem::unbounded), "[m] Smallest radius (uniform, normal). Range: >= 0.");
      prm.declare_entry("Maximum radius", "0", Double(0, dem::unbounded), "[m] Largest radius (uniform, normal). Range: >= 0.");
      prm.declare_entry("Standard deviation", "0", Double(0, dem::unbounded), "[m] Of the normal distribution. Range: >= 0.");
      prm.declare_entry("Count", "0", Integer(0),
                        "Number of particles to generate; 0: use the solid fraction. Range: >= 0.");
      prm.declare_entry("Solid fraction", "0.35", Double(0, 0.5),
                        "[-] Particle volume over fill-region volume, used when Count = 0. "
                        "Range: [0, 0.5]; random placement (then a sweep of the free space) reaches "
                        "about 0.35 in a box, then the particles are poured.");
      prm.declare_entry("Seed", "1", Integer(0), "Random seed of the placement and sizes. Range: >= 0.");
      section.declare_vector("Initial velocity", {0, 0, -0.5}, "[m/s] Velocity of the generated particles.");
      prm.leave_subsection();
    }

    /// Particles/Coarse graining: the factor, and the fine region with its levels.
    void declare_coarse_graining(dealii::ParameterHandler &prm, PluginSection &section)
    {
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
      section.declare_vector("Fine region min", {0, 0, 0},
                     "[m] Multi-level coarse graining: a box of the fill region that is filled with "
                     "particles coarse-grained by Fine region factor instead (its share of the real "
                     "Count by volume), around the tools' paths; layers of intermediate sizes surround "
                     "it (Fine region step). Equal corners: none. docs/coarse-graining.md.");
      section.declare_vector("Fine region max", {0, 0, 0}, "[m] Upper corner of the fine region.");
      prm.declare_entry("Fine region factor", "1", Double(1e-3, 1e3),
                        "[-] Coarse-graining ratio inside the fine region (smaller than Factor). The time "
                        "step, the skin, a wall's contact layer and the wear filter follow these finer "
                        "particles (the ones the tools meet). Range: [0.001, 1000].");
      prm.declare_entry("Fine region step", "1.25", Double(0, 1e3),
                        "[-] Largest ratio between the coarse-graining factors of neighbouring sizes: "
                        "shells of intermediate sizes around the fine region take the factor from Fine "
                        "region factor to Factor in equal steps no larger than this, so that no two sizes "
                        "that meet differ by more (two sizes 2x apart pack up to 12 % denser where they meet; "
                        "docs/coarse-graining.md). 0: none (the fine particles meet the bulk's). Range: 0 "
                        "or >= 1.05.");
      prm.declare_entry("Fine region layer thickness", "1", Double(0.5, 1e3),
                        "[particle diameters] Thickness of each intermediate shell, in the largest "
                        "diameter of its particles. Range: [0.5, 1000].");
      prm.declare_entry("Fine region pours", "3", Integer(1, 10),
                        "[-] How many times a multi-level bed is poured (only with a fine region, and only "
                        "when its bed is made: a saved Bed file is used as it is, with a warning when it "
                        "was poured another number of times). While a bed settles, the finer particles "
                        "spread into the coarser ones' voids, so that poured once the fine region holds "
                        "about 3 % less mass per area than the case pours over it (the knife-bed's: 96.7 %, "
                        "its top 15 mm lower than the uniform bed's). Each pour but the last measures what "
                        "each level's footprint (its box across x and y) lacks once settled, and the next "
                        "is poured with that level's count raised by it, the bulk's lowered (the total mass "
                        "stays, to half a bulk particle): 96.7, 99.0 and 99.7 % in three pours. Each pour "
                        "settles the bed again (a lifetime run's beds too, once each); a refilled count the "
                        "random placement cannot hold is refused. 1: poured once. The log and summary.json "
                        "(coarse_graining.pours) give each pour's shares. docs/coarse-graining.md. Range: "
                        "[1, 10].");
      prm.leave_subsection();
    }

    /// Particles/Settling: when a bed counts as settled (kinetic energy, time) and its bed file.
    void declare_settling(dealii::ParameterHandler &prm)
    {
      prm.enter_subsection("Settling");
      prm.declare_entry("Kinetic energy threshold", "1e-4", Double(0, dem::unbounded),
                        "[J] The poured bed counts as settled when the mean kinetic energy per "
                        "particle falls below this. Range: >= 0.");
      prm.declare_entry("Maximum time", "1.0", Double(0, dem::unbounded),
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
    }
  } // namespace

  void declare_particle_parameters(dealii::ParameterHandler &prm)
  {
    PluginSection section(prm);
    prm.enter_subsection("Particles");
    declare_material(prm, 1e8, 0.25, 3700, true);
    declare_interaction(prm, 0.6, 0.5, "particle-particle");
    declare_generation(prm, section);
    declare_coarse_graining(prm, section);
    declare_settling(prm);
    prm.leave_subsection();
  }

  namespace
  {
    /// Particles/Generation (the handler in Particles): the fill box inside the domain, the
    /// sizes and their distribution.
    void read_generation(ParameterFile &f, DemCase &c)
    {
      dealii::ParameterHandler &prm = f.handler();
      const auto               &s   = c.settings; // (Simulation's, read before: the domain)
      prm.enter_subsection("Generation");
      const std::vector<std::string> gp = {"Particles", "Generation"};
      auto &fill                       = c.fill;
      fill.box_min                     = vector_entry(prm, "Region min");
      fill.box_max                     = vector_entry(prm, "Region max");
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
      fill.velocity       = vector_entry(prm, "Initial velocity");
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
    }

    /// Particles/Coarse graining (the handler in Particles): the factor, and a fine region split
    /// off the fill where one is given.
    void read_fine_region(ParameterFile &f, DemCase &c)
    {
      dealii::ParameterHandler &prm  = f.handler();
      auto                     &fill = c.fill;
      prm.enter_subsection("Coarse graining");
      c.coarse_graining = prm.get_double("Factor");
      dem::FineRegion region;
      region.lo = vector_entry(prm, "Fine region min"), region.hi = vector_entry(prm, "Fine region max");
      region.factor          = prm.get_double("Fine region factor");
      region.step            = prm.get_double("Fine region step");
      region.layer_diameters = prm.get_double("Fine region layer thickness");
      c.fine_region_pours    = static_cast<int>(prm.get_integer("Fine region pours"));
      prm.leave_subsection();
      if (region.lo == region.hi)
        return;
      const std::vector<std::string> cg = {"Particles", "Coarse graining"};
      if (!(region.factor < c.coarse_graining))
        f.fail(cg, "Fine region factor", "must be smaller than Factor (" + io::format_number(c.coarse_graining) + ")");
      if (region.step != 0 && !(region.step >= 1.05))
        f.fail(cg, "Fine region step", "must be 0 (no intermediate sizes) or at least 1.05 (smaller steps make thousands of sizes)");
      if (!c.region_mesh_file.empty())
        f.fail(cg, "Fine region max", "a fine region needs a fill box without Region mesh");
      if (!(region.lo.array() < region.hi.array()).all() || !(region.lo.array() < fill.box_max.array()).all() ||
          !(region.hi.array() > fill.box_min.array()).all())
        f.fail(cg, "Fine region max", "must exceed Fine region min and overlap the fill box");
      try
        {
          c.finer_levels = dem::split_into_levels(fill, region, c.coarse_graining);
        }
      catch (const std::invalid_argument &e)
        {
          f.fail(cg, "Fine region max", std::string(e.what()) + " (Fine region layer thickness and step set the shells)");
        }
      c.tool_particle_radius = c.finer_levels.front().fill.sizes.largest();
      std::string sizes;
      for (const auto &level : c.finer_levels)
        sizes += io::format_number(level.fill.sizes.largest(), 3) + " m (" + std::to_string(level.fill.count) + "), ";
      c.notes.push_back("multi-level coarse graining: particles of " + sizes + "and " +
                        io::format_number(fill.sizes.largest() * c.coarse_graining, 3) +
                        " m elsewhere (largest radius, count); the time step, skin, contact layers and wear filter "
                        "follow the finest, the settling threshold the mean particle mass");
    }

    /// Particles/Settling (the handler in Particles): when a bed has settled, and the bed file
    /// (another code's bed: an input, next to the parameter file, which must be there).
    void read_settling(ParameterFile &f, DemCase &c)
    {
      dealii::ParameterHandler &prm = f.handler();
      prm.enter_subsection("Settling");
      c.settle_ke       = prm.get_double("Kinetic energy threshold");
      c.settle_max_time = prm.get_double("Maximum time");
      c.bed_file        = prm.get("Bed file");
      if (dem::is_imported_bed(c.bed_file))
        {
          c.bed_file = f.path_beside(c.bed_file);
          if (!std::ifstream(c.bed_file))
            f.fail({"Particles", "Settling"}, "Bed file",
                   "no bed to import at '" + c.bed_file + "' (a .csv table or a LIGGGHTS/LAMMPS dump is read, never "
                   "written; abrade's own beds end in .bed)");
        }
      prm.leave_subsection();
    }

    /// A relative bed is the run's own, in its output directory: one that would be written out
    /// of it ('../x.bed', not there yet) is refused; reading one from anywhere is fine, and a bed
    /// shared between runs is named by an absolute path, on purpose.
    void check_bed_stays_in_output(ParameterFile &f, const DemCase &c)
    {
      if (dem::is_imported_bed(c.bed_file) || !std::filesystem::path(c.bed_file).is_relative())
        return;
      const std::filesystem::path output = output_directory(f);
      const std::filesystem::path bed(c.bed_file);
      const bool escapes = std::any_of(bed.begin(), bed.end(), [](const std::filesystem::path &part) { return part == ".."; });
      if (escapes && !std::filesystem::exists(output / bed))
        f.fail({"Particles", "Settling"}, "Bed file",
               "'" + c.bed_file + "' would be written out of the output directory (a relative bed file is the run's "
               "own, inside it): name a bed shared between runs by its absolute path");
    }
  } // namespace

  void read_particle_parameters(ParameterFile &f, DemCase &c)
  {
    dealii::ParameterHandler &prm = f.handler();
    prm.enter_subsection("Particles");
    c.particle_material    = read_material(f, {"Particles"}, "particles");
    c.particle_interaction = read_interaction(f, {"Particles"});
    read_generation(f, c);
    read_fine_region(f, c);
    read_settling(f, c);
    prm.leave_subsection();
    check_bed_stays_in_output(f, c);
    apply_coarse_graining(f, c);
    follow_the_finest_level(c);
  }
} // namespace abrade::coupling
