#pragma once
// The part as the lifetime loop sees it (the parametric knife, or a part from a file): a
// tetrahedral solid whose wearable surface recedes by a wear depth per surface vertex at every
// update.
//
//   PartModel part(geometry, settings);
//   const SolidSurface &s = part.surface();           // the DEM's wall mesh
//   auto r = part.apply_wear(depth_per_vertex);        // move, check, remesh if needed
//   if (!r.worn_through.empty()) ... end of life
//
// apply_wear moves each wearable surface vertex inward along its normal by its depth (the
// clamped face stays), carries the motion into the interior (MeshMotion), checks the quality and
// remeshes when it falls below a threshold (relative to the fresh mesh), or when the surface has
// moved more than half a mesh size since the last remesh (the mesh then no longer resolves the
// receding, rounding edge), carrying the accumulated depth and displacement over.
// Moved vertices cannot follow everywhere: where fronts meet (a chisel tip under wear that
// varies along its height) or a face shrinks away (the bevel of a thinning plate), triangles
// of the moved surface turn over, and the surface folds. Such an update (a triangle turned or
// squashed to 5 % of its area), and one whose moved surface Gmsh cannot remesh, is taken from
// the surface before it by eroded_surface.h, which solves "every point recedes along its normal
// by its depth" as a set and cannot fold; the part is meshed anew from that.
// The wear depth (wear_depth) is not that displacement: it is the distance of the worn surface
// below the design (the fresh part's surface), measured as `abrade compare` measures a scan
// (geometry::wear_depth, one definition for both). Where the offset faces meet at a chisel tip
// or a corner the vertex moves 2.9-3x as far as the surface lies below the design; the
// displacement stays available as vertex_displacement(), a diagnostic.
// A depth that reaches the local wall thickness is reported as worn through and not applied
// (only where the part is at least half its plate thickness thick: near a sharp edge the local
// thickness vanishes and the receding edge is the mesh motion's and the remeshing's business).
#include <abrade/common/surface_distance.h>
#include <abrade/common/timer.h>
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::fem
{
  class PartModel
  {
  public:
    struct Settings
    {
      double      mesh_size      = 0.015; ///< [m]
      double      stiffening     = 1.0;   ///< mesh-motion cell-size stiffening exponent
      double      remesh_quality = 0.5;   ///< remesh below this fraction of the fresh mesh's quality
      double      density        = 7800;  ///< [kg/m^3]
      std::string work_directory;         ///< for Gmsh files
      /// [m] Where the part is thinner than half of this (the region of a sharp edge, whose
      /// receding the mesh motion and remeshing follow), reaching the local thickness does not
      /// count as worn through. 0: the plate thickness of a parametric knife, or for any other
      /// part the area-weighted median of the local thickness of its wearable surface.
      double plate_thickness = 0;
      /// [m] The grid of the worn surface's construction where moved vertices would fold
      /// (eroded_surface.h); 0: the smaller of mesh_size / 6 and plate_thickness / 15.
      double erosion_spacing = 0;
    };

    /// The parametric knife, meshed with Gmsh.
    PartModel(const ParametricKnife &geometry, const Settings &settings);
    /// A part already meshed (a user's part, fem/solid_file.h): its boundary faces with id
    /// wearable_boundary wear, all others are held (clamped).
    PartModel(std::unique_ptr<dealii::Triangulation<3>> mesh, const Settings &settings);

    struct UpdateResult
    {
      MeshQuality           quality;
      bool                  remeshed = false;
      /// Gmsh could not mesh the worn surface the first way it tried: why, and the way that
      /// worked instead (a sentence for the log); empty otherwise.
      std::string           surface_kept;
      std::vector<unsigned> worn_through; ///< surface vertices (of the surface before the update)
      /// Why the worn surface was built anew from the surface before the update (moved
      /// vertices would have folded, or the moved surface could not be remeshed); empty when
      /// the vertices moved.
      std::string           rebuilt;
      /// Why the surface before the update was meshed anew before its vertices moved (they
      /// would have folded on the old mesh); empty when it was not.
      std::string           meshed_first;
      double                volume_cut_off = 0; ///< [m^3] pieces the wear separated from the part
      /// [m^3] What the remeshes of this update changed of the enclosed volume themselves (new
      /// minus old: Gmsh's new surface vertices lie on the old surface, so a rounded convex
      /// region loses the chords' sagitta); the update's swept volume includes it.
      double                remesh_volume_change = 0;
      /// apply_wear with a volume to remove: the factor on the depth by which the offset surface
      /// removes it (above 1 at convex edges); 1 otherwise.
      double                offset_scale = 1;
      /// [m^3] The part of remesh_volume_change of remeshes before the step, which the step's
      /// volume took into account (the rest came after the step: not compensated).
      double                remesh_volume_taken_off = 0;
      /// Why the volume given could not be removed exactly (a sentence for the log); empty
      /// otherwise.
      std::string           volume_note;
      double                volume = 0;
    };

    /// @p depth: this update's inward wear depth per vertex of surface() [m]. Where the moved
    /// vertices would fold, the surface is built anew as a set (eroded_surface.h) if
    /// @p may_rebuild, else RunError ("... would fold"): the moved vertices are exact wherever
    /// they do not fold, and a smaller step often does not (the lifetime loop halves the step
    /// twice before it lets the surface be built anew).
    /// @p volume > 0: the update removes this volume of material [m^3] (a wear source that
    /// gives volumes, as Archard's law does): the surface offset by @p depth removes less of it
    /// at convex edges (the offset faces cut each other short) and a remesh's chords cut some
    /// more: the depth is scaled as a whole so that the moved surface encloses @p volume less,
    /// and where the moved mesh would need remeshing the step is undone and taken on a mesh
    /// made anew first, the remesh's change of the volume taken off the step's (a fresh mesh
    /// keeps its first step until the next update; only inverted cells are remeshed after
    /// the step, uncompensated: UpdateResult::remesh_volume_change minus
    /// remesh_volume_taken_off). 0: @p depth is the depth itself (a known rate,
    /// verification).
    UpdateResult apply_wear(const std::vector<double> &depth, bool may_rebuild = true, double volume = 0);

    const SolidSurface           &surface() const { return current_surface; }
    /// The wear depth of every vertex of surface(): its distance inside the design surface [m].
    std::vector<double> wear_depth() const;
    /// How far each of @p points lies inside the design surface [m] (< 0: outside).
    std::vector<double> depth_below_design(const std::vector<dealii::Point<3>> &points) const;
    /// The wear depth below the design points @p points (points of the design surface): what a
    /// gauge there measures. The worn surface is laid onto the design at its vertices' closest
    /// design points and its depth interpolated there (as `abrade calibrate` looks it up).
    std::vector<double> wear_depth_below(const std::vector<dealii::Point<3>> &points) const;
    /// How far each vertex of surface() has moved inward since the fresh part, summed over the
    /// updates [m] (a diagnostic: at edges and corners 2.9-3x the wear depth).
    const std::vector<double>    &vertex_displacement() const { return accumulated; }
    const dealii::Triangulation<3> &triangulation() const { return *tria; }
    /// The design (fresh) surface.
    const SolidSurface &design_surface() const { return design; }
    /// A per-vertex @p field of surface() at the surface points that were at @p points on the
    /// fresh part (the surface moved back by its accumulated displacement, interpolated
    /// linearly): what happened to points followed through the part's life.
    std::vector<double> at_followed_points(const std::vector<double>                &field,
                                           const std::vector<dealii::Point<3>> &points) const;
    /// The recession of followed points: how far the surface point that was at each of
    /// @p points on the fresh part has moved (vertex displacement interpolated); at a chisel
    /// tip that is the tip's recession along its bisector.
    std::vector<double> recession_at(const std::vector<dealii::Point<3>> &points) const
    {
      return at_followed_points(accumulated, points);
    }
    double volume() const;
    /// The thickness that separates the edge region from the plate (Settings::plate_thickness).
    double thickness() const { return plate_thickness; }
    double mass() const { return volume() * settings.density; }
    unsigned n_remeshes() const { return remeshes; }

    /// Writes the model's exact state (mesh, boundary ids, accumulated fields) to a binary file,
    /// and reads it back: a run resumed from it continues bit for bit.
    void save(const std::string &path) const;
    void load(const std::string &path);

    /// Appends the current state to a VTU series (fields: scaled Jacobian per cell; per vertex
    /// the wear depth below the design, the vertex displacement's length and its vector).
    void write(SolidOutput &output, double time) const;

    /// [m] The grid spacing of the construction that cannot fold.
    double erosion_spacing() const;

    /// Seconds spent so far in each part of the model's work ("mesh motion", "remesh",
    /// "quality", "surface transfer", "surface as a set", "output"), for the run's profile.
    const io::Timers &timings() const { return timers; }

  private:
    /// The state an update starts from.
    struct Before
    {
      SolidSurface        surface;
      std::vector<double> depth, accumulated, displacement;
    };
    /// The worn surface as eroded_surface() builds it from @p before (it cannot fold), meshed
    /// anew; the followed points carried over. Throws RunError when Gmsh cannot mesh it.
    /// @p volume > 0: the depth scaled so that the set removes that much (as move_surface's).
    void rebuild_eroded(const Before &before, const std::string &why, UpdateResult &r, double volume = 0);
    /// The part meshed anew inside its current surface (Gmsh remeshes the surface, keeping
    /// the edges it classifies), the followed points carried over; @p r gets the quality and
    /// how it was meshed. Returns the transfer from the old surface to the new one (for fields
    /// given on the old one). Throws InputError, the part unchanged, when Gmsh cannot mesh it;
    /// RunError when the new mesh has inverted cells.
    SurfaceTransfer remesh_current(UpdateResult &r);
    /// The part meshed anew inside its current surface (@p from), then moved by @p depth
    /// (given on @p from) carried to the new vertices, the remesh's change of the volume part of
    /// @p volume; @p r says it was meshed first, and @p why. False, the part as it was, where
    /// Gmsh could not remesh it, or only filled its own triangles where @p new_vertices are
    /// needed (the step would fold on the old ones).
    bool remesh_then_move(const SolidSurface &from, const std::vector<double> &depth, bool may_rebuild, UpdateResult &r,
                          double volume, const std::string &why, bool new_vertices);
    /// Where an update moves the surface's vertices: inward as the offset surface moves, the
    /// wearable faces only (a vertex of clamped faces only stays; one on a clamped face's rim
    /// moves within the clamped plane).
    struct SurfaceMoves
    {
      std::vector<double>               depth;   ///< [m] per vertex, scaled with the moves
      std::vector<dealii::Tensor<1, 3>> offsets; ///< the offset surface's move of each vertex
      std::vector<dealii::Tensor<1, 3>> moves;   ///< the offsets, none where clamped
      std::vector<bool>                 clamped; ///< a vertex of clamped faces only
      /// The depth, 0 where clamped: what the surface wears.
      std::vector<double> wearing() const;
    };
    /// The moves of the current surface by @p depth (per vertex).
    SurfaceMoves surface_moves(const std::vector<double> &depth) const;
    /// @p m scaled as a whole so that the moved surface encloses @p volume less; @p r gets the
    /// factor, or a note where no factor between 0.05 and 2 does it (@p m as it was).
    void scale_to_volume(SurfaceMoves &m, double volume, UpdateResult &r) const;
    /// The mesh moved by @p m (the interior follows the surface: MeshMotion), the surface's
    /// accumulated recession and displacement updated; returns the largest move of a surface
    /// vertex since the last remesh.
    double move_mesh(const SurfaceMoves &m);
    /// After a step whose mesh needs remeshing (inverted or poor cells, or moved half a mesh
    /// size since the last remesh; @p moved_most): with a volume to remove, the step undone and
    /// taken on a fresh mesh (@p unmoved, @p since_before: the mesh and moves before it; not
    /// when the mesh was fresh already), else the moved surface meshed anew, or built as a set
    /// where Gmsh cannot mesh it (@p before); @p r gets the outcome and the volume.
    void remesh_after_step(const Before &before, const dealii::Triangulation<3> &unmoved,
                           const std::vector<double> &since_before, const std::vector<double> &given_depth,
                           double moved_most, bool may_rebuild, UpdateResult &r, double volume, bool may_mesh_first);
    /// apply_wear after its worn-through check: the vertices moved by @p depth, the part meshed
    /// anew first where they would fold on the mesh as it stands, built as a set where they
    /// fold on a fresh mesh too (if @p may_rebuild).
    /// @p volume > 0: the depth scaled so that the moved surface encloses that much less.
    /// @p may_mesh_first: whether a mesh that needs remeshing after the step may be meshed
    /// anew before it instead (a volume to remove).
    void move_surface(const std::vector<double> &depth, bool may_rebuild, UpdateResult &r, double volume = 0,
                      bool may_mesh_first = true);

    /// The design surface, the fields and the quality threshold of the fresh mesh.
    void start();

    Settings                                  settings;
    std::unique_ptr<dealii::Triangulation<3>> tria;
    SolidSurface                              current_surface;
    SolidSurface                              design;
    std::shared_ptr<const geometry::SurfaceDistance> design_distance;
    std::vector<double>                       accumulated;
    std::vector<double>                       displacement;   ///< accumulated, 3 per surface vertex
    std::vector<double>                       since_remesh;   ///< |displacement| since the last remesh
    double                                    quality_threshold = 0;
    double                                    plate_thickness   = 0;
    unsigned                                  remeshes          = 0;
    mutable io::Timers                        timers;
  };
} // namespace abrade::fem
