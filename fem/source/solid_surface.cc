// The part's boundary as a triangle surface, mapped to the cells' faces and vertices; read from
// files, remeshed by Gmsh, its thickness and fields carried across (solid_surface.h).
#include <abrade/common/closest_point.h>
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/symmetric_tensor.h>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStaticCellLocator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>

#include <gmsh.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>

#include <unistd.h>

namespace abrade::fem
{
  using namespace dealii;

  double SolidSurface::triangle_area(std::size_t k) const
  {
    const auto &t = triangles[k];
    return 0.5 * cross_product_3d(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]).norm();
  }

  double SolidSurface::area() const
  {
    double a = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
      a += triangle_area(t);
    return a;
  }

  std::vector<Tensor<1, 3>> SolidSurface::vertex_normals() const
  {
    std::vector<Tensor<1, 3>> n(vertices.size());
    for (const auto &t : triangles)
      {
        const Tensor<1, 3> a = cross_product_3d(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]);
        for (unsigned v : t)
          n[v] += a; // |a| = twice the area: area weighting
      }
    for (auto &x : n)
      if (x.norm() > 0)
        x /= x.norm();
    return n;
  }

  std::vector<Tensor<1, 3>> SolidSurface::inward_offsets(const std::vector<double> &depth,
                                                         const std::vector<bool>   *held) const
  {
    // per vertex: M = sum A n n^T, b = -sum A n depth (n outward); u minimises sum A (n.u + depth)^2
    // (a held triangle's plane with depth 0)
    std::vector<SymmetricTensor<2, 3>> m(vertices.size());
    std::vector<Tensor<1, 3>>          b(vertices.size());
    for (std::size_t k = 0; k < triangles.size(); ++k)
      {
        const auto  &t    = triangles[k];
        Tensor<1, 3> n    = cross_product_3d(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]);
        const double area = 0.5 * n.norm();
        if (area <= 0)
          continue;
        n /= 2 * area;
        const SymmetricTensor<2, 3> nn    = symmetrize(outer_product(n, n));
        const double                wears = held && (*held)[k] ? 0.0 : 1.0;
        for (unsigned v : t)
          m[v] += area * nn, b[v] -= area * wears * depth[v] * n;
      }
    std::vector<Tensor<1, 3>> u(vertices.size());
    for (std::size_t v = 0; v < vertices.size(); ++v)
      {
        if (depth[v] == 0 || m[v].norm() == 0)
          continue;
        const auto eig = eigenvectors(m[v]); // descending eigenvalues
        for (const auto &[lambda, e] : eig)
          if (lambda > 1e-3 * eig[0].first)
            u[v] += (e * b[v]) / lambda * e;
        if (u[v].norm() > 4 * std::abs(depth[v]))
          u[v] *= 4 * std::abs(depth[v]) / u[v].norm();
      }
    return u;
  }

  io::PolyData SolidSurface::as_polydata() const
  {
    io::PolyData d;
    for (const auto &p : vertices)
      d.points.insert(d.points.end(), {p[0], p[1], p[2]});
    for (const auto &t : triangles)
      d.triangles.push_back({long(t[0]), long(t[1]), long(t[2])});
    std::vector<double> ids(boundary_id.begin(), boundary_id.end());
    d.cell_fields.push_back({"boundary_id", 1, ids});
    return d;
  }

  namespace
  {
    /// The surface as VTK polydata (double points), for VTK's locators.
    vtkSmartPointer<vtkPolyData> as_vtk(const SolidSurface &s)
    {
      vtkNew<vtkPoints> points;
      points->SetDataTypeToDouble();
      for (const auto &p : s.vertices)
        points->InsertNextPoint(p[0], p[1], p[2]);
      vtkNew<vtkCellArray> cells;
      for (const auto &t : s.triangles)
        {
          const vtkIdType ids[3] = {t[0], t[1], t[2]};
          cells->InsertNextCell(3, ids);
        }
      auto polydata = vtkSmartPointer<vtkPolyData>::New();
      polydata->SetPoints(points);
      polydata->SetPolys(cells);
      return polydata;
    }

    vtkSmartPointer<vtkStaticCellLocator> locator_of(vtkPolyData *polydata)
    {
      auto locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      locator->SetDataSet(polydata);
      locator->BuildLocator();
      return locator;
    }
  } // namespace

  std::vector<double> local_thickness(const SolidSurface &s)
  {
    std::vector<double> thickness(s.vertices.size(), std::numeric_limits<double>::infinity());
    if (s.triangles.empty())
      return thickness;
    const auto polydata = as_vtk(s);
    const auto locator  = locator_of(polydata);
    const auto normals  = s.vertex_normals();
    double     box[6];
    polydata->GetBounds(box);
    const double reach = 2 * std::hypot(box[1] - box[0], box[3] - box[2], box[5] - box[4]);
    // The ray starts a hair inside: the vertex's own triangles all pass through the vertex, so a
    // ray from just below it cannot meet them again (VTK's locator finds the first hit along it).
    const double hair = 1e-9 * reach;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      {
        if (normals[v].norm() == 0)
          continue;
        const Tensor<1, 3> d    = -normals[v];
        const Point<3>     from = s.vertices[v] + hair * d, to = s.vertices[v] + reach * d;
        double             t = 0, x[3], pcoords[3];
        int                sub  = 0;
        vtkIdType          cell = -1;
        if (locator->IntersectWithLine(from.begin_raw(), to.begin_raw(), 0.0, t, x, pcoords, sub, cell) && cell >= 0)
          thickness[v] = hair + t * (reach - hair);
      }
    return thickness;
  }

  double typical_thickness(const SolidSurface &s, types::boundary_id id)
  {
    const auto          thickness = local_thickness(s);
    std::vector<double> area(s.vertices.size(), 0.0);
    for (std::size_t t = 0; t < s.triangles.size(); ++t)
      if (s.boundary_id[t] == id)
        for (unsigned v : s.triangles[t])
          area[v] += s.triangle_area(t) / 3;
    std::vector<std::pair<double, double>> by_thickness; // (thickness, area)
    double                                 total = 0;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      if (area[v] > 0 && std::isfinite(thickness[v]))
        by_thickness.emplace_back(thickness[v], area[v]), total += area[v];
    std::sort(by_thickness.begin(), by_thickness.end());
    double below = 0;
    for (const auto &[t, a] : by_thickness)
      if ((below += a) >= 0.5 * total)
        return t;
    return 0;
  }

  std::vector<unsigned> worn_through(const SolidSurface &s, const std::vector<double> &depth, double fraction,
                                     double ignore_below)
  {
    const auto            thickness = local_thickness(s);
    std::vector<unsigned> out;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      if (thickness[v] >= ignore_below && depth[v] >= fraction * thickness[v])
        out.push_back(static_cast<unsigned>(v));
    return out;
  }

  struct SurfaceTransfer::Impl
  {
    vtkSmartPointer<vtkPolyData>         polydata;
    vtkSmartPointer<vtkStaticCellLocator> locator;
  };

  SurfaceTransfer::SurfaceTransfer(const SolidSurface &from, const SolidSurface &to)
  {
    if (from.triangles.empty())
      throw std::logic_error("SurfaceTransfer: the surface to carry fields from has no triangles");
    Impl impl;
    impl.polydata = as_vtk(from);
    impl.locator  = locator_of(impl.polydata);
    triangle.resize(to.vertices.size());
    weight.resize(to.vertices.size());
    foot.resize(to.vertices.size());
    for (std::size_t v = 0; v < to.vertices.size(); ++v)
      {
        double    q[3] = {to.vertices[v][0], to.vertices[v][1], to.vertices[v][2]}, closest[3], d2 = 0;
        vtkIdType cell = 0;
        int       sub  = 0;
        impl.locator->FindClosestPoint(q, closest, cell, sub, d2);
        const auto &t = from.triangles[cell];
        const auto  cp = geometry::closest_point_on_triangle(q, from.vertices[t[0]].begin_raw(), from.vertices[t[1]].begin_raw(),
                                                             from.vertices[t[2]].begin_raw());
        triangle[v] = static_cast<unsigned>(cell);
        weight[v]   = geometry::barycentric(cp.p, from.vertices[t[0]].begin_raw(), from.vertices[t[1]].begin_raw(),
                                            from.vertices[t[2]].begin_raw());
        foot[v]     = Point<3>(cp.p[0], cp.p[1], cp.p[2]);
      }
    triangles = from.triangles;
  }

  std::vector<double> SurfaceTransfer::operator()(const std::vector<double> &values, unsigned components,
                                                  unsigned component) const
  {
    std::vector<double> out(triangle.size());
    for (std::size_t v = 0; v < out.size(); ++v)
      {
        const auto &t = triangles[triangle[v]];
        out[v]        = weight[v][0] * values[components * t[0] + component] +
                 weight[v][1] * values[components * t[1] + component] + weight[v][2] * values[components * t[2] + component];
      }
    return out;
  }

  std::vector<double> transfer_surface_field(const SolidSurface &from, const std::vector<double> &values,
                                             const SolidSurface &to)
  {
    return SurfaceTransfer(from, to)(values);
  }

  SolidSurface extract_surface(const Triangulation<3> &tria, const std::set<types::boundary_id> &ids)
  {
    SolidSurface      s;
    std::vector<long> surface_index(tria.n_vertices(), -1);
    auto vertex = [&](const typename Triangulation<3>::active_cell_iterator &cell, unsigned f, unsigned v) {
      const unsigned g = cell->face(f)->vertex_index(v);
      if (surface_index[g] < 0)
        {
          surface_index[g] = static_cast<long>(s.vertices.size());
          s.vertices.push_back(tria.get_vertices()[g]);
          s.tria_vertex.push_back(g);
        }
      return static_cast<unsigned>(surface_index[g]);
    };
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned f : cell->face_indices())
        {
          const auto face = cell->face(f);
          if (!face->at_boundary() || (!ids.empty() && !ids.count(face->boundary_id())))
            continue;
          std::vector<std::array<unsigned, 3>> tris;
          if (face->n_vertices() == 3)
            tris.push_back({vertex(cell, f, 0), vertex(cell, f, 1), vertex(cell, f, 2)});
          else // quadrilateral: vertices in lexicographic order, cyclic order 0 1 3 2
            {
              tris.push_back({vertex(cell, f, 0), vertex(cell, f, 1), vertex(cell, f, 3)});
              tris.push_back({vertex(cell, f, 0), vertex(cell, f, 3), vertex(cell, f, 2)});
            }
          for (auto t : tris)
            {
              const Tensor<1, 3> n = cross_product_3d(s.vertices[t[1]] - s.vertices[t[0]], s.vertices[t[2]] - s.vertices[t[0]]);
              if (n * (face->center() - cell->center()) < 0) // point away from the cell
                std::swap(t[1], t[2]);
              s.triangles.push_back(t);
              s.face.emplace_back(cell->active_cell_index(), f);
              s.boundary_id.push_back(face->boundary_id());
            }
        }
    return s;
  }

  SolidSurface surface_of(const io::PolyData &polydata)
  {
    SolidSurface s;
    for (std::size_t k = 0; k + 2 < polydata.points.size(); k += 3)
      s.vertices.emplace_back(polydata.points[k], polydata.points[k + 1], polydata.points[k + 2]);
    for (const auto &t : polydata.triangles)
      s.triangles.push_back({unsigned(t[0]), unsigned(t[1]), unsigned(t[2])});
    s.boundary_id.assign(s.triangles.size(), 0);
    return s;
  }

  double enclosed_volume(const SolidSurface &s, const std::vector<Tensor<1, 3>> *moves, double scale)
  {
    auto at = [&](unsigned v) { return moves ? Point<3>(s.vertices[v] + scale * (*moves)[v]) : s.vertices[v]; };
    double six_v = 0;
    for (const auto &t : s.triangles)
      six_v += Tensor<1, 3>(at(t[0])) * cross_product_3d(Tensor<1, 3>(at(t[1])), Tensor<1, 3>(at(t[2])));
    return std::abs(six_v) / 6;
  }

  namespace
  {
    /// Gmsh remeshes the surface in @p stl (enclosing @p enclosed) into @p new_tria. Gmsh's
    /// classification of a worn surface into patches it can reparametrise is erratic: a bolted
    /// edge's worn surface that it refused at 15 degrees ("Invalid boundary mesh (overlapping
    /// facets)" inside one patch) meshed at 20, 25, 40 and more, and aborted Gmsh at 30 and 35
    /// (in its child process). Larger angles are tried in turn, but they merge edges of less
    /// than the angle into patches that the new triangles cut by chords: the same surface lost
    /// 6e-4 of its volume at 25 degrees (a whole DEM update's wear) and gained 1e-4 at 20, 4e-5
    /// at 40. A larger angle's mesh is taken only where it keeps the enclosed volume to 5e-5 (a
    /// 15-degree remesh of a worn knife changes it by up to 2e-5); a time limit is not tried
    /// again.
    void remesh_at_angles(const std::string &stl, double h, Triangulation<3> &new_tria, SolidFileSettings &settings,
                          double enclosed)
    {
      std::string refused;
      for (const double angle : {15.0, 20.0, 25.0, 40.0})
        {
          try
            {
              settings.classify_angle = angle;
              read_solid(stl, h, new_tria, settings);
              const double change = std::abs(mesh_volume(new_tria) / enclosed - 1);
              if (angle == 15.0 || change <= 5e-5)
                return;
              refused += "; at " + io::format_number(angle) + " degrees its volume changed by " + io::format_number(change);
            }
          catch (const InputError &e)
            {
              if (std::string(e.what()).find("did not finish meshing") != std::string::npos)
                throw;
              if (refused.empty())
                refused = e.what();
            }
          new_tria.clear();
        }
      throw InputError(stl, "Gmsh could not remesh it: " + refused);
    }

    /// Boundary ids from the old boundary triangle (@p ids_from) closest to each new face's
    /// centre.
    void take_boundary_ids(Triangulation<3> &new_tria, const SolidSurface &ids_from)
    {
      SolidSurface centres;
      for (const auto &cell : new_tria.active_cell_iterators())
        for (const unsigned f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            centres.vertices.push_back(cell->face(f)->center());
      const SurfaceTransfer closest(ids_from, centres);
      std::size_t           k = 0;
      for (const auto &cell : new_tria.active_cell_iterators())
        for (const unsigned f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            cell->face(f)->set_boundary_id(ids_from.boundary_id[closest.triangles_of()[k++]]);
    }
  } // namespace

  std::string mesh_closed_surface(const io::PolyData &surface, double h, Triangulation<3> &new_tria,
                                  const std::string &dir, const SolidSurface &ids_from, bool own_triangles_first)
  {
    std::filesystem::create_directories(dir);
    // a name of this process's own: under MPI every rank meshes its copy of the part
    const std::string stl = dir + "/remesh-surface-" + std::to_string(::getpid()) + ".stl";
    io::write_stl(stl, surface);
    SolidFileSettings as_is;
    as_is.work_directory = dir;
    // a remesh with a sliver (scaled Jacobian 4e-6 on the 30 mm reference knife at 8 mm of
    // uniform wear) is meshed again by Gmsh's other mesher and optimisers and the better one
    // kept: the next update's interior motion inverts a sliver (no warning: the lifetime loop
    // judges the quality of its remeshes itself)
    as_is.min_quality = 0.01;
    // a worn surface meshes in seconds; Gmsh's surface classification can loop forever on a
    // tangled one (METIS): two minutes, then the other way
    as_is.mesher_time_limit = 120;
    // the two ways, in the order asked: Gmsh remeshes the surface (its triangles then need not
    // be good ones, but its reparametrisation can cut sharp edges between its new vertices), or
    // it fills the volume inside the surface's own triangles (exact, and as good as they are)
    const double enclosed = enclosed_volume(surface_of(surface)); // (the surface as it went to Gmsh)
    auto remeshed = [&] { remesh_at_angles(stl, h, new_tria, as_is, enclosed); };
    auto filled   = [&] { read_closed_triangles(stl, h, new_tria, as_is.mesher_time_limit); };
    std::string kept;
    new_tria.clear();
    try
      {
        own_triangles_first ? filled() : remeshed();
      }
    catch (const InputError &first)
      {
        kept = first.what();
        new_tria.clear();
        try
          {
            own_triangles_first ? remeshed() : filled();
          }
        catch (const InputError &second)
          {
            throw InputError(stl, std::string("Gmsh could neither remesh nor fill the surface: ") + first.what() +
                                    "; " + second.what());
          }
      }
    take_boundary_ids(new_tria, ids_from);
    return kept;
  }

  std::string remesh(const Triangulation<3> &tria, double h, Triangulation<3> &new_tria, const std::string &dir)
  {
    const SolidSurface old = extract_surface(tria);
    return mesh_closed_surface(old.as_polydata(), h, new_tria, dir, old);
  }

  std::size_t set_ids_from_design(Triangulation<3> &tria, const SolidSurface &design, double tolerance,
                                  types::boundary_id worn_id)
  {
    // the boundary faces, their centres, and their vertices (each once)
    SolidSurface                                     centres, corners;
    std::vector<TriaIterator<TriaAccessor<2, 3, 3>>> faces;
    std::vector<std::vector<std::size_t>>            face_corners;
    std::map<unsigned, std::size_t>                  corner_of;
    for (const auto &cell : tria.active_cell_iterators())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            faces.push_back(cell->face(f));
            centres.vertices.push_back(cell->face(f)->center());
            face_corners.emplace_back();
            for (const unsigned v : cell->face(f)->vertex_indices())
              {
                const auto [it, added] = corner_of.emplace(cell->face(f)->vertex_index(v), corners.vertices.size());
                if (added)
                  corners.vertices.push_back(cell->face(f)->vertex(v));
                face_corners.back().push_back(it->second);
              }
          }
    // a face lies on the design where all its corners do (a face's centre lies off a curved
    // design face by its sagitta, its corners on it); the id is that of the design triangle
    // nearest its centre
    const SurfaceTransfer to_corners(design, corners), to_centres(design, centres);
    std::vector<bool>     on_design(corners.vertices.size());
    for (std::size_t v = 0; v < on_design.size(); ++v)
      on_design[v] = corners.vertices[v].distance(to_corners.feet()[v]) <= tolerance;
    std::size_t kept = 0;
    for (std::size_t k = 0; k < faces.size(); ++k)
      {
        bool on = true;
        for (const std::size_t v : face_corners[k])
          on = on && on_design[v];
        const types::boundary_id id = design.boundary_id[to_centres.triangles_of()[k]];
        faces[k]->set_boundary_id(on ? id : worn_id);
        kept += on && id != worn_id;
      }
    return kept;
  }
} // namespace abrade::fem
