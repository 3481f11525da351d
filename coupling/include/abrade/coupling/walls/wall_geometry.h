#pragma once
// Wall geometries as plugins: what `Wall NAME/Geometry` chooses. A geometry is a class in a file
// of its own in coupling/source/walls/geometries/ that says
//
//  - which parameters it takes (declared, read and checked through dem::ParameterSection, in
//    the subsection Wall NAME itself: a wall declares only its own geometry's entries), and
//  - the triangles it makes of them, in its own coordinates (the wall then rotates, moves,
//    refines and flips them: Rotation axis/angle, Offset, Maximum edge length, Flip normals),
//    with what else the geometry knows: a lip a knife can be mounted on, and whether it is the
//    FEM part's surface,
//
// and registers itself there with one line:
//
//   ABRADE_REGISTER_WALL_GEOMETRY(Plate);
//
// The geometries live in the coupling because two of them need the FEM library: a CAD file is
// meshed by Gmsh, and a solid model is the FEM part's surface (filled in by the job).
#include <abrade/common/plugin_registry.h>
#include <abrade/dem/parameter_section.h>
#include <abrade/dem/triangle_mesh.h>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// Where a knife sits on a wall (a shell's lip): the lip's centre, a unit vector along it, and
  /// a unit vector from the lip into the shell along its bottom (the mounted knife's inner face
  /// looks along inward x along).
  struct WallLip
  {
    dem::Vec3 centre, along, inward;
  };

  /// A clamshell shell: its radius, lip angle at t = 0 [rad] and side (+1: opens to +x).
  struct ShellShape
  {
    double radius = 0, opening = 0;
    int    side   = 1;
  };

  /// What a geometry may need of the case when it reads its parameters.
  struct WallGeometryContext
  {
    /// A path as named in the parameter file: relative to the file's directory.
    std::function<std::string(const std::string &)> path_beside;
    /// Wall NAME/Maximum edge length [m] (0: the mesh as it is made).
    double maximum_edge_length = 0;
  };

  /// A wall's shape as its geometry makes it, in the geometry's own coordinates (before the
  /// wall's Rotation and Offset).
  struct WallShape
  {
    dem::TriangleMesh         mesh;
    std::optional<WallLip>    lip;   ///< where a knife can be mounted
    std::optional<ShellShape> shell; ///< a clamshell shell's own shape
    bool solid_model = false;        ///< the mesh is the FEM part's surface (filled in by the job)
    std::string mount;               ///< the shell whose lip carries this part ("": none)
    double      protrusion = 0.02;   ///< of a mounted part's edge beyond the lip [m]
    std::vector<std::string> input_files; ///< the files read (no output may replace one)
    /// Why the wall may not be given a Rotation angle of its own ("": it may).
    std::string fixed_orientation;
  };

  class WallGeometry
  {
  public:
    virtual ~WallGeometry() = default;
    /// The name written in Wall NAME/Geometry ("plate").
    virtual std::string name() const = 0;
    /// What it is, a phrase for Geometry's documentation ("a rectangle").
    virtual std::string documentation() const = 0;
    virtual void        declare_parameters(dem::ParameterSection &) const {}
    /// Reads (and checks) its parameters for one wall and makes its shape.
    virtual WallShape make(const dem::ParameterSection &, const WallGeometryContext &) const = 0;
  };

  using WallGeometryFactory = std::unique_ptr<WallGeometry> (*)();

  /// One new instance of every registered geometry, in the order of their names.
  std::vector<std::unique_ptr<WallGeometry>> make_wall_geometries();
  /// A new geometry of that name; nullptr if there is none.
  std::unique_ptr<WallGeometry> make_wall_geometry(const std::string &name);

  /// Adds a geometry (ABRADE_REGISTER_WALL_GEOMETRY); a name registered twice is a bug.
  struct WallGeometryRegistration
  {
    explicit WallGeometryRegistration(WallGeometryFactory make);
  };
} // namespace abrade::coupling

/// One line in a geometry's file registers it (at namespace scope).
#define ABRADE_REGISTER_WALL_GEOMETRY(Class)                                                              \
  ABRADE_REGISTER_PLUGIN(::abrade::coupling::WallGeometryRegistration, ::abrade::coupling::WallGeometry, Class)
