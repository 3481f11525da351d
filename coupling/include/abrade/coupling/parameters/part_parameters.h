#pragma once
// The part that wears as the parameter file describes it (subsection Part: the parametric knife,
// or a part from a file with its placement and faces), its mesh, and its surface placed as walls;
// shared by the knife and lifetime jobs.
#include <abrade/common/log.h>
#include <abrade/coupling/parameters/parameter_choices.h>
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/part_faces.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_surface.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::coupling
{
  /// Part/Bevel side.
  inline const Choices<fem::ParametricKnife::BevelSide> bevel_sides = {{"both", fem::ParametricKnife::BevelSide::both},
                                                                     {"plus", fem::ParametricKnife::BevelSide::plus},
                                                                     {"minus", fem::ParametricKnife::BevelSide::minus}};

  struct PartParameters
  {
    fem::ParametricKnife geometry;
    double             mesh_size = 0.015;
    double             density   = 7800;
    bool               from_file = false;
    std::string        file;
    fem::SolidFileSettings file_settings; ///< File scale, Maximum cells, Solid, placement
    std::vector<fem::FaceSelector> clamped_faces, wearable_faces;
  };

  /// Declares subsection Part: the parametric knife's shape, or a part from a file with its
  /// placement and faces, and the mesh.
  void declare_part_parameters(dealii::ParameterHandler &prm);
  /// Reads and checks subsection Part; errors name the file.
  PartParameters read_part_parameters(ParameterFile &file);
  /// Part/Length [m] alone: the walls that mount the part read it before it is meshed.
  double read_part_length(ParameterFile &file);

  /// The part's volume mesh as subsection Part describes it, with what was found on the way.
  struct PartMesh
  {
    std::unique_ptr<dealii::Triangulation<3>> tria;
    fem::SolidFileReport                      report;     ///< a part from a file: notes, warnings
    std::vector<fem::PartFace>                file_faces; ///< its faces as the file numbers them
    fem::FaceAssignment                       faces;      ///< which wear, which are clamped
  };

  /// Meshes the parametric knife (its Gmsh file written into @p directory) or reads the part
  /// from its file and chooses its wearable and clamped faces (boundary ids
  /// wearable_boundary and clamped_boundary). Errors name the parameter.
  PartMesh mesh_part(const PartParameters &part, ParameterFile &file, const std::string &directory);

  /// Writes what mesh_part found out about a part from a file (its solids, its faces, which
  /// wear, a poor mesh) to @p log, and its warnings also into @p warnings.
  void report_part_mesh(const PartParameters &part, const PartMesh &m, io::Log &log,
                         std::vector<std::string> *warnings = nullptr);

  /// @p surface as a wall mesh, every vertex p moved to @p linear p + @p offset.
  dem::TriangleMesh wall_mesh(const fem::SolidSurface &surface, const Eigen::Matrix3d &linear,
                              const dem::Vec3 &offset);
  /// The part's surface placed as wall @p wc's geometry (its rotation, then its offset).
  dem::TriangleMesh place_surface(const fem::SolidSurface &surface, const DemCase::WallCase &wc);

  /// A part from a file mounted on a shell: centred along the lip by its bounding box, its
  /// lowest point (the edge) 'Protrusion' beyond the lip (the parametric knife, x from 0
  /// to its length and its edge at z = 0, is placed so by construction). Across the lip (y) the
  /// part stays as placed: its y = 0 plane on the lip's line. Returns a warning when the part
  /// does not straddle y = 0 (empty otherwise).
  std::string fit_mounted_parts(DemCase &c, const fem::SolidSurface &design);

  /// Meshes the part of subsection Part (into @p directory) and gives every wall with
  /// Geometry = solid model its surface, placed.
  void fill_solid_model_walls(DemCase &c, ParameterFile &file, const std::string &directory, io::Log &log);
} // namespace abrade::coupling
