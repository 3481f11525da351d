#pragma once
// The knife as the lifetime loop sees it: a tetrahedral solid whose wearable surface recedes by
// a wear depth per surface vertex at every update.
//
//   KnifeModel knife(geometry, settings);
//   const SolidSurface &s = knife.surface();          // the DEM's wall mesh
//   auto r = knife.apply_wear(depth_per_vertex);       // move, check, remesh if needed
//   if (!r.worn_through.empty()) ... end of life
//
// apply_wear moves each wearable surface vertex inward along its normal by its depth (the
// clamped face stays), carries the motion into the interior (MeshMotion), checks the quality and
// remeshes when it falls below a threshold (relative to the fresh mesh), or when the surface has
// moved more than half a mesh size since the last remesh (the mesh then no longer resolves the
// receding, rounding edge), carrying the accumulated depth and displacement over.
// A depth that reaches the local wall thickness is reported as worn through and not applied
// (only where the knife is at least half its plate thickness thick: near a sharp edge the local
// thickness vanishes and the receding edge is the mesh motion's and the remeshing's business).
#include <abrade/fem/knife_geometry.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/grid/tria.h>

#include <memory>
#include <string>
#include <vector>

namespace abrade::fem
{
  class KnifeModel
  {
  public:
    struct Settings
    {
      double      mesh_size      = 0.015; ///< [m]
      double      stiffening     = 1.0;   ///< mesh-motion cell-size stiffening exponent
      double      remesh_quality = 0.5;   ///< remesh below this fraction of the fresh mesh's quality
      double      density        = 7800;  ///< [kg/m^3]
      std::string work_directory;         ///< for Gmsh files
    };

    KnifeModel(const KnifeGeometry &geometry, const Settings &settings);

    struct UpdateResult
    {
      MeshQuality           quality;
      bool                  remeshed = false;
      std::vector<unsigned> worn_through; ///< surface vertices (of the surface before the update)
      double                volume = 0;
    };

    /// @p depth: this update's inward wear depth per vertex of surface() [m].
    UpdateResult apply_wear(const std::vector<double> &depth);

    const SolidSurface           &surface() const { return current_surface; }
    const std::vector<double>    &accumulated_depth() const { return accumulated; }
    const dealii::Triangulation<3> &triangulation() const { return *tria; }
    /// The accumulated wear depth of the surface points that were at @p points on the fresh
    /// knife (the surface moved back by its accumulated displacement, interpolated linearly).
    std::vector<double> recession_at(const std::vector<dealii::Point<3>> &points) const;
    double volume() const;
    double mass() const { return volume() * settings.density; }
    unsigned n_remeshes() const { return remeshes; }

    /// Writes the model's exact state (mesh, boundary ids, accumulated fields) to a binary file,
    /// and reads it back: a run resumed from it continues bit for bit.
    void save(const std::string &path) const;
    void load(const std::string &path);

    /// Appends the current state to a VTU series (fields: scaled Jacobian per cell, accumulated
    /// wear depth per vertex).
    void write(SolidOutput &output, double time) const;

  private:
    Settings                                  settings;
    std::unique_ptr<dealii::Triangulation<3>> tria;
    SolidSurface                              current_surface;
    std::vector<double>                       accumulated;
    std::vector<double>                       displacement;   ///< accumulated, 3 per surface vertex
    std::vector<double>                       since_remesh;   ///< |displacement| since the last remesh
    double                                    quality_threshold = 0;
    double                                    plate_thickness   = 0;
    unsigned                                  remeshes          = 0;
  };
} // namespace abrade::fem
