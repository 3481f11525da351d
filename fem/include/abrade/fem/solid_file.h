#pragma once
// A user's part from a file: a Gmsh .msh volume mesh, a STEP/IGES CAD model or a closed STL
// surface, read into a tetrahedral deal.II triangulation in metres, placed, with the file's own
// face numbers as boundary ids (part_faces.h then says which wear and which are clamped).
//
// In order: the file is read (CAD: OpenCASCADE converts the unit the file declares; STL and .msh
// have none, `scale` says it), one solid is chosen when the file holds several, the size is
// checked against the unit (a part in millimetres read as metres is refused, naming its bounding
// box and the likely scale), the cell count is estimated and checked against the budget, Gmsh
// meshes it, a poor mesh is optimised once more (Gmsh's optimisers, harder) and reported with where it
// is poor, and last the part is rotated and moved into place.
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/tensor.h>
#include <deal.II/grid/tria.h>

#include <map>
#include <array>
#include <string>
#include <vector>

namespace abrade::fem
{
  /// How a solid file is read: units, limits, which solid, placement (a user's part, not a
  /// generated one).
  /// Parses Part/Place: ','-separated 'centred' (in x and y), 'centred in x' (y, z), 'lowest
  /// point at z = V' [m]; empty: none. Throws std::invalid_argument naming the item.
  struct SolidFileSettings;
  void parse_part_placement(const std::string &text, SolidFileSettings &settings);

  struct SolidFileSettings
  {
    /// Multiplies the file's coordinates: STL, OBJ and .msh files have no units (0.001: the file
    /// is in millimetres). STEP/IGES files declare their unit, which is converted to metres on
    /// import (OpenCASCADE); the scale applies on top of that.
    double scale = 1;
    /// Refuse parts that would need more tetrahedra than this (estimated before meshing from the
    /// part's volume: about 8.5 V / h^3); 0: no limit.
    double max_cells = 0;
    /// Refuse parts whose bounding box is larger than this or whose largest extent is smaller
    /// than min_extent [m], naming the box and the likely unit (a part in millimetres read as
    /// metres is 1000x too large).
    double max_extent = 50, min_extent = 1e-3;
    /// Refuse parts with a larger volume [m^3] (a mass limit over the density); 0: no limit.
    double max_volume = 0;
    /// A CAD file with several solids: "" or "all" takes all of them as one part; a number
    /// takes the solid of that number (Gmsh's volume tag, as the message lists them).
    std::string solid;
    /// Where the intermediate meshes go (the run's own directory, so that nothing is written
    /// outside it); empty: a directory of this process's own, made with exclusive create in the
    /// system's temporary folder and removed when the process ends.
    std::string work_directory;
    /// Below this minimum scaled Jacobian a mesh made by Gmsh is optimised once more (Gmsh: vertices relocated, cells below 0.5 improved),
    /// and a mesh still below it is reported with the place of its worst cell.
    double min_quality = 0.05;
    /// Placement after the scale: p -> R p + t + offset, R the right-handed rotation by
    /// rotation_angle [degrees] about rotation_axis through the origin, t the move @p place asks
    /// of the rotated part's bounding box.
    dealii::Tensor<1, 3> rotation_axis{{0, 0, 1}};
    double               rotation_angle = 0;
    dealii::Tensor<1, 3> offset;
    struct Place
    {
      std::array<bool, 3> centred{};     ///< the bounding box's centre to 0 along x, y, z
      bool                lowest = false; ///< the lowest point to z = lowest_z
      double              lowest_z = 0;   ///< [m]
      std::string         text;           ///< as written
    } place;
    /// [s] How long Gmsh may mesh the part (it runs in a child process: fem/meshing_job.h); 0:
    /// ABRADE_MESHER_TIME_LIMIT, or 1800 s.
    double mesher_time_limit = 0;
    /// [degrees] An STL remeshed by Gmsh keeps the facets' edges where they meet at more than
    /// this (its surface classification; the patches between are reparametrised and meshed
    /// anew).
    double classify_angle = 15;
  };

  /// What reading a solid file found out, for the log and summary.json.
  struct SolidFileReport
  {
    std::vector<std::string>                          notes;    ///< e.g. which solid was taken
    std::vector<std::string>                          warnings; ///< e.g. a poor mesh, and where
    std::map<dealii::types::boundary_id, std::string> face_names; ///< physical names of a .msh
    MeshQuality                                       quality;
    unsigned                                          n_solids = 1;
  };

  /// Reads a solid (above). Throws InputError naming the file when it cannot be read, does not
  /// enclose a volume, has an implausible size for its unit or would need more cells than
  /// @p settings allow. @p mesh_size [m]: the tetrahedra's size for CAD and STL files.
  SolidFileReport read_solid(const std::string &path, double mesh_size, dealii::Triangulation<3> &tria,
                             const SolidFileSettings &settings = {});

  /// Tetrahedra that fill the closed triangle surface of @p stl as it is (its triangles are not
  /// remeshed; the interior with tetrahedra of at most @p mesh_size). Boundary ids: Gmsh's
  /// surface number. Throws InputError when Gmsh cannot fill it.
  void read_closed_triangles(const std::string &stl, double mesh_size, dealii::Triangulation<3> &tria,
                             double time_limit = 0);

  /// The number of tetrahedra of size @p mesh_size that fill @p volume, about: a regular
  /// tetrahedron of edge h has the volume h^3 / (6 sqrt 2), and Gmsh's are a little smaller.
  double estimated_cells(double volume, double mesh_size);

  /// The rotation by @p degrees about @p axis (right-handed).
  dealii::Tensor<2, 3> rotation_matrix(const dealii::Tensor<1, 3> &axis, double degrees);

  /// The surfaces of a STEP/IGES CAD file (a grab shell, say: open or closed) as triangles of
  /// size @p mesh_size, meshed with Gmsh; only vertices and triangles are set. Throws
  /// InputError naming the file when it cannot be read or holds no surface.
  SolidSurface read_cad_surface(const std::string &path, double mesh_size);
  /// Writes the CAD model of @p input (a Gmsh script, .geo, with the OpenCASCADE kernel, or a
  /// STEP/BREP file) as STEP to @p step_file, its numbers as they are: a script drawn in
  /// millimetres gives a STEP in millimetres (the unit OpenCASCADE's writer declares). Throws
  /// InputError naming the file when Gmsh cannot read it or it holds no solid.
  void convert_to_step(const std::string &input, const std::string &step_file);
  /// Whether @p path names a CAD file by its extension (.step/.stp/.iges/.igs, any case).
  bool is_cad_file(const std::string &path);
} // namespace abrade::fem
