#pragma once
// Which faces of a part wear and which are held.
//
// A part read from a file keeps the file's own face numbers as boundary ids: a CAD face's number
// (STEP/IGES, as Gmsh numbers the surfaces it imports), a physical surface's tag (.msh; its name
// too, when the file gives one), or a patch of an STL (split at edges sharper than 15 degrees).
// The user then says which faces are clamped (bolted or welded to the shell: the mesh motion
// holds them, no wear is applied there) and which wear, with selectors:
//
//   group NAME | group NUMBER            a physical group (by name or tag) or a CAD face (number);
//                                        a name the file gives wins over a number
//   box x0, y0, z0, x1, y1, z1           faces whose centre lies in the box [m, the part's frame]
//   normal nx, ny, nz [, angle]          faces whose outward normal is within angle (degrees,
//                                        default 10) of the direction
//   cylinder px, py, pz, ax, ay, az, r [, tolerance]
//                                        faces on the cylinder of radius r [m] about the axis
//                                        through p along a: the centre r from the axis within
//                                        the tolerance [m; default 0.15 r, which holds a facet's
//                                        chord 1.1 r long] and the normal across the axis (within
//                                        15 degrees); a bore or a pin whose CAD face is split in
//                                        halves, both ends of a pin through two lugs
//
// several separated by ';'. A face is clamped when a clamped selector takes it; otherwise it wears
// when a wearable selector takes it, or when no wearable selector is given (the default: every
// face that is not clamped wears). A face that neither list takes is held like a clamped one. A
// selector that takes no face is an error (a box in millimetres for a part in metres, say).
// Boxes and normals are evaluated per boundary face (a triangle of the mesh), after the part is
// scaled and placed: in the coordinates the part job writes part/part.stl in.
#include <abrade/fem/part_boundary.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace abrade::fem
{
  struct FaceSelector
  {
    enum class Kind
    {
      group,
      box,
      normal,
      cylinder
    } kind = Kind::group;
    std::string           group;                  ///< name or number
    std::array<double, 6> box{};                  ///< lower corner, upper corner; a cylinder: a point of its axis
    std::array<double, 3> direction{};            ///< unit (a cylinder's axis)
    double                radius = 0, tolerance = 0; ///< a cylinder's [m]
    double                angle_degrees = 10;
    std::string           text;                   ///< as written, for messages
  };

  /// Parses a ';'-separated list of selectors (empty: none); throws std::invalid_argument saying
  /// what is wrong with which one.
  std::vector<FaceSelector> parse_face_selectors(const std::string &text);

  /// A face of the part as the file numbers it: the boundary faces with one boundary id.
  struct PartFace
  {
    dealii::types::boundary_id id = 0;
    std::string                name;   ///< the physical group's name, when the file has one
    double                     area = 0;
    dealii::Point<3>           centre; ///< area-weighted
    dealii::Tensor<1, 3>       normal; ///< area-weighted mean outward normal (unit; zero if it cancels)
  };

  /// The faces of @p tria grouped by boundary id, with the names of @p names where given.
  std::vector<PartFace> part_faces(const dealii::Triangulation<3>                        &tria,
                                   const std::map<dealii::types::boundary_id, std::string> &names = {});

  struct FaceAssignment
  {
    double   wearable_area = 0, clamped_area = 0;
    unsigned wearable_faces = 0, clamped_faces = 0; ///< boundary faces (mesh faces)

    /// What became of one face of the file (its mesh faces may go different ways: a box or a
    /// normal selector is evaluated per mesh face).
    struct Role
    {
      double wearing_area = 0; ///< [m^2] wears
      double clamped_area = 0; ///< [m^2] taken by a Clamped faces selector
      double held_area    = 0; ///< [m^2] taken by neither list (held like a clamped face)
    };
    std::map<dealii::types::boundary_id, Role> by_face; ///< by the file's face number

    /// What one selector took: its area (a mesh face taken by two selectors counts for both)
    /// and the file's faces it took a part of.
    struct Taken
    {
      std::string                             list;     ///< "Clamped faces" or "Wearable faces"
      std::string                             selector; ///< as written
      double                                  area = 0; ///< [m^2]
      std::vector<dealii::types::boundary_id> faces;
    };
    std::vector<Taken> taken; ///< the clamped selectors in order, then the wearable ones

    /// Every boundary face of the mesh, in the order of the active cells and their faces: the
    /// file's face it belongs to and what became of it (the part's preview draws them).
    enum class Became : unsigned char
    {
      wears,
      clamped,
      held
    };
    std::vector<std::pair<dealii::types::boundary_id, Became>> boundary_faces;
  };

  /// Sets the boundary id of every boundary face of @p tria to @p wearable_id or @p clamped_id
  /// by the rules above. @p names: the file's names of its boundary ids. Throws
  /// std::invalid_argument naming a selector that takes no face, or when no face wears.
  FaceAssignment assign_faces(dealii::Triangulation<3> &tria, const std::vector<FaceSelector> &clamped,
                              const std::vector<FaceSelector>                         &wearable,
                              const std::map<dealii::types::boundary_id, std::string> &names,
                              dealii::types::boundary_id wearable_id, dealii::types::boundary_id clamped_id);
} // namespace abrade::fem
