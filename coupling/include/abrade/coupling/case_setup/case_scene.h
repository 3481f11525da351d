#pragma once
// The case around a part, for its preview (`abrade preview`, the part job): what a user needs
// to see before a run to trust the set-up. Where the case's walls with Geometry = solid model
// place the part (the case's frame, in which the DEM runs), the other walls' outlines, the
// particles' fill region (the bed box) and the domain, and the path the part's lowest point
// follows over one cycle of prescribed motion (each phase's velocity table for its duration;
// the free degrees of freedom of a rigid body are not drawn: they follow the particles).
#include <abrade/coupling/parameters/parameter_file.h>
#include <abrade/fem/solid_surface.h>

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace abrade::coupling
{
  struct CaseScene
  {
    /// false: the parameter file has no wall with Geometry = solid model (a part on its own)
    bool present = false;
    std::array<double, 6> domain{};     ///< Simulation/Domain min, max [m]
    std::array<double, 6> fill_region{}; ///< Particles/Generation/Region min, max [m]
    long                  particles = 0; ///< the fill's count (0: by its solid fraction)
    /// the part as wall @p wall places it: p -> rotation p + offset
    struct Placement
    {
      std::string     wall;
      Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
      Eigen::Vector3d offset   = Eigen::Vector3d::Zero();
    };
    std::vector<Placement> placements;
    /// another wall's outline: its feature edges (between triangles turned by more than 20
    /// degrees, and open edges) as segments x0 y0 z0 x1 y1 z1 [m]
    struct Outline
    {
      std::string                        wall;
      std::vector<std::array<double, 6>> segments;
    };
    std::vector<Outline> outlines;
    /// the part's lowest point (at the cycle's start) through one phase: its positions [m]
    struct Leg
    {
      std::string                        wall, phase;
      std::vector<std::array<double, 3>> points;
    };
    std::vector<Leg> path;
    std::vector<std::string> notes; ///< what is not drawn (free motion), in words
  };

  /// Reads the DEM case of @p file (walls, fill, domain, phases; errors as a run would give
  /// them) and places @p part (the part's surface, its own frame) as its walls do.
  CaseScene case_scene(ParameterFile &file, const fem::SolidSurface &part);

  /// The feature edges of a triangle mesh (vertices, triangles): edges between triangles whose
  /// normals differ by more than @p angle_degrees, and edges with one triangle.
  std::vector<std::array<double, 6>> feature_edges(const std::vector<Eigen::Vector3d> &vertices,
                                                   const std::vector<std::array<int, 3>> &triangles,
                                                   double angle_degrees = 20);
} // namespace abrade::coupling
