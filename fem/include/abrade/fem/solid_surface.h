#pragma once
// The part's boundary as a triangle surface, for the DEM and for export: outward-oriented
// triangles (a hexahedral face gives two), each mapped back to the cell face it lies on, and
// each surface vertex to its triangulation vertex. The map is stable while the mesh moves (it
// is rebuilt after a remesh), so per-triangle DEM fields come to the FEM boundary and back.
#include <abrade/common/vtk_output.h>

#include <deal.II/grid/tria.h>

#include <array>
#include <set>
#include <string>
#include <vector>

namespace abrade::fem
{
  struct SolidSurface
  {
    std::vector<dealii::Point<3>>       vertices;
    std::vector<std::array<unsigned, 3>> triangles;
    std::vector<unsigned>               tria_vertex;  ///< surface vertex -> triangulation vertex
    std::vector<std::pair<unsigned, unsigned>> face; ///< triangle -> (active cell index, face no)
    std::vector<dealii::types::boundary_id>    boundary_id; ///< per triangle

    double triangle_area(std::size_t t) const;
    double area() const;
    /// Outward unit normal of each surface vertex (area-weighted over its triangles).
    std::vector<dealii::Tensor<1, 3>> vertex_normals() const;
    /// The displacement that moves every vertex inward by its @p depth: the point that moves each
    /// of the vertex's triangle planes inward by the depth, in the least-squares sense
    /// (area-weighted). On a smooth surface this is depth times the inward normal; at a sharp
    /// edge or corner it is the intersection of the offset faces, so a chisel tip recedes by
    /// depth / sin(half angle) as the offset surface does, instead of by the depth alone (which
    /// leaves a growing spike). Directions the planes hardly constrain (eigenvalues below 1e-3 of
    /// the largest) are left out; the displacement is capped at 4 x depth.
    /// Triangles with @p held true do not wear: their planes stay (offset 0), so a vertex on the
    /// rim of a held face moves within its plane as the worn faces beside it recede (the inner
    /// parallel body of the worn faces, the held plane kept), and a vertex of held triangles
    /// only does not move.
    std::vector<dealii::Tensor<1, 3>> inward_offsets(const std::vector<double> &depth,
                                                     const std::vector<bool>   *held = nullptr) const;
    io::PolyData as_polydata() const;
  };

  /// The triangles of @p polydata as a surface (no mesh behind it: tria_vertex and face empty),
  /// every triangle with boundary id 0.
  SolidSurface surface_of(const io::PolyData &polydata);

  /// The volume the closed surface @p s encloses [m^3] (the divergence theorem over its
  /// triangles), with each vertex moved by @p scale times its @p moves if given.
  double enclosed_volume(const SolidSurface &s, const std::vector<dealii::Tensor<1, 3>> *moves = nullptr,
                         double scale = 0);

  /// Local wall thickness at every surface vertex: the distance along the inward normal to the
  /// surface on the other side (ray cast; infinity where the ray leaves through no triangle).
  std::vector<double> local_thickness(const SolidSurface &surface);

  /// The typical wall thickness of a part: the area-weighted median of local_thickness over the
  /// vertices of its faces with boundary id @p id (a plate's thickness, as its two large faces
  /// carry most of the area); 0 when no ray finds the other side.
  double typical_thickness(const SolidSurface &surface, dealii::types::boundary_id id = 1);

  /// Surface vertices whose inward wear depth reaches @p fraction of the local thickness: where
  /// the part is worn through, which ends its life (reported, never carried into the mesh).
  /// Vertices thinner than @p ignore_below (the region of a sharp edge, whose receding and
  /// rounding the mesh motion and remeshing follow) are not counted.
  std::vector<unsigned> worn_through(const SolidSurface &surface, const std::vector<double> &depth,
                                     double fraction = 1.0, double ignore_below = 0.0);

  /// Carries a per-vertex field (accumulated wear depth, say) from one surface to another (after
  /// a remesh): each new vertex takes the barycentric interpolation at its closest point on the
  /// old surface, which is exact for fields linear over each old triangle.
  std::vector<double> transfer_surface_field(const SolidSurface &from, const std::vector<double> &values,
                                             const SolidSurface &to);

  /// The same for many fields: each vertex of @p to found once on @p from (its closest point
  /// there, VTK's static cell locator), then any per-vertex field of @p from carried over.
  class SurfaceTransfer
  {
  public:
    SurfaceTransfer(const SolidSurface &from, const SolidSurface &to);
    /// Component @p component of a field with @p components values per vertex of from.
    std::vector<double> operator()(const std::vector<double> &values, unsigned components = 1,
                                   unsigned component = 0) const;
    /// The closest point on from of each vertex of to.
    const std::vector<dealii::Point<3>> &feet() const { return foot; }
    /// The triangle of from that holds the closest point of each vertex of to.
    const std::vector<unsigned> &triangles_of() const { return triangle; }

  private:
    struct Impl;
    std::vector<std::array<unsigned, 3>> triangles;
    std::vector<unsigned>                triangle;
    std::vector<std::array<double, 3>>   weight;
    std::vector<dealii::Point<3>>        foot;
  };

  /// The boundary faces with the given ids (all boundary faces when @p ids is empty).
  SolidSurface extract_surface(const dealii::Triangulation<3> &tria,
                               const std::set<dealii::types::boundary_id> &ids = {});

  /// Remeshing: a new tetrahedral mesh of size @p mesh_size that fills the current boundary of
  /// @p tria (through an STL of the surface and Gmsh); boundary ids of the new faces are taken
  /// from the nearest old boundary face. When Gmsh cannot remesh the surface, the volume is filled
  /// again inside the surface's own triangles: returns the reason then (empty: remeshed).
  /// A tetrahedral mesh of size @p mesh_size filling the closed, outward triangle surface
  /// @p surface (Gmsh, in its own process: fem/meshing_job.h): the surface remeshed, or where
  /// Gmsh cannot, the volume filled inside its own triangles (returns why the first way failed;
  /// empty: it worked). @p own_triangles_first: fill first, remesh where that fails. Boundary
  /// ids from the nearest triangle of @p ids_from. Throws InputError when neither works.
  std::string mesh_closed_surface(const io::PolyData &surface, double mesh_size, dealii::Triangulation<3> &new_tria,
                                  const std::string &work_directory, const SolidSurface &ids_from,
                                  bool own_triangles_first = false);

  std::string remesh(const dealii::Triangulation<3> &tria, double mesh_size, dealii::Triangulation<3> &new_tria,
                     const std::string &work_directory);

  /// The boundary ids of a worn part's new mesh @p tria, from its design (unworn) surface
  /// @p design: a boundary face whose corners all lie on the design (within @p tolerance) takes
  /// the id of the design triangle nearest its centre; every other face has worn and takes
  /// @p worn_id. Exact however often the part is remeshed: an unworn face keeps its design id (a
  /// clamped face, also where its rim moved within its plane; a curved one too, whose faces'
  /// centres lie off it by their sagitta), a worn one wears. (The nearest face of the surface
  /// before the update, which earlier remeshes used, is a clamped face for a worn
  /// face's centre nearer the rim than the wear is deep.) Returns the number of faces that keep
  /// an id other than @p worn_id.
  std::size_t set_ids_from_design(dealii::Triangulation<3> &tria, const SolidSurface &design, double tolerance,
                                  dealii::types::boundary_id worn_id);
} // namespace abrade::fem
