// The `knife` job: the knife's solid model on its own.
//
// 1. Build the knife: the parametric grab knife (fem/knife_geometry.h) or a solid from a file.
// 2. Check the mesh: scaled Jacobians, aspect ratio, inverted cells (an inverted cell is an
//    error), the wearable and clamped boundary.
// 3. Write knife/knife.pvd + .vtu (cell field scaled_jacobian), knife/knife.stl (the surface the
//    DEM would see), and volume, mass and quality into summary.json.
#include <abrade/common/error.h>
#include <abrade/coupling/jobs.h>
#include <abrade/coupling/knife_parameters.h>
#include <abrade/fem/knife_geometry.h>
#include <abrade/fem/mesh_quality.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/solid_surface.h>

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

namespace abrade::coupling
{
  KnifeParameters read_knife_parameters(ParameterFile &file)
  {
    auto           &prm = file.handler();
    KnifeParameters kp;
    auto           &k = kp.geometry;
    prm.enter_subsection("Knife");
    k.length     = prm.get_double("Length");
    k.height     = prm.get_double("Height");
    k.thickness  = prm.get_double("Thickness");
    k.bevel      = prm.get_double("Bevel height");
    const std::string side = prm.get("Bevel side");
    k.bevel_side = side == "both" ? fem::KnifeGeometry::BevelSide::both
                   : side == "plus" ? fem::KnifeGeometry::BevelSide::plus
                                    : fem::KnifeGeometry::BevelSide::minus;
    k.tip_radius = prm.get_double("Tip radius");
    k.lip_height = prm.get_double("Lip height");
    k.lip_width  = prm.get_double("Lip width");
    k.lip_offset = prm.get_double("Lip offset");
    kp.mesh_size = prm.get_double("Mesh size");
    kp.density   = prm.get_double("Density");
    kp.from_file = prm.get("Geometry") == "file";
    kp.file      = prm.get("File");
    kp.file_settings.scale     = prm.get_double("File scale");
    kp.file_settings.max_cells = prm.get_double("Maximum cells");
    prm.leave_subsection();
    if (kp.from_file && !kp.file.empty() && std::filesystem::path(kp.file).is_relative() &&
        file.file_name().front() != '<')
      kp.file = (std::filesystem::path(file.file_name()).parent_path() / kp.file).string();
    if (!kp.from_file)
      {
        try
          {
            k.check();
          }
        catch (const InputError &e)
          {
            // "knife geometry: <problem>" -> "FILE: Knife: <problem>"
            const std::string what = e.what();
            throw InputError(file.file_name(), "Knife: " + what.substr(what.find(": ") + 2));
          }
        // the meshing budget, before Gmsh is asked (the plate's volume is an upper bound)
        const double cells = fem::estimated_cells(k.length * k.height * k.thickness, kp.mesh_size);
        if (kp.file_settings.max_cells > 0 && cells > kp.file_settings.max_cells)
          {
            char text[300];
            std::snprintf(text, sizeof text,
                          "%.3g m needs about %.3g tetrahedra for this knife, more than Maximum cells = %.3g; a "
                          "Mesh size of %.3g m needs about half the limit",
                          kp.mesh_size, cells, kp.file_settings.max_cells,
                          kp.mesh_size * std::cbrt(cells / (0.5 * kp.file_settings.max_cells)));
            file.fail({"Knife"}, "Mesh size", text);
          }
      }
    return kp;
  }

  dem::TriangleMesh wall_mesh(const fem::SolidSurface &surface, const Eigen::Matrix3d &linear,
                              const dem::Vec3 &offset)
  {
    dem::TriangleMesh m;
    for (const auto &p : surface.vertices)
      m.vertices.push_back(linear * dem::Vec3(p[0], p[1], p[2]) + offset);
    for (const auto &t : surface.triangles)
      m.triangles.push_back({int(t[0]), int(t[1]), int(t[2])});
    return m;
  }

  dem::TriangleMesh place_surface(const fem::SolidSurface &surface, const DemCase::WallCase &wc)
  {
    return wall_mesh(surface, wc.rotation, wc.offset);
  }

  void fill_solid_model_walls(DemCase &c, ParameterFile &file, const std::string &directory)
  {
    if (std::none_of(c.walls.begin(), c.walls.end(), [](const auto &w) { return w.solid_model; }))
      return;
    init_mpi_once();
    const KnifeParameters    kp = read_knife_parameters(file);
    dealii::Triangulation<3> tria;
    if (!kp.from_file)
      kp.geometry.mesh(tria, kp.mesh_size, directory + "/knife.msh");
    else
      {
        if (kp.file.empty())
          file.fail({"Knife"}, "File", "Geometry = file needs a solid file");
        fem::read_solid(kp.file, kp.mesh_size, tria, fem::KnifeGeometry::wearable_boundary, kp.file_settings);
      }
    const fem::SolidSurface surface = fem::extract_surface(tria);
    for (auto &wc : c.walls)
      if (wc.solid_model)
        wc.wall.mesh = place_surface(surface, wc);
  }

  void init_mpi_once()
  {
    // PETSc and the FEM need MPI; a single process here
    static int                                      argc = 1;
    static char                                     name[] = "abrade", *args[] = {name, nullptr};
    static char                                   **argv = args;
    static dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  }

  void run_knife_job(JobContext &ctx)
  {
    const KnifeParameters     kp = read_knife_parameters(ctx.parameters);
    const fem::KnifeGeometry &k  = kp.geometry;
    const double              h = kp.mesh_size, density = kp.density;

    init_mpi_once();

    dealii::Triangulation<3> tria;
    const std::string        dir = ctx.output.subdirectory("knife");
    {
      io::ScopedTimer t(ctx.timers, "mesh knife");
      if (!kp.from_file)
        k.mesh(tria, h, dir + "/knife.msh");
      else
        {
          if (kp.file.empty())
            ctx.parameters.fail({"Knife"}, "File", "Geometry = file needs a solid file");
          fem::read_solid(kp.file, h, tria, fem::KnifeGeometry::wearable_boundary, kp.file_settings);
        }
    }
    const fem::MeshQuality q = fem::mesh_quality(tria);
    const double           volume = fem::mesh_volume(tria);
    std::ostringstream     s;
    s << "Knife: " << tria.n_active_cells() << " cells, volume " << volume << " m^3, mass " << volume * density
      << " kg; min scaled Jacobian " << q.min_scaled_jacobian << ", max aspect ratio " << q.max_aspect_ratio;
    ctx.log.line(s.str());
    if (q.n_inverted > 0)
      throw RunError("the knife mesh has " + std::to_string(q.n_inverted) + " inverted cells (cell " +
                     std::to_string(q.worst_cell) + " is the worst)");

    fem::SolidOutput out(dir, "knife");
    out.write(tria, {{"scaled_jacobian", fem::cell_scaled_jacobians(tria)}}, 0.0);
    const fem::SolidSurface surface = fem::extract_surface(tria);
    io::write_stl(dir + "/knife.stl", surface.as_polydata());

    io::Json &r                  = ctx.results["knife"];
    r["cells"]                   = static_cast<long>(tria.n_active_cells());
    r["volume"]                  = volume;
    r["mass"]                    = volume * density;
    r["surface_area"]            = surface.area();
    r["surface_triangles"]       = static_cast<long>(surface.triangles.size());
    r["min_scaled_jacobian"]     = q.min_scaled_jacobian;
    r["max_aspect_ratio"]        = q.max_aspect_ratio;
    if (!kp.from_file)
      r["analytic_volume"] = k.volume();
  }
} // namespace abrade::coupling
