#pragma once
// The knife's solid model as the parameter file describes it (subsection Knife), shared by the
// knife and lifetime jobs.
#include <abrade/coupling/parameter_file.h>
#include <abrade/coupling/parameters.h>
#include <abrade/fem/knife_geometry.h>
#include <abrade/fem/solid_surface.h>

#include <string>

namespace abrade::coupling
{
  struct KnifeParameters
  {
    fem::KnifeGeometry geometry;
    double             mesh_size = 0.015;
    double             density   = 7800;
    bool               from_file = false;
    std::string        file;
    fem::SolidFileSettings file_settings; ///< File scale, Maximum cells
  };

  /// Reads and checks subsection Knife; errors name the file.
  KnifeParameters read_knife_parameters(ParameterFile &file);

  /// @p surface as a wall mesh, every vertex p moved to @p linear p + @p offset.
  dem::TriangleMesh wall_mesh(const fem::SolidSurface &surface, const Eigen::Matrix3d &linear,
                              const dem::Vec3 &offset);
  /// The knife's surface placed as wall @p wc's geometry (its rotation, then its offset).
  dem::TriangleMesh place_surface(const fem::SolidSurface &surface, const DemCase::WallCase &wc);

  /// Meshes the knife of subsection Knife (into @p directory) and gives every wall with
  /// Geometry = solid model its surface, placed.
  void fill_solid_model_walls(DemCase &c, ParameterFile &file, const std::string &directory);

  /// MPI (for PETSc) in this single process, initialised once.
  void init_mpi_once();
} // namespace abrade::coupling
