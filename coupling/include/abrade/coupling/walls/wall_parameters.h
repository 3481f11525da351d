#pragma once
// The subsection "Wall NAME" of every wall: its geometry (a plugin, walls/wall_geometry.h), its
// placement, material, contact, wear laws, contact-layer probe and motion (a plugin,
// dem/wall_motion_model.h), declared and read into the DEM's wall.
//
// A wall declares only the entries of its own geometry and motion: the file is read once
// leniently for each wall's Geometry and Motion/Type (read_wall_choices()), then every entry is
// declared and the file read strictly. An entry of another geometry or motion set on a wall is
// then an error that says whose entry it is (foreign_entry_hint()), unless it is that plugin's
// default or a replaced choice's (ParameterFile leaves those out: plugin_entry()).
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// First pass, after the wall names: declares each wall's Geometry and Motion/Type (any text)
  /// and reads what the file chose. A wall whose choice is not registered (a typing error) gets
  /// none: all entries are declared for it, and the strict pass refuses the choice itself.
  void declare_wall_choices(dealii::ParameterHandler &prm, const std::vector<std::string> &walls);
  std::map<std::string, WallChoices> read_wall_choices(dealii::ParameterHandler &prm,
                                                       const std::vector<std::string> &walls);

  /// Declares subsection "Wall @p name" with the entries of the chosen geometry and motion
  /// (@p choices; nullptr: of every one, as `abrade params` lists them).
  void declare_wall(dealii::ParameterHandler &prm, const std::string &name, const WallChoices *choices);

  /// Reads and checks wall @p name of case @p c (whose phases, particles and coarse graining are
  /// read), adding its warnings and input files to @p c.
  DemCase::WallCase read_wall(ParameterFile &f, const std::string &name, DemCase &c);

  /// Places every mounted part (@p part_length long, Part/Length: part_parameters.h) on its
  /// shell's lip and gives it the shell's motion.
  void mount_parts(ParameterFile &f, DemCase &c, double part_length);

  /// Whether a wall of Walls is the part's surface (Geometry = solid model). A file that
  /// describes a part alone has none: no case around the part.
  bool a_wall_is_the_part(ParameterFile &f);

  /// The defaults of a wall's entries that depend on its name. They are the default case's
  /// (Walls = container, knife): a wall named "knife" is that case's knife, worn by Archard's
  /// law, probed, pushed down and along at 1.5 m/s with friction 0.4 against the particles;
  /// any other is a fixed box with friction 0.5, no wear and no probe. (Files of earlier
  /// versions rely on a wall named knife getting these; every other default is the same for
  /// all walls.)
  struct WallDefaults
  {
    WallChoices choices;      ///< Geometry, Motion/Type
    std::string wear_laws;    ///< Wear/Laws
    bool        probe;        ///< Layer probe/Enabled
    std::string velocities;   ///< Motion/Velocities
    double      friction;     ///< Interaction/Friction
  };
  WallDefaults wall_defaults(const std::string &name);

  /// A wall's Geometry and Motion/Type where the file does not set them.
  WallChoices default_wall_choices(const std::string &name);

  /// An entry of a wall that a geometry (in Wall NAME) or a motion (in Wall NAME/Motion)
  /// declares: which choice it depends on ("Geometry" or "Motion/Type"), and each plugin that
  /// declares it with its default there.
  struct PluginEntry
  {
    std::string                        family;
    std::map<std::string, std::string> defaults; ///< plugin name -> default, as a file writes it
  };
  /// The plugins that declare @p key in subsection @p path, if @p path is a wall's or its
  /// Motion and any does.
  std::optional<PluginEntry> plugin_entry(const std::vector<std::string> &path, const std::string &key);

  /// Whether the value @p a of an entry is @p b: the same text but for blanks and case, or the
  /// same numbers ("0,0,0" and "0, 0, 0.0"; "yes" and "true").
  bool same_value(std::string a, std::string b);

  /// An entry set on a wall that belongs to another geometry or motion than the wall's own
  /// choice (@p lists' wall_choices): the plugins that declare it, and the wall's choice.
  struct ForeignEntry
  {
    PluginEntry entry;
    std::string wall; ///< its name ("floor" of subsection "Wall floor")
    std::string ours; ///< the wall's own choice in entry.family
    /// the wall's own default for it, where the wall gives one (the default case's knife's
    /// Velocities, which an earlier abrade printed whatever its motion)
    std::string own_default;
    /// Whether @p value is one of those plugins' default for it, or the wall's own (a no-op).
    bool at_default(const std::string &value) const;
  };
  /// @p key in subsection @p path as such an entry; nullopt when it is the wall's own (or no
  /// plugin's, or not a wall's).
  std::optional<ForeignEntry> foreign_entry(const DeclarationLists &lists, const std::vector<std::string> &path,
                                            const std::string &key);

  /// When @p key (in subsection @p path) is an entry of another geometry or motion than the
  /// wall's, a sentence that says so; otherwise "".
  std::string foreign_entry_hint(const DeclarationLists &lists, const std::vector<std::string> &path,
                                 const std::string &key);
} // namespace abrade::coupling
