#pragma once
// Parametric grab knives, meshed with the Gmsh API (OpenCASCADE kernel) into tetrahedra and read
// into a deal.II triangulation.
//
// The knife is a cross-section in the y-z plane extruded along x by its length: a plate of
// thickness T and height H whose bottom edge is a bevel of height B, on both faces (a chisel, as
// the reference knife) or on one (the other face stays flat to the edge). Optional shape features
// from the thesis' concepts: a tip radius at the edge, and a lip (ridge) on the +y face above
// the bevel that holds back a protective layer of material. A changed edge angle is a changed
// B / T. Boundary ids (part_boundary.h): the wearable surface, and the clamped top face (bolted
// to the shell).
#include <abrade/fem/part_boundary.h>

#include <deal.II/grid/tria.h>

#include <string>
#include <utility>
#include <vector>

namespace abrade::fem
{
  struct ParametricKnife
  {
    double length    = 0.4;   ///< along x [m]
    double height    = 0.5;   ///< along z [m]
    double thickness = 0.03;  ///< along y [m]
    double bevel     = 0.04;  ///< height of the bevel [m]
    enum class BevelSide
    {
      both,  ///< chisel: the edge is in the middle of the thickness
      plus,  ///< bevel on the +y face; the -y face is flat to the edge
      minus  ///< bevel on the -y face
    } bevel_side = BevelSide::both;
    double tip_radius = 0;    ///< rounds the edge [m]; 0: sharp
    double lip_height = 0;    ///< ridge on the +y face [m], 0: none
    double lip_width  = 0;    ///< how far the ridge stands out of the face [m]
    double lip_offset = 0;    ///< ridge's distance above the bevel [m]

    /// The cross-section (y, z) as a closed polygon, counter-clockwise, the edge at the bottom
    /// (z = 0); without the tip rounding.
    std::vector<std::pair<double, double>> profile() const;
    /// Analytic volume of the polygon profile times the length (tip radius not included).
    double volume() const;
    /// Checks the parameters; throws InputError naming the bad one.
    void check() const;

    /// Meshes the knife with tetrahedra of size @p mesh_size [m] into @p tria. @p msh_file: the
    /// Gmsh file written on the way (kept for inspection).
    void mesh(dealii::Triangulation<3> &tria, double mesh_size, const std::string &msh_file) const;

    /// Writes the knife's CAD geometry (OpenCASCADE) as STEP in millimetres (the unit the file
    /// declares), for CAD tools or read_solid().
    void write_step(const std::string &step_file) const;

  private:
    /// Builds the OpenCASCADE model in the current Gmsh session; returns the volume's tag.
    int  build(const std::vector<std::pair<double, double>> &profile, double mesh_size) const;
    void build_and_mesh(const std::vector<std::pair<double, double>> &profile, double mesh_size,
                        const std::string &msh_file) const;
    /// Physical groups, tetrahedra, .msh for the model built by build().
    void mesh_built(int volume_tag, double mesh_size, const std::string &msh_file) const;
  };
} // namespace abrade::fem
