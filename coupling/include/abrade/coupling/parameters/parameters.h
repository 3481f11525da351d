#pragma once
// The parameters of a case: the declaration of every subsection, each by its owner (the file of
// what it configures, listed in parameters.cc), composed here, and their conversion into the
// plain settings structs of the DEM (which knows nothing of deal.II). One subsection per
// component, one "Wall NAME" subsection per wall.
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/walls/wall_geometry.h>
#include <abrade/dem/coarse_graining.h>
#include <abrade/dem/generation.h>
#include <abrade/dem/rope_grab_driver.h>
#include <abrade/dem/simulation.h>
#include <abrade/dem/wear.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace abrade::coupling
{
  /// A wall's Geometry and Motion/Type, which decide the entries it has.
  struct WallChoices
  {
    std::string geometry, motion;
  };

  /// Names that shape the declaration (read in the first pass).
  struct DeclarationLists
  {
    std::vector<std::string> walls = {"container", "knife"};
    /// each wall's choices, read from the file (a wall not here has every geometry's and
    /// motion's entries: `abrade params`)
    std::map<std::string, WallChoices> wall_choices;
  };

  /// Why @p name cannot be a wall or phase name (it becomes a file name: letters, digits, '_'
  /// and '-', at most 64), or "" when it can.
  std::string bad_name(const std::string &name);

  /// First pass: declares the lists only.
  void declare_lists(dealii::ParameterHandler &prm);
  DeclarationLists read_lists(dealii::ParameterHandler &prm);

  /// Second pass: declares everything.
  void declare_parameters(dealii::ParameterHandler &prm, const DeclarationLists &lists);

  /// A phase of the operating cycle: name and duration [s].
  using Phase = std::pair<std::string, double>;

  /// Everything the DEM job needs, read from the parameters.
  struct DemCase
  {
    dem::Settings            settings;
    dem::Material            particle_material;
    dem::Interaction         particle_interaction;
    dem::FillRegion          fill;
    std::string              region_mesh_file;
    double                   settle_ke = 1e-4, settle_max_time = 1;
    double                   max_particle_steps = 1e12; ///< of one run (0: no limit)
    double                   coarse_graining = 1; ///< Particles/Coarse graining/Factor (applied)
    /// Multi-level coarse graining: the finer levels' fills, finest first (fill holds the rest).
    std::vector<dem::Level>  finer_levels;
    /// Particles/Coarse graining/Fine region pours: a multi-level bed is poured this many
    /// times, each with the levels' counts refilled by what their footprints lacked before.
    int                      fine_region_pours = 3;
    /// The largest radius of the particles the tools meet: the finest level's where there are
    /// levels, else 0 (the largest in the bed). Lengths tied to the particle size near a wall
    /// (the contact layer's thickness, the wear filter) follow it.
    double                   tool_particle_radius = 0;
    /// tool_particle_radius, or without levels @p bed_radius (the bed's largest radius).
    double particle_radius_at_tools(double bed_radius) const
    {
      return tool_particle_radius > 0 ? tool_particle_radius : bed_radius;
    }
    /// The same for the bed of @p sim.
    double particle_radius_at_tools(const dem::Simulation &sim) const
    {
      return particle_radius_at_tools(sim.largest_radius());
    }
    /// The coarse-graining factor of the particles the tools meet (the finest level's, else
    /// Factor): the one that goes with particle_radius_at_tools.
    double factor_at_tools() const { return finer_levels.empty() ? coarse_graining : finer_levels.front().factor; }
    double                   wear_profile_band = 0.01, wear_filter_length = 0.0275; ///< Output/...
    std::string              wear_field = "archard_volume"; ///< Output/Wear field
    std::vector<std::string> warnings;            ///< parameters that do not follow it, ...
    std::vector<std::string> notes;               ///< what the reading decided (ParameterFile::notes)
    std::string              bed_file;
    std::vector<std::string> input_files; ///< the mesh files read (no output may replace one)
    std::vector<Phase>       phases;
    std::optional<double>    payload_height; ///< report the mass above it after every phase
    struct WallCase
    {
      dem::Wall        wall;
      dem::Material    material;
      dem::Interaction interaction;
      dem::WallWearLaws wear; ///< its wear laws (none: not tracked)
      bool             probe = false;          ///< the contact-layer probe (geometry bin)
      dem::Vec3        probe_axis = dem::Vec3::UnitX();
      double           probe_thickness = 0;    ///< 0: 1.5 x the largest particle radius
      double           probe_interval  = 1e-3; ///< [s]
      bool             solid_model = false;    ///< the mesh is the FEM part's surface
      /// Placement of the geometry: p -> rotation p + offset (rotation: identity unless the wall
      /// is a part mounted on a shell's lip).
      dem::Vec3        offset   = dem::Vec3::Zero();
      Eigen::Matrix3d  rotation = Eigen::Matrix3d::Identity();
      using Shell = ShellShape;
      std::optional<Shell> shell;
      /// Where a part sits on this wall (a shell's lip), at t = 0 in the global frame
      /// (wall_geometry.h). Parametric shells have one; a shell read from a file gets one from
      /// 'Lip centre', 'Lip direction', 'Lip inward'.
      using Lip = WallLip;
      std::optional<Lip> lip;
      std::string          mount; ///< the shell whose lip carries this part ("": none)
      double               protrusion = 0.02; ///< of a mounted knife's edge beyond the lip [m]
    };
    std::vector<WallCase> walls;
    /// The mechanism that moves a grab's walls (Grab mechanism; none: each wall's own motion).
    std::optional<dem::RopeGrabRig> grab_mechanism;
    /// Part/Length, by which mount_parts centres a mounted part on its lip [m]
    double mounted_part_length = 0.4;
    double snapshot_interval = 0.05, force_interval = 1e-3;
    bool   write_particles   = true;
  };

  /// Reads and checks the DEM parameters; errors name the file, line and key.
  DemCase read_dem_case(ParameterFile &file);

  /// Builds the simulation (materials, interactions, walls, the grab's mechanism) of a case,
  /// without particles; returns the mechanism that moves the grab's walls (none: null).
  std::shared_ptr<dem::RopeGrabDriver> build_simulation(const DemCase &c, dem::Simulation &sim);
} // namespace abrade::coupling
