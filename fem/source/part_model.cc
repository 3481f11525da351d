// The part as the lifetime loop sees it: its surface receding by a wear depth per vertex, the
// mesh moved, checked and remeshed, checkpoints (part_model.h).
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/common/hash.h>
#include <abrade/common/temporary_directory.h>
#include <abrade/fem/part_model.h>
#include <abrade/fem/eroded_surface.h>
#include <abrade/fem/mesh_motion.h>
#include <abrade/fem/surface_filter.h>

#include <deal.II/grid/tria_description.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>

namespace abrade::fem
{
  using namespace dealii;

  PartModel::PartModel(const ParametricKnife &geometry, const Settings &s)
    : settings(s), tria(std::make_unique<Triangulation<3>>())
  {
    if (settings.work_directory.empty())
      settings.work_directory = io::private_temporary_directory();
    std::filesystem::create_directories(settings.work_directory);
    geometry.mesh(*tria, settings.mesh_size, settings.work_directory + "/part.msh");
    if (settings.plate_thickness <= 0)
      settings.plate_thickness = geometry.thickness;
    start();
  }

  PartModel::PartModel(std::unique_ptr<Triangulation<3>> mesh, const Settings &s)
    : settings(s), tria(std::move(mesh))
  {
    if (settings.work_directory.empty())
      settings.work_directory = io::private_temporary_directory();
    std::filesystem::create_directories(settings.work_directory);
    start();
  }

  void PartModel::start()
  {
    current_surface   = extract_surface(*tria);
    design            = current_surface;
    plate_thickness   = settings.plate_thickness > 0 ? settings.plate_thickness : typical_thickness(design);
    std::vector<double>                 points;
    std::vector<std::array<long, 3>>    triangles;
    for (const auto &p : design.vertices)
      points.insert(points.end(), {p[0], p[1], p[2]});
    for (const auto &t : design.triangles)
      triangles.push_back({long(t[0]), long(t[1]), long(t[2])});
    design_distance = std::make_shared<const geometry::SurfaceDistance>(points, triangles);
    accumulated.assign(current_surface.vertices.size(), 0.0);
    displacement.assign(3 * current_surface.vertices.size(), 0.0);
    since_remesh.assign(current_surface.vertices.size(), 0.0);
    quality_threshold = settings.remesh_quality * mesh_quality(*tria).min_scaled_jacobian;
  }

  double PartModel::volume() const { return mesh_volume(*tria); }

  namespace
  {
    /// mesh_quality and SurfaceTransfer, their time added to @p timers.
    MeshQuality timed_quality(io::Timers &timers, const Triangulation<3> &tria)
    {
      io::ScopedTimer t(timers, "quality");
      return mesh_quality(tria);
    }
    SurfaceTransfer timed_transfer(io::Timers &timers, const SolidSurface &from, const SolidSurface &to)
    {
      io::ScopedTimer t(timers, "surface transfer");
      return SurfaceTransfer(from, to);
    }

    /// The triangles of @p s that the vertex @p offsets turn over (their normal against the one
    /// they had) or squash to nothing: where fronts meet or a face shrinks away, which moved
    /// vertices cannot follow.
    std::size_t folding_triangles(const SolidSurface &s, const std::vector<Tensor<1, 3>> &offsets)
    {
      std::size_t folds = 0;
      for (const auto &t : s.triangles)
        {
          const Tensor<1, 3> n0 = cross_product_3d(s.vertices[t[1]] - s.vertices[t[0]], s.vertices[t[2]] - s.vertices[t[0]]);
          const Point<3>     a = s.vertices[t[0]] + offsets[t[0]], b = s.vertices[t[1]] + offsets[t[1]],
                         c = s.vertices[t[2]] + offsets[t[2]];
          const Tensor<1, 3> n1 = cross_product_3d(b - a, c - a);
          if (n1 * n0 <= 0.05 * n0.norm_square())
            ++folds;
        }
      return folds;
    }

    /// The factor on vertex @p moves of surface @p s by which the enclosed volume falls by
    /// @p volume (a cubic in it: secant iterations from 1); 0 where none is found between 0.05
    /// and 2 (the offset's own volume is within a few % of depth x area on a surface it does
    /// not fold; a factor well below 1 is the rest of an update whose remesh before the step
    /// took most of its volume: 0.6 of it at a rounded chisel tip).
    double offset_scale_for_volume(const SolidSurface &s, const std::vector<Tensor<1, 3>> &moves, double volume)
    {
      const double v0   = enclosed_volume(s);
      auto         miss = [&](double x) { return v0 - enclosed_volume(s, &moves, x) - volume; };
      double       x0 = 1, x1 = 1.01, f0 = miss(x0), f1 = miss(x1);
      for (int k = 0; k < 30 && std::abs(f1) > 1e-10 * volume && f1 != f0; ++k)
        {
          const double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
          x0 = x1, f0 = f1, x1 = x2, f1 = miss(x1);
        }
      return std::isfinite(x1) && x1 > 0.05 && x1 < 2 && std::abs(f1) <= 1e-6 * volume ? x1 : 0.0;
    }

    /// A field of 3-vectors per vertex of a transfer's old surface, carried to its new one.
    std::vector<double> transferred_vectors(const SurfaceTransfer &transfer, const std::vector<double> &field)
    {
      std::vector<double> carried(3 * transfer.feet().size());
      for (unsigned c = 0; c < 3; ++c)
        {
          const auto component = transfer(field, 3, c);
          for (std::size_t v = 0; v < component.size(); ++v)
            carried[3 * v + c] = component[v];
        }
      return carried;
    }

    /// The depth of an update given on the vertices of @p from, carried to those of @p to (the
    /// same surface meshed anew): interpolated at each new vertex's closest point, then scaled so
    /// that the depth over the wearable area, the update's Archard volume, is the one given
    /// (interpolation flattens a sharply varying field's peaks).
    std::vector<double> carried_depth(const SurfaceTransfer &transfer, const SolidSurface &from, const SolidSurface &to,
                                      const std::vector<double> &depth)
    {
      std::vector<double> carried = transfer(depth);
      const auto          a_from = vertex_areas(from, wearable_boundary);
      const auto          a_to   = vertex_areas(to, wearable_boundary);
      double              given = 0, now = 0;
      for (std::size_t v = 0; v < depth.size(); ++v)
        given += a_from[v] * depth[v];
      for (std::size_t v = 0; v < carried.size(); ++v)
        now += a_to[v] * carried[v];
      if (now > 0)
        for (double &d : carried)
          d *= given / now;
      return carried;
    }
  } // namespace

  PartModel::UpdateResult PartModel::apply_wear(const std::vector<double> &depth, bool may_rebuild, double volume)
  {
    if (depth.size() != current_surface.vertices.size())
      throw std::logic_error("apply_wear: one depth per surface vertex expected");
    UpdateResult r;
    // through the plate, not the receding edge: regions thinner than half the plate do not count
    r.worn_through = worn_through(current_surface, depth, 1.0, 0.5 * plate_thickness);
    if (!r.worn_through.empty())
      {
        r.quality = timed_quality(timers, *tria);
        r.volume  = PartModel::volume();
        return r; // end of life: reported, not carried into the mesh
      }
    move_surface(depth, may_rebuild, r, volume);
    return r;
  }

  PartModel::SurfaceMoves PartModel::surface_moves(const std::vector<double> &depth) const
  {
    // inward, as the offset surface moves (SolidSurface::inward_offsets), the wearable faces
    // only: a vertex of clamped faces only stays, one on a clamped face's rim moves within the
    // clamped plane as the worn faces beside it recede (held still, the rim took 1.6 % of a
    // uniform update's volume from the 30 mm knife)
    std::vector<bool> held(current_surface.triangles.size(), false);
    std::vector<int>  wearing_triangles(current_surface.vertices.size(), 0);
    for (std::size_t t = 0; t < current_surface.triangles.size(); ++t)
      {
        held[t] = current_surface.boundary_id[t] != wearable_boundary;
        for (unsigned v : current_surface.triangles[t])
          wearing_triangles[v] += held[t] ? 0 : 1;
      }
    SurfaceMoves m;
    m.depth   = depth;
    m.offsets = current_surface.inward_offsets(depth, &held);
    m.clamped.assign(current_surface.vertices.size(), false);
    for (std::size_t v = 0; v < m.clamped.size(); ++v)
      m.clamped[v] = wearing_triangles[v] == 0;
    // what the update starts from, for the construction that cannot fold (rebuild_eroded; a rim
    // point's ball cuts the clamped face's rim as the faces beside it recede, and nothing below
    // the clamped plane that the faces' own balls do not)
    m.moves.resize(m.offsets.size());
    for (std::size_t v = 0; v < m.offsets.size(); ++v)
      m.moves[v] = m.clamped[v] ? Tensor<1, 3>() : m.offsets[v];
    return m;
  }

  std::vector<double> PartModel::SurfaceMoves::wearing() const
  {
    std::vector<double> w = depth;
    for (std::size_t v = 0; v < clamped.size(); ++v)
      if (clamped[v])
        w[v] = 0;
    return w;
  }

  void PartModel::scale_to_volume(SurfaceMoves &m, double volume, UpdateResult &r) const
  {
    // The offset surface removes less than depth x area where the worn area shrinks as it
    // recedes, at convex edges (0.985 of it on the 30 mm reference knife at 2 mm steps, 0.970 at
    // 4 mm: first order in the step). The offsets are linear in the depth: the update's depth,
    // scaled as a whole, removes the volume given (the volume rate the update began with held
    // over it, where the depth alone holds the depth rate; one factor, so the wear stays
    // distributed as deposited and planes stay planes).
    const double scale = offset_scale_for_volume(current_surface, m.moves, volume);
    if (scale > 0)
      {
        for (std::size_t v = 0; v < m.moves.size(); ++v)
          m.moves[v] *= scale, m.offsets[v] *= scale, m.depth[v] *= scale;
        r.offset_scale = scale;
      }
    else
      r.volume_note = "no factor between 0.05 and 2 on the depth removes the volume worn: the depth as it is";
  }

  double PartModel::move_mesh(const SurfaceMoves &m)
  {
    std::map<unsigned, Tensor<1, 3>> prescribed;
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      prescribed[current_surface.tria_vertex[v]] = m.moves[v];
    {
      // (its DoF handler holds on to the triangulation: gone before the step may be undone)
      io::ScopedTimer t(timers, "mesh motion");
      MeshMotion motion(*tria, {1, settings.stiffening, 1e-10});
      motion.solve(prescribed, {});
      move_vertices(*tria, motion.vertex_displacements());
    }
    double moved_most = 0;
    for (std::size_t v = 0; v < accumulated.size(); ++v)
      {
        const Tensor<1, 3> d = prescribed[current_surface.tria_vertex[v]];
        accumulated[v] += m.clamped[v] ? 0.0 : m.offsets[v].norm(); // how far the surface receded here
        for (unsigned c = 0; c < 3; ++c)
          displacement[3 * v + c] += d[c];
        since_remesh[v] += d.norm();
        moved_most = std::max(moved_most, since_remesh[v]);
      }
    return moved_most;
  }

  void PartModel::move_surface(const std::vector<double> &given_depth, bool may_rebuild, UpdateResult &r, double volume,
                                bool may_mesh_first)
  {
    SurfaceMoves m = surface_moves(given_depth);
    // A volume to remove (Archard's): the depth scaled so that the moved surface removes it
    // (scale_to_volume). Not where the moves fold (the enclosed volume of a folded surface
    // counts its turned loops negative): the fresh mesh below scales its own step, the
    // set-based rebuild takes the depth as it is.
    const std::size_t folds = folding_triangles(current_surface, m.moves);
    if (volume > 0 && folds == 0)
      scale_to_volume(m, volume, r);
    const Before before{current_surface, m.wearing(), accumulated, displacement};
    // (unscaled where they fold already; the scaled moves checked too)
    if (const std::size_t folding = folds > 0 ? folds : folding_triangles(current_surface, m.moves); folding > 0)
      {
        const std::string why = std::to_string(folding) + " triangle(s) of the moved surface would fold";
        // Most folds are vertices the receding fronts overtake: a vertex of the bevel near a
        // chisel tip, which shrinks the bevel by 2.67 times the depth. The surface meshed anew
        // before the step has its vertices a triangle's height from its edges again, and its
        // planes and edges exactly (Gmsh keeps the edges it classifies); the step is tried
        // once more from there, its depth carried to the new vertices.
        if (*std::max_element(since_remesh.begin(), since_remesh.end()) > 0 &&
            remesh_then_move(before.surface, given_depth, may_rebuild, r, volume, why + " on the old mesh", true))
          return;
        if (!may_rebuild)
          throw RunError(why);
        rebuild_eroded(before, why, r, volume);
        return;
      }

    // (a volume to remove: the mesh before the step, in case the moved one must be remeshed)
    Triangulation<3>          unmoved;
    const std::vector<double> since_before = since_remesh;
    if (volume > 0)
      unmoved.copy_triangulation(*tria);
    const double moved_most = move_mesh(m);

    r.quality = timed_quality(timers, *tria);
    if (r.quality.n_inverted > 0 || r.quality.min_scaled_jacobian < quality_threshold ||
        moved_most > 0.5 * settings.mesh_size)
      remesh_after_step(before, unmoved, since_before, given_depth, moved_most, may_rebuild, r, volume, may_mesh_first);
    else
      {
        current_surface = extract_surface(*tria);
        r.volume        = PartModel::volume();
      }
  }

  void PartModel::remesh_after_step(const Before &before, const Triangulation<3> &unmoved,
                                    const std::vector<double> &since_before, const std::vector<double> &given_depth,
                                    double moved_most, bool may_rebuild, UpdateResult &r, double volume,
                                    bool may_mesh_first)
  {
    // A remesh after the step would change the volume the update removed (Gmsh's chords
    // across a rounded region cut up to 3.5 % of a DEM update's volume): with a volume to
    // remove, the step is undone, the part meshed anew first and the step taken on the
    // fresh mesh, the remesh's change part of the volume (not again if that mesh, too,
    // needs a remesh after its step).
    const bool fresh = *std::max_element(since_before.begin(), since_before.end()) == 0;
    if (volume > 0 && fresh && r.quality.n_inverted == 0)
      {
        // a fresh mesh that needs remeshing after one step: meshing it anew before the step
        // would not help; it is meshed anew before the next update's step instead (its
        // change of the volume then taken off that step), unless its cells turned inside out
        current_surface = extract_surface(*tria);
        r.volume        = PartModel::volume();
        return;
      }
    if (volume > 0 && may_mesh_first && !fresh)
      {
        auto undo = [&] {
          tria->clear();
          tria->copy_triangulation(unmoved);
          current_surface = before.surface;
          accumulated     = before.accumulated;
          displacement    = before.displacement;
          since_remesh    = since_before;
        };
        undo();
        std::ostringstream why;
        why << "after the step its mesh would need remeshing (moved " << io::format_number(1e3 * moved_most)
            << " mm since the last remesh, minimum scaled Jacobian "
            << io::format_number(r.quality.min_scaled_jacobian) << ")";
        if (remesh_then_move(before.surface, given_depth, may_rebuild, r, volume, why.str(), false))
          return;
        // Gmsh could not: the step on the old mesh again, remeshed after it
        undo();
        move_surface(given_depth, may_rebuild, r, volume, false);
        return;
      }
    try
      {
        remesh_current(r);
      }
    catch (const InputError &e)
      {
        // Gmsh can mesh neither the moved surface nor inside its triangles: from the
        // surface before the update, built so that it cannot fold
        rebuild_eroded(before, std::string("the moved surface could not be remeshed (") + e.what() + ")", r,
                       volume);
        return;
      }
    r.volume = PartModel::volume();
  }

  bool PartModel::remesh_then_move(const SolidSurface &from, const std::vector<double> &depth, bool may_rebuild,
                                    UpdateResult &r, double volume, const std::string &why, bool new_vertices)
  {
    UpdateResult                   first;
    std::optional<SurfaceTransfer> transfer;
    try
      {
        transfer.emplace(remesh_current(first));
      }
    catch (const InputError &)
      {
        return false; // Gmsh could not mesh it: the part is as it was
      }
    // where Gmsh only filled the surface's own triangles, the vertices are the old ones: they
    // would fold the same way (the caller goes on another way); a step that needed only a fresh
    // interior takes it (the surface unchanged, so is its volume)
    if (!first.surface_kept.empty() && new_vertices)
      return false;
    if (!first.surface_kept.empty())
      r.surface_kept = first.surface_kept;
    // (the remesh's own change of the volume is part of the update's)
    const double rest = volume > 0 ? volume + first.remesh_volume_change : 0.0;
    if (volume > 0 && !(rest > 0))
      r.volume_note = "the remesh before the step took more than the volume worn: the depth as it is";
    move_surface(carried_depth(*transfer, from, current_surface, depth), may_rebuild, r, rest > 0 ? rest : 0.0);
    r.remeshed     = true;
    r.meshed_first = why;
    r.remesh_volume_change += first.remesh_volume_change;
    if (rest > 0)
      r.remesh_volume_taken_off += first.remesh_volume_change;
    return true;
  }

  SurfaceTransfer PartModel::remesh_current(UpdateResult &r)
  {
    const SolidSurface old_surface = extract_surface(*tria);
    const double       old_volume  = volume();
    auto               fresh       = std::make_unique<Triangulation<3>>();
    {
      io::ScopedTimer t(timers, "remesh");
      if (const std::string failed = remesh(*tria, settings.mesh_size, *fresh, settings.work_directory); !failed.empty())
        r.surface_kept = failed + "; the part was meshed again inside its worn surface's own triangles";
    }
    set_ids_from_design(*fresh, design, 1e-3 * settings.mesh_size, wearable_boundary);
    tria = std::move(fresh);
    ++remeshes;
    r.remeshed      = true;
    current_surface = extract_surface(*tria);
    SurfaceTransfer transfer = timed_transfer(timers, old_surface, current_surface);
    // the new surface's vertices lie on the old surface but went to Gmsh through a binary STL,
    // in single precision (up to 1.5e-8 m at 0.4 m): each is put back on the old surface, at its
    // closest point there in double precision
    std::vector<Tensor<1, 3>> onto(tria->n_vertices());
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      if (const Tensor<1, 3> d = transfer.feet()[v] - current_surface.vertices[v];
          d.norm() < 1e-5 * settings.mesh_size)
        {
          onto[current_surface.tria_vertex[v]] = d;
          current_surface.vertices[v]          = transfer.feet()[v];
        }
    move_vertices(*tria, onto);
    r.quality = timed_quality(timers, *tria);
    r.remesh_volume_change += volume() - old_volume;
    accumulated  = transfer(accumulated);
    displacement = transferred_vectors(transfer, displacement);
    since_remesh.assign(current_surface.vertices.size(), 0.0);
    if (r.quality.n_inverted > 0)
      throw RunError("the remeshed part has inverted cells");
    return transfer;
  }

  double PartModel::erosion_spacing() const
  {
    return settings.erosion_spacing > 0 ? settings.erosion_spacing
                                        : std::min(settings.mesh_size / 6, plate_thickness / 15);
  }

  void PartModel::rebuild_eroded(const Before &before, const std::string &why, UpdateResult &r, double volume)
  {
    const io::PolyData start = before.surface.as_polydata();
    auto               build = [&](double scale) {
      std::vector<double> depth = before.depth;
      for (double &d : depth)
        d *= scale;
      io::ScopedTimer t(timers, "surface as a set");
      return eroded_surface(start, depth, erosion_spacing(), settings.mesh_size / 3, &timers);
    };
    ErodedSurface eroded = build(1);
    // A volume to remove: the depth scaled as a whole until the set removes it (to 0.5 %), as
    // the moved vertices' step is scaled; the set's own error (edges cut by up to half a grid
    // spacing) is then part of the factor. Secant iterations from the proportional guess, each
    // a construction of the set (seconds).
    if (volume > 0)
      {
        const double v0      = enclosed_volume(before.surface);
        auto         miss    = [&](const ErodedSurface &e) { return v0 - e.volume - volume; };
        double       x0      = 1, f0 = miss(eroded);
        const double removed = f0 + volume;
        double       x1      = removed > 0 ? volume / removed : 1;
        ErodedSurface best   = eroded;
        double        best_x = x0, best_f = f0;
        for (int k = 0; k < 4 && std::abs(best_f) > 5e-3 * volume && x1 > 0.05 && x1 < 2 && x1 != x0; ++k)
          {
            ErodedSurface e  = build(x1);
            const double  f1 = miss(e);
            if (std::abs(f1) < std::abs(best_f))
              best = e, best_x = x1, best_f = f1;
            const double x2 = f1 != f0 ? x1 - f1 * (x1 - x0) / (f1 - f0) : x1;
            x0 = x1, f0 = f1, x1 = x2;
          }
        eroded = std::move(best);
        r.offset_scale *= best_x;
        if (std::abs(best_f) > 5e-3 * volume)
          r.volume_note = "the surface built anew removes " + io::format_number((best_f + volume) / volume) +
                          " times the volume worn (no factor on the depth between 0.05 and 2 removes it)";
      }
    auto fresh = std::make_unique<Triangulation<3>>();
    try
      {
        // its own triangles lie on the front exactly; Gmsh's remeshing of them would cut its
        // sharp edges (0.7 mm on the 30 mm chisel after 10 mm of wear)
        io::ScopedTimer   t(timers, "remesh");
        const std::string failed = mesh_closed_surface(eroded.surface, settings.mesh_size, *fresh,
                                                       settings.work_directory, before.surface, true);
        if (!failed.empty())
          r.surface_kept = "the worn surface's own triangles could not be filled (" + failed + "): remeshed instead";
      }
    catch (const InputError &e)
      {
        throw RunError(std::string("the worn part could not be meshed: ") + e.what());
      }
    set_ids_from_design(*fresh, design, 1e-3 * settings.mesh_size, wearable_boundary);
    r.quality = timed_quality(timers, *fresh);
    if (r.quality.n_inverted > 0)
      throw RunError("the remeshed part has inverted cells");
    tria = std::move(fresh);
    ++remeshes;
    r.remeshed        = true;
    r.rebuilt         = why;
    r.volume_cut_off  = eroded.volume_cut_off;
    current_surface   = extract_surface(*tria);
    // followed points: each new vertex continues the point of the surface before the update
    // closest to it (its fields there), moved on by the step between them
    const SurfaceTransfer transfer = timed_transfer(timers, before.surface, current_surface);
    accumulated = transfer(before.accumulated);
    displacement = transferred_vectors(transfer, before.displacement);
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      {
        const Tensor<1, 3> step = current_surface.vertices[v] - transfer.feet()[v];
        accumulated[v] += step.norm();
        for (unsigned c = 0; c < 3; ++c)
          displacement[3 * v + c] += step[c];
      }
    since_remesh.assign(current_surface.vertices.size(), 0.0);
    r.volume = PartModel::volume();
  }

  std::vector<double> PartModel::wear_depth() const
  {
    std::vector<double> points;
    points.reserve(3 * current_surface.vertices.size());
    for (const auto &p : current_surface.vertices)
      points.insert(points.end(), {p[0], p[1], p[2]});
    return geometry::wear_depth(*design_distance, points);
  }

  std::vector<double> PartModel::depth_below_design(const std::vector<Point<3>> &points) const
  {
    std::vector<double> flat;
    for (const auto &p : points)
      flat.insert(flat.end(), {p[0], p[1], p[2]});
    return geometry::wear_depth(*design_distance, flat);
  }

  std::vector<double> PartModel::wear_depth_below(const std::vector<Point<3>> &points) const
  {
    std::vector<double> worn, feet;
    for (const auto &p : current_surface.vertices)
      worn.insert(worn.end(), {p[0], p[1], p[2]});
    const std::vector<double> depth = geometry::wear_depth(*design_distance, worn, &feet);
    SolidSurface              laid  = current_surface;
    for (std::size_t v = 0; v < laid.vertices.size(); ++v)
      laid.vertices[v] = Point<3>(feet[3 * v], feet[3 * v + 1], feet[3 * v + 2]);
    SolidSurface at;
    at.vertices = points;
    return transfer_surface_field(laid, depth, at);
  }

  std::vector<double> PartModel::at_followed_points(const std::vector<double> &field,
                                                     const std::vector<Point<3>> &points) const
  {
    if (field.size() != current_surface.vertices.size())
      throw std::logic_error("at_followed_points: one value per surface vertex expected");
    SolidSurface fresh = current_surface;
    for (std::size_t v = 0; v < fresh.vertices.size(); ++v)
      for (unsigned c = 0; c < 3; ++c)
        fresh.vertices[v][c] -= displacement[3 * v + c];
    SolidSurface at;
    at.vertices = points;
    return transfer_surface_field(fresh, field, at);
  }

  namespace
  {
    // A knife checkpoint: this line, the blocks (each its length, then its values), and the
    // FNV-1a hash of all before it (16 hex digits): a changed byte is named, never read as a mesh.
    const std::string checkpoint_magic = "abrade knife checkpoint 2\n";

    template <typename T>
    void put(std::ostream &out, const std::vector<T> &v)
    {
      const std::uint64_t n = v.size();
      out.write(reinterpret_cast<const char *>(&n), sizeof n);
      out.write(reinterpret_cast<const char *>(v.data()), n * sizeof(T));
    }
    template <typename T>
    std::vector<T> get(std::istream &in, std::size_t bytes_left, const std::string &path)
    {
      std::uint64_t n = 0;
      in.read(reinterpret_cast<char *>(&n), sizeof n);
      if (!in || n > bytes_left / sizeof(T))
        throw InputError(path, "corrupt knife checkpoint (a block longer than the file)");
      std::vector<T> v(n);
      in.read(reinterpret_cast<char *>(v.data()), n * sizeof(T));
      if (!in)
        throw InputError(path, "truncated knife checkpoint");
      return v;
    }
  } // namespace

  void PartModel::save(const std::string &path) const
  {
    std::vector<double>   vertices;
    std::vector<unsigned> cells, faces;
    for (const auto &p : tria->get_vertices())
      vertices.insert(vertices.end(), {p[0], p[1], p[2]});
    for (const auto &cell : tria->active_cell_iterators())
      {
        if (!cell->reference_cell().is_simplex())
          throw std::logic_error("knife checkpoints hold tetrahedral meshes");
        for (const unsigned v : cell->vertex_indices())
          cells.push_back(cell->vertex_index(v));
        for (const unsigned f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            faces.insert(faces.end(), {cell->face(f)->vertex_index(0), cell->face(f)->vertex_index(1),
                                       cell->face(f)->vertex_index(2), unsigned(cell->face(f)->boundary_id())});
      }
    const std::vector<double> state = {quality_threshold, double(remeshes)};
    std::ostringstream        blocks(std::ios::binary);
    blocks << checkpoint_magic;
    put(blocks, vertices), put(blocks, cells), put(blocks, faces), put(blocks, accumulated), put(blocks, displacement),
      put(blocks, since_remesh), put(blocks, state);
    const std::string content = blocks.str();
    std::ofstream     out(path, std::ios::binary);
    out << content << io::fnv1a_hex(content);
    out.close();
    if (!out)
      throw RunError("cannot write " + path);
  }

  void PartModel::load(const std::string &path)
  {
    std::ifstream file(path, std::ios::binary);
    if (!file)
      throw InputError(path, "cannot open knife checkpoint");
    std::ostringstream whole;
    whole << file.rdbuf();
    const std::string text = whole.str();
    if (text.rfind(checkpoint_magic, 0) != 0)
      throw InputError(path, "not a knife checkpoint of this version of abrade (start afresh without --resume)");
    if (text.size() < checkpoint_magic.size() + 16 ||
        io::fnv1a_hex(text.substr(0, text.size() - 16)) != text.substr(text.size() - 16))
      throw InputError(path, "corrupt knife checkpoint (its checksum does not match: changed or cut; start afresh "
                             "without --resume, or remove this update's checkpoint files to resume from the one before)");
    std::istringstream in(text.substr(checkpoint_magic.size(), text.size() - 16 - checkpoint_magic.size()),
                          std::ios::binary);
    const std::size_t  size = text.size();
    const auto v = get<double>(in, size, path);
    const auto c = get<unsigned>(in, size, path);
    const auto f = get<unsigned>(in, size, path);
    auto       acc = get<double>(in, size, path), disp = get<double>(in, size, path), since = get<double>(in, size, path);
    const auto state = get<double>(in, size, path);
    // what a checksum cannot catch (a file written by other code): the blocks' shapes and ranges
    const std::size_t n_points = v.size() / 3;
    bool              sane     = v.size() % 3 == 0 && c.size() % 4 == 0 && f.size() % 4 == 0 && state.size() >= 2 &&
                    disp.size() == 3 * acc.size() && since.size() == acc.size();
    for (std::size_t k = 0; sane && k < v.size(); ++k)
      sane = std::isfinite(v[k]);
    for (std::size_t k = 0; sane && k < c.size(); ++k)
      sane = c[k] < n_points;
    for (std::size_t k = 0; sane && k < f.size(); ++k)
      sane = k % 4 == 3 || f[k] < n_points;
    if (!sane)
      throw InputError(path, "corrupt knife checkpoint (block sizes or vertex indices out of range)");
    std::vector<Point<3>> points;
    for (std::size_t k = 0; k < v.size(); k += 3)
      points.emplace_back(v[k], v[k + 1], v[k + 2]);
    std::vector<CellData<3>> cells(c.size() / 4, CellData<3>(4));
    for (std::size_t k = 0; k < cells.size(); ++k)
      for (unsigned j = 0; j < 4; ++j)
        cells[k].vertices[j] = c[4 * k + j];
    auto fresh = std::make_unique<Triangulation<3>>();
    try
      {
        fresh->create_triangulation(points, cells, SubCellData());
      }
    catch (const std::exception &)
      {
        throw InputError(path, "corrupt knife checkpoint (its cells do not form a mesh)");
      }
    std::map<std::array<unsigned, 3>, unsigned> ids;
    for (std::size_t k = 0; k < f.size(); k += 4)
      {
        std::array<unsigned, 3> key{f[k], f[k + 1], f[k + 2]};
        std::sort(key.begin(), key.end());
        ids[key] = f[k + 3];
      }
    for (const auto &cell : fresh->active_cell_iterators())
      for (const unsigned j : cell->face_indices())
        if (cell->face(j)->at_boundary())
          {
            std::array<unsigned, 3> key{cell->face(j)->vertex_index(0), cell->face(j)->vertex_index(1),
                                        cell->face(j)->vertex_index(2)};
            std::sort(key.begin(), key.end());
            if (auto it = ids.find(key); it != ids.end())
              cell->face(j)->set_boundary_id(it->second);
          }
    tria              = std::move(fresh);
    current_surface   = extract_surface(*tria);
    if (acc.size() != current_surface.vertices.size())
      throw InputError(path, "knife checkpoint does not match its mesh");
    accumulated.swap(acc), displacement.swap(disp), since_remesh.swap(since);
    quality_threshold = state.at(0);
    remeshes          = static_cast<unsigned>(state.at(1));
  }

  void PartModel::write(SolidOutput &output, double time) const
  {
    io::ScopedTimer t(timers, "output");
    std::vector<double> depth(tria->n_vertices(), 0.0), travel(tria->n_vertices(), 0.0),
      moved(3 * tria->n_vertices(), 0.0);
    const std::vector<double> gauge = wear_depth();
    for (std::size_t v = 0; v < current_surface.vertices.size(); ++v)
      {
        depth[current_surface.tria_vertex[v]]  = gauge[v];
        travel[current_surface.tria_vertex[v]] = accumulated[v];
        for (unsigned c = 0; c < 3; ++c)
          moved[3 * current_surface.tria_vertex[v] + c] = displacement[3 * v + c];
      }
    output.write(*tria, {{"scaled_jacobian", cell_scaled_jacobians(*tria)}}, time,
                 {{"wear_depth", 1, depth}, {"vertex_displacement", 1, travel}, {"wear_displacement", 3, moved}});
  }
} // namespace abrade::fem
