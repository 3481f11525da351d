#pragma once
// A triangle surface with shared (welded) vertices, so that neighbouring triangles know the
// edges and vertices they share: the sphere-triangle contact needs this to count a contact that
// touches two triangles once.
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <array>
#include <string>
#include <vector>

namespace abrade::dem
{
  using Vec3 = Eigen::Vector3d;

  struct TriangleMesh
  {
    std::vector<Vec3>               vertices;
    std::vector<std::array<int, 3>> triangles;

    std::size_t n_triangles() const { return triangles.size(); }
    Vec3        normal(std::size_t t) const;   ///< unit normal, right-hand rule
    double      area(std::size_t t) const;
    double      total_area() const;
    /// Signed enclosed volume (positive for a closed surface with outward normals).
    double      volume() const;
    void        bounding_box(Vec3 &lo, Vec3 &hi) const;
    /// Every edge shared by exactly two triangles (a closed, manifold surface).
    bool        is_closed() const;

    /// Merges vertices closer than @p tolerance (STL files store every triangle's corners).
    /// Drops degenerate triangles. Returns the number of vertices removed.
    std::size_t weld(double tolerance);

    /// Splits triangles (conforming: shared edges are split the same way on both sides) until
    /// no edge is longer than @p max_edge.
    void refine(double max_edge);

    void translate(const Vec3 &d);
    void append(const TriangleMesh &other);
    /// Reverses the orientation of every triangle.
    void flip();
  };

  /// Generated wall primitives.
  namespace primitives
  {
    /// An open-top box container (floor and four side walls) with inward normals.
    TriangleMesh box_container(const Vec3 &lo, const Vec3 &hi, bool with_top = false);
    /// A rectangle in the plane through @p centre with normal @p normal (one of x, y, z), of
    /// size a x b, split into triangles no larger than @p max_edge.
    TriangleMesh plate(const Vec3 &centre, int normal_axis, double size_a, double size_b,
                       double max_edge, bool flip = false);
    /// The knife-bed reference knife (shared/reference/cases.md): a plate parallel to XZ of
    /// length L (X), height H (Z), thickness T (Y), its bottom edge a chisel over height B; the
    /// origin is the middle of the bottom edge.
    TriangleMesh chisel_knife(double length, double height, double thickness, double bevel);
    /// One shell of a clamshell grab (shared/reference/cases.md), a thin surface: the hinge axis
    /// is the y axis through the origin; the shell is a cylindrical bottom of radius R about it,
    /// @p width along y, and two side plates (circular sectors from the hinge). Its lip (the
    /// knife's place) is at angle @p opening from straight down, towards +x for side +1, -x for
    /// side -1; the bottom spans @p sector radians beyond the lip, away from the other shell.
    /// Closed (opening 0), two mirrored shells meet under the hinge and hold a volume of
    /// sector R^2 width (both together).
    TriangleMesh clamshell_shell(double radius, double width, double sector, double opening, int side,
                                 double max_edge);
  } // namespace primitives
} // namespace abrade::dem
