#include <abrade/common/error.h>
#include <abrade/fem/knife_model.h>
#include <abrade/fem/mesh_motion.h>

#include <filesystem>
#include <map>

namespace abrade::fem
{
  using namespace dealii;

  KnifeModel::KnifeModel(const KnifeGeometry &geometry, const Settings &s)
    : settings(s), tria(std::make_unique<Triangulation<3>>())
  {
    if (settings.work_directory.empty())
      settings.work_directory = (std::filesystem::temp_directory_path() / "abrade-knife").string();
    std::filesystem::create_directories(settings.work_directory);
    geometry.mesh(*tria, settings.mesh_size, settings.work_directory + "/knife.msh");
    current_surface   = extract_surface(*tria);
    accumulated.assign(current_surface.vertices.size(), 0.0);
    displacement.assign(3 * current_surface.vertices.size(), 0.0);
    since_remesh.assign(current_surface.vertices.size(), 0.0);
    quality_threshold = settings.remesh_quality * mesh_quality(*tria).min_scaled_jacobian;
  }

  double KnifeModel::volume() const { return mesh_volume(*tria); }

  KnifeModel::UpdateResult KnifeModel::apply_wear(const std::vector<double> &depth)
  {
    if (depth.size() != current_surface.vertices.size())
      throw std::logic_error("apply_wear: one depth per surface vertex expected");
    UpdateResult r;
    r.worn_through = worn_through(current_surface, depth);
    if (!r.worn_through.empty())
      {
        r.quality = mesh_quality(*tria);
        r.volume  = volume();
        return r; // end of life: reported, not carried into the mesh
      }

    // inward along the vertex normals, on the wearable surface only (clamped vertices stay)
    const auto                             normals = current_surface.vertex_normals();
    std::vector<bool>                      clamped(current_surface.vertices.size(), false);
    for (std::size_t t = 0; t < current_surface.triangles.size(); ++t)
      if (current_surface.boundary_id[t] != KnifeGeometry::wearable_boundary)
        for (unsigned v : current_surface.triangles[t])
          clamped[v] = true;
    std::map<unsigned, Tensor<1, 3>> prescribed;
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      prescribed[current_surface.tria_vertex[v]] = clamped[v] ? Tensor<1, 3>() : Tensor<1, 3>(-depth[v] * normals[v]);
    MeshMotion motion(*tria, {1, settings.stiffening, 1e-10});
    motion.solve(prescribed, {});
    move_vertices(*tria, motion.vertex_displacements());
    double moved_most = 0;
    for (std::size_t v = 0; v < accumulated.size(); ++v)
      {
        const Tensor<1, 3> d = prescribed[current_surface.tria_vertex[v]];
        accumulated[v] += clamped[v] ? 0.0 : depth[v];
        for (unsigned c = 0; c < 3; ++c)
          displacement[3 * v + c] += d[c];
        since_remesh[v] += d.norm();
        moved_most = std::max(moved_most, since_remesh[v]);
      }

    r.quality = mesh_quality(*tria);
    if (r.quality.n_inverted > 0 || r.quality.min_scaled_jacobian < quality_threshold ||
        moved_most > 0.5 * settings.mesh_size)
      {
        const SolidSurface old_surface = extract_surface(*tria);
        auto               fresh       = std::make_unique<Triangulation<3>>();
        remesh(*tria, settings.mesh_size, *fresh, settings.work_directory);
        tria = std::move(fresh);
        ++remeshes;
        r.remeshed = true;
        r.quality  = mesh_quality(*tria);
        current_surface = extract_surface(*tria);
        accumulated     = transfer_surface_field(old_surface, accumulated, current_surface);
        std::vector<double> moved(3 * current_surface.vertices.size());
        for (unsigned c = 0; c < 3; ++c)
          {
            std::vector<double> old_c(old_surface.vertices.size());
            for (std::size_t v = 0; v < old_c.size(); ++v)
              old_c[v] = displacement[3 * v + c];
            const auto new_c = transfer_surface_field(old_surface, old_c, current_surface);
            for (std::size_t v = 0; v < new_c.size(); ++v)
              moved[3 * v + c] = new_c[v];
          }
        displacement.swap(moved);
        since_remesh.assign(current_surface.vertices.size(), 0.0);
        if (r.quality.n_inverted > 0)
          throw RunError("the remeshed knife has inverted cells");
      }
    else
      current_surface = extract_surface(*tria);
    r.volume = volume();
    return r;
  }

  void KnifeModel::write(SolidOutput &output, double time) const
  {
    std::vector<double> depth(tria->n_vertices(), 0.0), moved(3 * tria->n_vertices(), 0.0);
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      {
        depth[current_surface.tria_vertex[v]] = accumulated[v];
        for (unsigned c = 0; c < 3; ++c)
          moved[3 * current_surface.tria_vertex[v] + c] = displacement[3 * v + c];
      }
    output.write(*tria, {{"scaled_jacobian", cell_scaled_jacobians(*tria)}}, time,
                 {{"wear_depth", 1, depth}, {"wear_displacement", 3, moved}});
  }
} // namespace abrade::fem
