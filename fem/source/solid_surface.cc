#include <abrade/common/closest_point.h>
#include <abrade/common/error.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/symmetric_tensor.h>
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

  std::vector<Tensor<1, 3>> SolidSurface::inward_offsets(const std::vector<double> &depth) const
  {
    // per vertex: M = sum A n n^T, b = -sum A n depth (n outward); u minimises sum A (n.u + depth)^2
    std::vector<SymmetricTensor<2, 3>> m(vertices.size());
    std::vector<Tensor<1, 3>>          b(vertices.size());
    for (const auto &t : triangles)
      {
        Tensor<1, 3> n    = cross_product_3d(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]);
        const double area = 0.5 * n.norm();
        if (area <= 0)
          continue;
        n /= 2 * area;
        const SymmetricTensor<2, 3> nn = symmetrize(outer_product(n, n));
        for (unsigned v : t)
          m[v] += area * nn, b[v] -= area * depth[v] * n;
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

  std::vector<double> local_thickness(const SolidSurface &s)
  {
    const auto          normals = s.vertex_normals();
    std::vector<double> thickness(s.vertices.size(), std::numeric_limits<double>::infinity());
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
      {
        const Point<3>     o = s.vertices[v];
        const Tensor<1, 3> d = -normals[v];
        for (const auto &t : s.triangles)
          {
            if (t[0] == v || t[1] == v || t[2] == v)
              continue; // the vertex's own triangles
            // Moeller-Trumbore ray-triangle intersection
            const Tensor<1, 3> e1 = s.vertices[t[1]] - s.vertices[t[0]], e2 = s.vertices[t[2]] - s.vertices[t[0]];
            const Tensor<1, 3> p  = cross_product_3d(d, e2);
            const double       det = e1 * p;
            if (std::abs(det) < 1e-300)
              continue;
            const Tensor<1, 3> tv = o - s.vertices[t[0]];
            const double       u  = (tv * p) / det;
            if (u < 0 || u > 1)
              continue;
            const Tensor<1, 3> q = cross_product_3d(tv, e1);
            const double       w = (d * q) / det;
            if (w < 0 || u + w > 1)
              continue;
            const double dist = (e2 * q) / det;
            if (dist > 1e-12)
              thickness[v] = std::min(thickness[v], dist);
          }
      }
    return thickness;
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

  std::vector<double> transfer_surface_field(const SolidSurface &from, const std::vector<double> &values,
                                             const SolidSurface &to)
  {
    std::vector<double> out(to.vertices.size(), 0.0);
    for (std::size_t v = 0; v < to.vertices.size(); ++v)
      {
        const Point<3> &p = to.vertices[v];
        double          best_d2 = std::numeric_limits<double>::infinity();
        for (const auto &t : from.triangles)
          {
            const Point<3> &a = from.vertices[t[0]], &b = from.vertices[t[1]], &c = from.vertices[t[2]];
            const auto      cp = geometry::closest_point_on_triangle(p.begin_raw(), a.begin_raw(), b.begin_raw(),
                                                                     c.begin_raw());
            const Point<3>  q(cp.p[0], cp.p[1], cp.p[2]);
            const double    d2 = p.distance_square(q);
            if (d2 >= best_d2)
              continue;
            best_d2      = d2;
            const auto w = geometry::barycentric(cp.p, a.begin_raw(), b.begin_raw(), c.begin_raw());
            out[v]       = w[0] * values[t[0]] + w[1] * values[t[1]] + w[2] * values[t[2]];
          }
      }
    return out;
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

  namespace
  {
    void read_msh_file(const std::string &path, Triangulation<3> &tria)
    {
      std::ifstream file(path);
      GridIn<3>     in;
      in.attach_triangulation(tria);
      in.read_msh(file); // deal.II's own parser: physical surface tags become boundary ids
    }

    /// Gmsh: surfaces in the current model -> one volume -> tetrahedra -> .msh 2.2
    void mesh_volume_with_gmsh(const std::string &label, double h, types::boundary_id id, const std::string &msh)
    {
      gmsh::vectorpair volumes;
      gmsh::model::getEntities(volumes, 3);
      if (volumes.empty())
        throw InputError(label, "the geometry encloses no volume (is the surface closed?)");
      gmsh::vectorpair surfaces;
      gmsh::model::getEntities(surfaces, 2);
      std::vector<int> vtags, stags;
      for (const auto &v : volumes)
        vtags.push_back(v.second);
      for (const auto &f : surfaces)
        stags.push_back(f.second);
      gmsh::model::addPhysicalGroup(3, vtags, 1);
      gmsh::model::addPhysicalGroup(2, stags, id);
      gmsh::option::setNumber("Mesh.MeshSizeMax", h);
      gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * h);
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.Optimize", 1);
      gmsh::model::mesh::generate(3);
      gmsh::write(msh);
    }

    /// Loads the shapes of a STEP or IGES file into the current Gmsh model, in metres:
    /// OpenCASCADE converts the unit the file declares to millimetres (its default), which is
    /// scaled here to metres. (Gmsh 4.8's Geometry.OCCTargetUnit does not change that.)
    void import_cad(const std::string &path)
    {
      gmsh::vectorpair shapes;
      gmsh::model::occ::importShapes(path, shapes);
      gmsh::model::occ::synchronize();
      gmsh::vectorpair top;
      for (int dim = 3; dim >= 0 && top.empty(); --dim)
        gmsh::model::getEntities(top, dim);
      if (!top.empty())
        {
          gmsh::model::occ::dilate(top, 0, 0, 0, 0.001, 0.001, 0.001);
          gmsh::model::occ::synchronize();
        }
    }

    std::string format_length(double x)
    {
      char b[32];
      std::snprintf(b, sizeof b, "%.4g", x);
      return b;
    }

    /// Refuses a part whose size is implausible for its unit, naming its bounding box (in metres,
    /// after @p scale) and the likely scale.
    void check_extent(const std::string &path, const std::array<double, 6> &box, double scale,
                      const SolidFileSettings &s, bool has_units)
    {
      double extent[3], largest = 0;
      for (int k = 0; k < 3; ++k)
        largest = std::max(largest, extent[k] = scale * (box[k + 3] - box[k]));
      const std::string size = format_length(extent[0]) + " x " + format_length(extent[1]) + " x " +
                               format_length(extent[2]) + " m";
      const std::string fix  = has_units ? "check the unit the file declares, or set Knife/File scale"
                                         : "set Knife/File scale (the file has no unit)";
      if (largest > s.max_extent)
        throw InputError(path, "the part's bounding box is " + size + ", larger than " + format_length(s.max_extent) +
                                 " m: is it in millimetres? " + fix + " = " + format_length(0.001 * scale));
      if (largest < s.min_extent)
        throw InputError(path, "the part's bounding box is " + size + ", smaller than " + format_length(s.min_extent) +
                                 " m: is it in metres read as millimetres? " + fix + " = " + format_length(1000 * scale));
    }

    /// Refuses a part that would need more than the allowed tetrahedra, with the estimate and a
    /// mesh size that fits.
    void check_budget(const std::string &path, double volume, double h, const SolidFileSettings &s)
    {
      if (s.max_cells <= 0)
        return;
      const double cells = estimated_cells(volume, h);
      if (cells > s.max_cells)
        throw InputError(path, "meshing the part (" + format_length(volume) + " m^3) with Knife/Mesh size " +
                                 format_length(h) + " m needs about " + format_length(cells) +
                                 " tetrahedra, more than Knife/Maximum cells = " + format_length(s.max_cells) +
                                 "; a Mesh size of " + format_length(h * std::cbrt(cells / (0.5 * s.max_cells))) +
                                 " m needs about half the limit");
    }

    /// The bounding box of the current Gmsh model.
    std::array<double, 6> model_box()
    {
      std::array<double, 6> b;
      gmsh::model::getBoundingBox(-1, -1, b[0], b[1], b[2], b[3], b[4], b[5]);
      return b;
    }

    /// The volume enclosed by the current Gmsh model's surface triangles (an STL just merged),
    /// by the divergence theorem; oriented either way.
    double enclosed_volume_of_triangles()
    {
      std::vector<std::size_t> tags;
      std::vector<double>      xyz, parametric;
      gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
      std::map<std::size_t, std::size_t> at;
      for (std::size_t k = 0; k < tags.size(); ++k)
        at[tags[k]] = k;
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> elements, nodes;
      gmsh::model::mesh::getElements(types, elements, nodes, 2, -1);
      double v = 0;
      for (std::size_t b = 0; b < types.size(); ++b)
        if (types[b] == 2)
          for (std::size_t k = 0; k + 2 < nodes[b].size(); k += 3)
            {
              const double *p = &xyz[3 * at.at(nodes[b][k])], *q = &xyz[3 * at.at(nodes[b][k + 1])],
                           *r = &xyz[3 * at.at(nodes[b][k + 2])];
              v += (p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0]) +
                    p[2] * (q[0] * r[1] - q[1] * r[0])) / 6;
            }
      return std::abs(v);
    }

    template <typename F>
    void with_gmsh(const std::string &label, F &&f)
    {
      gmsh::initialize();
      gmsh::option::setNumber("General.Terminal", 0);
      try
        {
          f();
        }
      catch (const InputError &)
        {
          gmsh::finalize();
          throw;
        }
      catch (...)
        {
          std::string last;
          gmsh::logger::getLastError(last);
          gmsh::finalize();
          throw InputError(label, "Gmsh could not mesh it: " + (last.empty() ? std::string("unknown error") : last));
        }
      gmsh::finalize();
    }
  } // namespace

  double estimated_cells(double volume, double h) { return 8.5 * volume / (h * h * h); }

  void read_solid(const std::string &path, double h, Triangulation<3> &tria, types::boundary_id id,
                  const SolidFileSettings &settings)
  {
    if (!(settings.scale > 0))
      throw InputError(path, "the file scale must be positive");
    if (!std::filesystem::exists(path))
      throw InputError(path, "solid file not found");
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext == ".msh")
      {
        read_msh_file(path, tria);
        if (settings.scale != 1)
          GridTools::scale(settings.scale, tria);
        const BoundingBox<3> b = GridTools::compute_bounding_box(tria);
        check_extent(path, {b.lower_bound(0), b.lower_bound(1), b.lower_bound(2), b.upper_bound(0), b.upper_bound(1),
                            b.upper_bound(2)},
                     1.0, settings, false);
        return;
      }
    if (!(h > 0))
      throw InputError(path, "meshing a CAD or STL solid needs a positive mesh size");
    // a name of this process's own: MPI ranks and the parallel runs of a study remesh at once
    static int        meshed = 0;
    const std::string msh    = (std::filesystem::temp_directory_path() /
                             (std::filesystem::path(path).stem().string() + "-abrade-volume-" +
                              std::to_string(::getpid()) + "-" + std::to_string(meshed++) + ".msh"))
                              .string();
    // the file's own length unit: h in it (STL), or the model scaled to metres first (CAD)
    const double file_h = h / settings.scale;
    if (is_cad_file(path))
      with_gmsh(path, [&] {
        import_cad(path);
        if (settings.scale != 1)
          {
            gmsh::vectorpair volumes;
            gmsh::model::getEntities(volumes, 3);
            gmsh::model::occ::dilate(volumes, 0, 0, 0, settings.scale, settings.scale, settings.scale);
            gmsh::model::occ::synchronize();
          }
        check_extent(path, model_box(), 1.0, settings, true);
        gmsh::vectorpair volumes;
        gmsh::model::getEntities(volumes, 3);
        double volume = 0;
        for (const auto &v : volumes)
          {
            double m = 0;
            gmsh::model::occ::getMass(v.first, v.second, m);
            volume += m;
          }
        check_budget(path, volume, h, settings);
        mesh_volume_with_gmsh(path, h, id, msh);
      });
    else if (ext == ".stl")
      with_gmsh(path, [&] {
        gmsh::merge(path);
        check_extent(path, model_box(), settings.scale, settings, false);
        check_budget(path, enclosed_volume_of_triangles() * std::pow(settings.scale, 3), h, settings);
        // sharp edges (more than 15 degrees) stay edges; the facets become remeshable surfaces
        gmsh::model::mesh::classifySurfaces(15 * M_PI / 180, true, true, M_PI);
        gmsh::model::mesh::createGeometry();
        gmsh::vectorpair surfaces;
        gmsh::model::getEntities(surfaces, 2);
        std::vector<int> tags;
        for (const auto &f : surfaces)
          tags.push_back(f.second);
        const int loop = gmsh::model::geo::addSurfaceLoop(tags);
        gmsh::model::geo::addVolume({loop});
        gmsh::model::geo::synchronize();
        mesh_volume_with_gmsh(path, file_h, id, msh);
      });
    else
      throw InputError(path, "unknown solid format '" + ext + "' (use .msh, .step/.stp, .iges/.igs or a closed .stl)");
    read_msh_file(msh, tria);
    std::filesystem::remove(msh);
    if (ext == ".stl" && settings.scale != 1)
      GridTools::scale(settings.scale, tria);
  }

  bool is_cad_file(const std::string &path)
  {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
  }

  SolidSurface read_cad_surface(const std::string &path, double h)
  {
    if (!std::filesystem::exists(path))
      throw InputError(path, "CAD file not found");
    if (!is_cad_file(path))
      throw InputError(path, "not a CAD file (.step/.stp or .iges/.igs)");
    if (!(h > 0))
      throw InputError(path, "meshing a CAD surface needs a positive mesh size");
    SolidSurface s;
    with_gmsh(path, [&] {
      import_cad(path);
      gmsh::vectorpair surfaces;
      gmsh::model::getEntities(surfaces, 2);
      if (surfaces.empty())
        throw InputError(path, "the file holds no surface");
      gmsh::option::setNumber("Mesh.MeshSizeMax", h);
      gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * h);
      gmsh::model::mesh::generate(2);
      // the nodes of the model (on surfaces, curves and points); those of triangles are kept
      std::vector<std::size_t> tags;
      std::vector<double>      xyz, parametric;
      gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
      std::map<std::size_t, std::size_t> position;
      for (std::size_t k = 0; k < tags.size(); ++k)
        position[tags[k]] = k;
      std::map<std::size_t, unsigned> index;
      auto vertex = [&](std::size_t tag) {
        const auto [it, added] = index.try_emplace(tag, static_cast<unsigned>(s.vertices.size()));
        if (added)
          {
            const std::size_t k = position.at(tag);
            s.vertices.emplace_back(xyz[3 * k], xyz[3 * k + 1], xyz[3 * k + 2]);
          }
        return it->second;
      };
      std::vector<int>                      types;
      std::vector<std::vector<std::size_t>> elements, nodes;
      gmsh::model::mesh::getElements(types, elements, nodes, 2, -1);
      for (std::size_t b = 0; b < types.size(); ++b)
        {
          if (types[b] != 2) // 3-node triangles only (no quadrangles are asked for)
            throw InputError(path, "Gmsh made surface elements other than triangles");
          for (std::size_t k = 0; k + 2 < nodes[b].size(); k += 3)
            s.triangles.push_back({vertex(nodes[b][k]), vertex(nodes[b][k + 1]), vertex(nodes[b][k + 2])});
        }
    });
    if (s.triangles.empty())
      throw InputError(path, "Gmsh made no triangles of its surfaces");
    return s;
  }

  void remesh(const Triangulation<3> &tria, double h, Triangulation<3> &new_tria, const std::string &dir)
  {
    const SolidSurface old = extract_surface(tria);
    std::filesystem::create_directories(dir);
    const std::string stl = dir + "/remesh-surface.stl";
    io::write_stl(stl, old.as_polydata());
    read_solid(stl, h, new_tria, 0);
    // boundary ids from the old boundary triangle closest to each new face's centre
    for (const auto &cell : new_tria.active_cell_iterators())
      for (const unsigned f : cell->face_indices())
        if (cell->face(f)->at_boundary())
          {
            const Point<3> c = cell->face(f)->center();
            std::size_t    best = 0;
            double         best_d2 = std::numeric_limits<double>::infinity();
            for (std::size_t t = 0; t < old.triangles.size(); ++t)
              {
                const auto  &tri = old.triangles[t];
                const auto   cp  = geometry::closest_point_on_triangle(c.begin_raw(), old.vertices[tri[0]].begin_raw(),
                                                                       old.vertices[tri[1]].begin_raw(),
                                                                       old.vertices[tri[2]].begin_raw());
                const double d2 = c.distance_square(Point<3>(cp.p[0], cp.p[1], cp.p[2]));
                if (d2 < best_d2)
                  best_d2 = d2, best = t;
              }
            cell->face(f)->set_boundary_id(old.boundary_id[best]);
          }
  }
} // namespace abrade::fem
