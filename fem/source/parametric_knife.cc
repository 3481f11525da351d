// Parametric grab knives meshed with the Gmsh API (OpenCASCADE kernel) into tetrahedra
// (parametric_knife.h).
#include "gmsh_session.h"
#include <abrade/common/error.h>
#include <abrade/common/termination.h>
#include <abrade/fem/parametric_knife.h>

#include "quiet_stdout.h"

#include <deal.II/base/mpi.h>
#include <deal.II/distributed/tria_base.h>
#include <deal.II/grid/grid_in.h>

#include <gmsh.h>

#include <cmath>
#include <fstream>

namespace abrade::fem
{
  std::vector<std::pair<double, double>> ParametricKnife::profile() const
  {
    const double h = thickness / 2;
    // the edge point: middle for a chisel, on the flat face for a one-sided bevel
    const double y_edge = bevel_side == BevelSide::both ? 0.0 : bevel_side == BevelSide::plus ? -h : h;
    std::vector<std::pair<double, double>> p;
    p.emplace_back(y_edge, 0.0);
    if (y_edge < h)
      p.emplace_back(h, bevel);
    if (lip_height > 0)
      {
        const double z0 = bevel + lip_offset;
        p.emplace_back(h, z0);
        p.emplace_back(h + lip_width, z0);
        p.emplace_back(h + lip_width, z0 + lip_height);
        p.emplace_back(h, z0 + lip_height);
      }
    p.emplace_back(h, height);
    p.emplace_back(-h, height);
    if (y_edge > -h)
      p.emplace_back(-h, bevel);
    return p;
  }

  double ParametricKnife::volume() const
  {
    const auto p = profile();
    double     a = 0;
    for (std::size_t k = 0; k < p.size(); ++k)
      {
        const auto &u = p[k], &v = p[(k + 1) % p.size()];
        a += u.first * v.second - v.first * u.second;
      }
    return 0.5 * std::abs(a) * length;
  }

  void ParametricKnife::check() const
  {
    auto need = [](bool ok, const std::string &what) {
      if (!ok)
        throw InputError("", "knife geometry: " + what);
    };
    need(length > 0 && height > 0 && thickness > 0, "length, height and thickness must be positive");
    need(bevel > 0 && bevel < height, "the bevel height must be positive and below the knife height");
    need(tip_radius >= 0 && tip_radius < 0.5 * thickness, "the tip radius must be below half the thickness");
    need(lip_height >= 0 && lip_width >= 0 && lip_offset >= 0, "lip dimensions must not be negative");
    need(lip_height == 0 || (lip_width > 0 && bevel + lip_offset + lip_height < height),
         "a lip needs a width, and must end below the top of the knife");
  }

  void ParametricKnife::mesh(dealii::Triangulation<3> &tria, double h, const std::string &msh_file) const
  {
    check();
    if (!(h > 0))
      throw InputError("knife geometry", "the mesh size must be positive");
    const auto p = profile();
    // on a parallel triangulation, one process runs Gmsh and all read its file
    const auto *parallel = dynamic_cast<const dealii::parallel::TriangulationBase<3> *>(&tria);
    const bool  meshing  = !parallel || dealii::Utilities::MPI::this_mpi_process(parallel->get_communicator()) == 0;
    try
      {
        if (meshing)
          build_and_mesh(p, h, msh_file);
      }
    catch (const abrade::InputError &)
      {
        throw;
      }
    catch (const std::exception &e)
      {
        gmsh::finalize();
        throw RunError(std::string("gmsh could not mesh the knife: ") + e.what());
      }
    catch (const std::string &e)
      {
        gmsh::finalize();
        throw RunError("gmsh could not mesh the knife: " + e);
      }
    catch (...)
      {
        std::string last;
        gmsh::logger::getLastError(last);
        gmsh::finalize();
        throw RunError("gmsh could not mesh the knife: " + (last.empty() ? std::string("unknown error") : last));
      }

    if (parallel)
      MPI_Barrier(parallel->get_communicator());
    // deal.II's own .msh (2.2) parser: physical surface tags become boundary ids
    dealii::GridIn<3> in;
    in.attach_triangulation(tria);
    std::ifstream file(msh_file);
    try
      {
        in.read_msh(file);
      }
    catch (const std::exception &) // the file Gmsh wrote a moment ago (a full disk cuts it)
      {
        throw RunError("cannot read back the knife mesh Gmsh wrote to " + msh_file + " (disk full?)");
      }
  }

  void ParametricKnife::build_and_mesh(const std::vector<std::pair<double, double>> &p, double h,
                                     const std::string &msh_file) const
  {
    start_gmsh();
    io::install_termination_handlers(); // (Gmsh's own ignored SIGTERM and Ctrl-C)
    gmsh::option::setNumber("General.Terminal", 0);
    const int volume_tag = build(p, h);
    mesh_built(volume_tag, h, msh_file);
  }

  void ParametricKnife::write_step(const std::string &step_file) const
  {
    check();
    start_gmsh();
    io::install_termination_handlers(); // (Gmsh's own ignored SIGTERM and Ctrl-C)
    gmsh::option::setNumber("General.Terminal", 0);
    try
      {
        build(profile(), 1.0);
        // in millimetres, the unit OpenCASCADE's STEP writer declares (read_solid converts the
        // declared unit back to metres)
        gmsh::vectorpair all;
        gmsh::model::getEntities(all, 3);
        gmsh::model::occ::dilate(all, 0, 0, 0, 1000, 1000, 1000);
        gmsh::model::occ::synchronize();
        with_stdout_silenced([&] { gmsh::write(step_file); });
      }
    catch (...)
      {
        gmsh::finalize();
        throw RunError("cannot write " + step_file);
      }
    gmsh::finalize();
  }

  int ParametricKnife::build(const std::vector<std::pair<double, double>> &p, double h) const
  {
    gmsh::model::add("knife");
    namespace occ = gmsh::model::occ;
    std::vector<int> points;
    for (const auto &[y, z] : p)
      points.push_back(occ::addPoint(0, y, z, h));
    std::vector<int> curves;
    const std::size_t n = points.size();
    if (tip_radius > 0)
      {
        // replace the edge corner (point 0) by an arc tangent to both sides
        auto unit = [](std::pair<double, double> a, std::pair<double, double> b) {
          const double dy = b.first - a.first, dz = b.second - a.second, l = std::hypot(dy, dz);
          return std::make_pair(dy / l, dz / l);
        };
        const auto   d1 = unit(p[0], p[1]), d2 = unit(p[0], p[n - 1]);
        const double half = 0.5 * std::acos(d1.first * d2.first + d1.second * d2.second);
        const double t    = tip_radius / std::tan(half);         // corner to tangent points
        const double c    = tip_radius / std::sin(half);         // corner to the arc's centre
        const std::pair<double, double> bis{(d1.first + d2.first), (d1.second + d2.second)};
        const double bl = std::hypot(bis.first, bis.second);
        const int a  = occ::addPoint(0, p[0].first + t * d1.first, p[0].second + t * d1.second, h);
        const int b  = occ::addPoint(0, p[0].first + t * d2.first, p[0].second + t * d2.second, h);
        const int ce = occ::addPoint(0, p[0].first + c * bis.first / bl, p[0].second + c * bis.second / bl, h);
        curves.push_back(occ::addCircleArc(b, ce, a));
        curves.push_back(occ::addLine(a, points[1]));
        for (std::size_t k = 1; k + 1 < n; ++k)
          curves.push_back(occ::addLine(points[k], points[k + 1]));
        curves.push_back(occ::addLine(points[n - 1], b));
        occ::remove({{0, points[0]}});
      }
    else
      for (std::size_t k = 0; k < n; ++k)
        curves.push_back(occ::addLine(points[k], points[(k + 1) % n]));
    const int loop    = occ::addCurveLoop(curves);
    const int section = occ::addPlaneSurface({loop});
    gmsh::vectorpair extruded;
    occ::extrude({{2, section}}, length, 0, 0, extruded);
    occ::synchronize();

    int volume_tag = -1;
    for (const auto &[dim, tag] : extruded)
      if (dim == 3)
        volume_tag = tag;
    return volume_tag;
  }

  void ParametricKnife::mesh_built(int volume_tag, double h, const std::string &msh_file) const
  {
    // physical groups: the volume, the clamped top face (z = height), the wearable rest
    std::vector<int> wearable, clamped;
    gmsh::vectorpair surfaces;
    gmsh::model::getEntities(surfaces, 2);
    for (const auto &[dim, tag] : surfaces)
      {
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(dim, tag, x0, y0, z0, x1, y1, z1);
        // OpenCASCADE pads bounding boxes by ~1e-7
        (std::abs(z0 - height) < 1e-5 * height && std::abs(z1 - height) < 1e-5 * height ? clamped : wearable)
          .push_back(tag);
      }
    gmsh::model::addPhysicalGroup(3, {volume_tag}, 1);
    gmsh::model::addPhysicalGroup(2, wearable, wearable_boundary);
    gmsh::model::addPhysicalGroup(2, clamped, clamped_boundary);
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * h);
    gmsh::option::setNumber("Mesh.MshFileVersion", 2.2); // deal.II maps its physical tags to boundary ids
    gmsh::option::setNumber("Mesh.Optimize", 1); // Gmsh's own tetrahedral optimiser
    gmsh::model::mesh::generate(3);
    gmsh::write(msh_file);
    gmsh::finalize();
  }
} // namespace abrade::fem
