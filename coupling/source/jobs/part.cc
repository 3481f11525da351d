// The `part` job (`Job = knife` is its old name, still read): the part's solid model on its own.
//
// 1. Build the part: the parametric grab knife (fem/parametric_knife.h) or a solid from a file.
// 2. Check the mesh: scaled Jacobians, aspect ratio, inverted cells (an inverted cell is an
//    error), the wearable and clamped boundary.
// 3. Write part/part.pvd + .vtu (cell field scaled_jacobian), part/part.stl (the surface the
//    DEM would see), part/part_surface.vtp (the same with boundary_id: 1 wears, 2 is clamped),
//    the parametric knife as part/part.step (millimetres), part/faces.vtp (each boundary face
//    with the file's face it belongs to and its role: wears, clamped, held), and volume, mass,
//    quality and a part's faces into summary.json (results.part). The run's report
//    (report.html) is the part's preview: it drawn from two sides coloured by role with the
//    faces' numbers, and the face table.
// 4. Where the parameter file is a DEM case that holds the part (a wall with Geometry = solid
//    model): the case around it (case_scene.h) for the preview's set-up picture: the part as
//    the case places it (part/scene_part.vtp, with role), the other walls' outlines
//    (part/scene_walls.dat) and the part's path over one cycle (part/scene_path.dat, a block
//    per phase), the fill region and the domain (summary.json results.part.case).
// (A run directory of an abrade from before subsection Knife was named Part has knife/knife*
// instead: io::part_folder.)
#include <abrade/common/error.h>
#include <abrade/common/vtk_output.h>
#include <abrade/coupling/case_setup/case_scene.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/mpi_once.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/grid/grid_tools.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

namespace abrade::coupling
{
  namespace
  {
    /// The part's boundary faces as triangles, each with the file's face it belongs to
    /// (`face_id`; the parametric knife's boundary id) and what became of it (`role`: 0 wears,
    /// 1 clamped, 2 held): part/faces.vtp, which the preview draws.
    io::PolyData part_faces_surface(const dealii::Triangulation<3> &tria, const PartMesh &m, bool from_file)
    {
      io::PolyData out;
      io::Field    id{"face_id", 1, {}}, role{"role", 1, {}};
      std::size_t  k = 0;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            {
              const auto   face = cell->face(f);
              const auto   b    = face->boundary_id();
              double       file_id = b, became = b == fem::wearable_boundary ? 0 : 1;
              if (from_file && k < m.faces.boundary_faces.size())
                file_id = m.faces.boundary_faces[k].first, became = double(m.faces.boundary_faces[k].second);
              ++k;
              const long first = long(out.points.size() / 3);
              for (const unsigned v : face->vertex_indices())
                for (int d = 0; d < 3; ++d)
                  out.points.push_back(face->vertex(v)[d]);
              // (a quadrilateral's vertices go 0 1 3 2 round it)
              const std::vector<std::array<long, 3>> triangles =
                face->n_vertices() == 3 ? std::vector<std::array<long, 3>>{{first, first + 1, first + 2}}
                                        : std::vector<std::array<long, 3>>{{first, first + 1, first + 3},
                                                                           {first, first + 3, first + 2}};
              for (const auto &t : triangles)
                out.triangles.push_back(t), id.values.push_back(file_id), role.values.push_back(became);
            }
      out.cell_fields = {id, role};
      return out;
    }
    /// Step 4: the case around the part, written for the preview (case_scene.h).
    void write_case_scene(JobContext &ctx, const fem::SolidSurface &surface, const io::PolyData &faces,
                          const std::string &dir)
    {
      const CaseScene scene = case_scene(ctx.parameters, surface);
      if (!scene.present)
        return;
      // the part as each wall places it, its faces' roles kept
      io::PolyData placed;
      for (const auto &p : scene.placements)
        {
          const long first = long(placed.points.size() / 3);
          for (std::size_t k = 0; k + 2 < faces.points.size(); k += 3)
            {
              const Eigen::Vector3d q = p.rotation * Eigen::Vector3d(faces.points[k], faces.points[k + 1],
                                                                     faces.points[k + 2]) + p.offset;
              placed.points.insert(placed.points.end(), {q[0], q[1], q[2]});
            }
          for (const auto &t : faces.triangles)
            placed.triangles.push_back({t[0] + first, t[1] + first, t[2] + first});
          for (std::size_t f = 0; f < faces.cell_fields.size(); ++f)
            {
              if (placed.cell_fields.size() <= f)
                placed.cell_fields.push_back({faces.cell_fields[f].name, 1, {}});
              auto &v = placed.cell_fields[f].values;
              v.insert(v.end(), faces.cell_fields[f].values.begin(), faces.cell_fields[f].values.end());
            }
        }
      io::write_vtp(dir + "/scene_part.vtp", placed);
      // the other walls' outlines and the path (a phase per block), as gnuplot data: blocks
      // apart by two blank lines (one would make splot join them into a mesh)
      std::ofstream walls(dir + "/scene_walls.dat"), path(dir + "/scene_path.dat");
      walls.precision(9), path.precision(9);
      for (const auto &o : scene.outlines)
        for (const auto &e : o.segments)
          walls << e[0] << ' ' << e[1] << ' ' << e[2] << '\n' << e[3] << ' ' << e[4] << ' ' << e[5] << "\n\n\n";
      io::Json &c = ctx.results["part"]["case"];
      c["domain"] = std::vector<double>(scene.domain.begin(), scene.domain.end());
      c["fill_region"] = std::vector<double>(scene.fill_region.begin(), scene.fill_region.end());
      c["particles"] = scene.particles;
      c["walls"] = std::vector<double>{};
      for (const auto &o : scene.outlines)
        c["walls"].push_back(o.wall);
      for (const auto &p : scene.placements)
        c["walls"].push_back(p.wall);
      c["path"] = std::vector<double>{};
      for (const auto &leg : scene.path)
        {
          path << "# " << leg.wall << ' ' << leg.phase << '\n';
          for (const auto &x : leg.points)
            path << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
          path << "\n\n";
          io::Json j;
          j["wall"] = leg.wall, j["phase"] = leg.phase;
          j["start"] = std::vector<double>(leg.points.front().begin(), leg.points.front().end());
          j["end"]   = std::vector<double>(leg.points.back().begin(), leg.points.back().end());
          c["path"].push_back(j);
        }
      c["notes"] = std::vector<double>{};
      for (const auto &n : scene.notes)
        c["notes"].push_back(n); // (logged by run(), with the part alone too)
      if (!walls || !path)
        throw RunError("could not write " + dir + "/scene_walls.dat and scene_path.dat");
    }
  } // namespace

  namespace
  {
    class PartJob : public Job
    {
    public:
      std::string name() const override { return "part"; }
      std::string documentation() const override
      {
        return "build the part's solid model (subsection Part), check its mesh and write it (VTU, STL) with its volume and "
               "mass (`knife` is its old name)";
      }
      void   run(JobContext &ctx) const override;
      Report report() const override { return {true, false, false}; }
    };
  } // namespace

  namespace
  {
    /// The mesh's cells, @p volume, mass and quality, logged; a mesh with an inverted cell is
    /// refused.
    fem::MeshQuality checked_quality(const dealii::Triangulation<3> &tria, double volume, double density, io::Log &log)
    {
      const fem::MeshQuality q = fem::mesh_quality(tria);
      std::ostringstream     s;
      s << "Part: " << tria.n_active_cells() << " cells, volume " << volume << " m^3, mass " << volume * density
        << " kg; min scaled Jacobian " << q.min_scaled_jacobian << ", max aspect ratio " << q.max_aspect_ratio;
      log.line(s.str());
      if (q.n_inverted > 0)
        throw RunError("the part's mesh has " + std::to_string(q.n_inverted) + " inverted cells (cell " +
                       std::to_string(q.worst_cell) + " is the worst)");
      return q;
    }

    /// The part into @p dir, its files named @p stem: the mesh with its cells' quality (VTU),
    /// its surface (STL, and VTP with the boundary ids: 1 wears, 2 clamped) and its faces with
    /// their roles (the preview's, returned).
    io::PolyData write_the_part(const dealii::Triangulation<3> &tria, const PartMesh &m, const PartParameters &part,
                                const fem::SolidSurface &surface, const std::string &dir,
                                const std::string &stem)
    {
      fem::SolidOutput out(dir, stem);
      out.write(tria, {{"scaled_jacobian", fem::cell_scaled_jacobians(tria)}}, 0.0);
      io::write_stl(dir + "/" + stem + ".stl", surface.as_polydata());
      io::write_vtp(dir + "/" + stem + "_surface.vtp", surface.as_polydata());
      io::PolyData faces = part_faces_surface(tria, m, part.from_file);
      io::write_vtp(dir + "/faces.vtp", faces);
      return faces;
    }

    /// The summary's account of the part: cells, volume, mass, surface, quality, box.
    void describe_the_part(io::Json &r, const dealii::Triangulation<3> &tria, double volume,
                           const fem::SolidSurface &surface, const fem::MeshQuality &q, double density)
    {
      r["cells"]               = static_cast<long>(tria.n_active_cells());
      r["volume"]              = volume;
      r["mass"]                = volume * density;
      r["surface_area"]        = surface.area();
      r["surface_triangles"]   = static_cast<long>(surface.triangles.size());
      r["min_scaled_jacobian"] = q.min_scaled_jacobian;
      r["max_aspect_ratio"]    = q.max_aspect_ratio;
      const dealii::BoundingBox<3> box = dealii::GridTools::compute_bounding_box(tria);
      r["bounding_box"] = std::vector<double>{box.lower_bound(0), box.lower_bound(1), box.lower_bound(2),
                                              box.upper_bound(0), box.upper_bound(1), box.upper_bound(2)};
    }

    /// A part file's faces as the file numbers them (what Clamped faces / Wearable faces
    /// select): each face's area, place and role (a box or a normal selector may take a part
    /// of a face: then it is mixed), each selector's area and faces, and the reading's
    /// warnings.
    void describe_the_files_faces(io::Json &r, const PartMesh &m, const std::vector<std::string> &warnings)
    {
      r["solids"]        = static_cast<long>(m.report.n_solids);
      r["wearable_area"] = m.faces.wearable_area;
      r["clamped_area"]  = m.faces.clamped_area;
      io::Json &faces    = r["file_faces"];
      faces              = std::vector<double>{};
      for (const auto &f : m.file_faces)
        {
          io::Json face;
          face["id"]     = static_cast<long>(f.id);
          face["name"]   = f.name;
          face["area"]   = f.area;
          face["centre"] = std::vector<double>{f.centre[0], f.centre[1], f.centre[2]};
          face["normal"] = std::vector<double>{f.normal[0], f.normal[1], f.normal[2]};
          const auto   it       = m.faces.by_face.find(f.id);
          const auto   role     = it != m.faces.by_face.end() ? it->second : fem::FaceAssignment::Role();
          const double parts[3] = {role.wearing_area, role.clamped_area, role.held_area};
          const char  *names[3] = {"wears", "clamped", "held"};
          int          single = -1, nonzero = 0;
          for (int k = 0; k < 3; ++k)
            if (parts[k] > 0)
              single = k, ++nonzero;
          face["role"]         = nonzero == 1 ? names[single] : nonzero == 0 ? "none" : "mixed";
          face["wearing_area"] = role.wearing_area;
          face["clamped_area"] = role.clamped_area;
          face["held_area"]    = role.held_area;
          faces.push_back(face);
        }
      io::Json &selectors = r["selectors"];
      selectors           = std::vector<double>{};
      for (const auto &t : m.faces.taken)
        {
          io::Json one;
          one["list"]     = t.list;
          one["selector"] = t.selector;
          one["area"]     = t.area;
          one["faces"]    = std::vector<double>{};
          for (const auto id : t.faces)
            one["faces"].push_back(static_cast<long>(id));
          selectors.push_back(one);
        }
      r["warnings"] = std::vector<double>{};
      for (const auto &w : warnings)
        r["warnings"].push_back(w);
    }
  } // namespace

  void PartJob::run(JobContext &ctx) const
  {
    for (const auto &n : ctx.parameters.notes()) // (what the reading left out or read under an old name)
      ctx.log.line(n);
    const PartParameters part = read_part_parameters(ctx.parameters);
    fem::init_mpi_once();
    const std::string folder = ctx.output.part_folder(); // (also the files' stem: part/part.pvd)
    const std::string dir    = ctx.output.subdirectory(folder);
    PartMesh          m;
    {
      io::ScopedTimer t(ctx.timers, "mesh part");
      m = mesh_part(part, ctx.parameters, dir);
    }
    const dealii::Triangulation<3> &tria = *m.tria;
    std::vector<std::string>        warnings;
    report_part_mesh(part, m, ctx.log, &warnings);
    const double            volume  = fem::mesh_volume(tria);
    const fem::MeshQuality  q       = checked_quality(tria, volume, part.density, ctx.log);
    const fem::SolidSurface surface = fem::extract_surface(tria);
    const io::PolyData      faces   = write_the_part(tria, m, part, surface, dir, folder);

    io::Json &r = ctx.results["part"];
    describe_the_part(r, tria, volume, surface, q, part.density);
    if (!part.from_file)
      {
        r["analytic_volume"] = part.geometry.volume();
        part.geometry.write_step(dir + "/" + folder + ".step"); // the design as CAD, in mm
      }
    else
      describe_the_files_faces(r, m, warnings);
    write_case_scene(ctx, surface, faces, dir);
  }

  ABRADE_REGISTER_JOB(PartJob);
} // namespace abrade::coupling
