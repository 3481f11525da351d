// Subsection Part: the parametric knife or a user's part (part_parameters.h), meshed, its faces
// chosen, and placed as the DEM's walls.
#include <abrade/dem/parameter_section.h>
#include <abrade/common/error.h>
#include <abrade/common/format_number.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/parameters/parameter_section.h>
#include <abrade/fem/mpi_once.h>

#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>

namespace abrade::coupling
{
  namespace
  {
    dealii::Tensor<1, 3> get_tensor(dealii::ParameterHandler &prm, const std::string &name)
    {
      const dem::Vec3 v = vector_entry(prm, name);
      return dealii::Tensor<1, 3>({v[0], v[1], v[2]});
    }

    std::vector<fem::FaceSelector> get_selectors(ParameterFile &file, dealii::ParameterHandler &prm,
                                                 const std::string &name)
    {
      try
        {
          return fem::parse_face_selectors(prm.get(name));
        }
      catch (const std::invalid_argument &e)
        {
          prm.leave_subsection();
          file.fail({"Part"}, name, e.what());
        }
    }

  } // namespace

  void declare_part_parameters(dealii::ParameterHandler &prm)
  {
    using dealii::Patterns::Anything;
    using dealii::Patterns::Double;
    using dealii::Patterns::Selection;
    PluginSection section(prm);
    prm.enter_subsection("Part");
    prm.declare_entry("Geometry", "parametric", Selection("parametric|file"),
                      "parametric: the grab knife below; file: a solid from File (.msh, .step/.stp, "
                      ".iges/.igs, or a closed .stl).");
    prm.declare_entry("File", "", Anything(), "Solid file when Geometry = file; relative to the parameter file.");
    prm.declare_entry("Length", "0.4", Double(1e-6, dem::unbounded), "[m] Knife length (x). Range: > 0.");
    prm.declare_entry("Height", "0.5", Double(1e-6, dem::unbounded), "[m] Knife height (z). Range: > 0.");
    prm.declare_entry("Thickness", "0.03", Double(1e-6, dem::unbounded), "[m] Plate thickness (y). Range: > 0.");
    prm.declare_entry("Bevel height", "0.04", Double(1e-6, dem::unbounded),
                      "[m] Height of the bevel that forms the edge; with the thickness it sets the "
                      "edge angle. Range: (0, Height).");
    prm.declare_entry("Bevel side", "both", selection_of(bevel_sides),
                      "both: chisel edge in the middle; plus / minus: bevel on the +y / -y face only.");
    prm.declare_entry("Tip radius", "0", Double(0, dem::unbounded), "[m] Rounding of the edge; 0: sharp. Range: [0, Thickness/2).");
    prm.declare_entry("Lip height", "0", Double(0, dem::unbounded),
                      "[m] Height of a ridge on the +y face above the bevel that holds back a "
                      "protective layer of material; 0: none. Range: >= 0.");
    prm.declare_entry("Lip width", "0", Double(0, dem::unbounded), "[m] How far the ridge stands out of the face. Range: >= 0.");
    prm.declare_entry("Lip offset", "0", Double(0, dem::unbounded), "[m] Distance of the ridge above the bevel. Range: >= 0.");
    prm.declare_entry("Mesh size", "0.015", Double(1e-6, dem::unbounded), "[m] Target tetrahedron size. Range: > 0.");
    prm.declare_entry("File scale", "1", Double(1e-12, dem::unbounded),
                      "[-] Geometry = file: multiplies the file's coordinates. STL and .msh files have no unit "
                      "(0.001: the file is in millimetres); STEP/IGES files declare theirs, which is converted "
                      "to metres on import (leave 1; another value multiplies on top, with a warning). A .msh "
                      "of hexahedra is split into tetrahedra. Range: > 0.");
    prm.declare_entry("Maximum cells", "3000000", Double(0, dem::unbounded),
                      "[-] Refuse a part that would need more tetrahedra than this (estimated before meshing "
                      "from its volume and Mesh size: about 8.5 V / h^3), with a Mesh size that fits; 0: no "
                      "limit. Range: >= 0.");
    prm.declare_entry("Density", "7800", Double(1e-6, dem::unbounded), "[kg/m^3] Density of the part's steel (mass). Range: > 0.");
    prm.declare_entry("Solid", "all", Anything(),
                      "Geometry = file, a CAD file with several solids: 'all' takes them all as one part, a "
                      "number the solid of that number (the part job lists them).");
    section.declare_vector("Rotation axis", {0, 0, 1},
                   "[-] Geometry = file: the axis of the rotation that brings the part from the file's "
                   "(assembly) coordinates into the part's frame (edge along x at the bottom, height along "
                   "z); through the origin, right-handed. A mounted part is then centred on its shell's lip "
                   "along x and z by its bounding box; across the lip its y = 0 plane lies on the lip's line.");
    prm.declare_entry("Rotation angle", "0", Double(-360, 360),
                      "[deg] Geometry = file: the angle of that rotation. The part's point p becomes "
                      "R (File scale x p) + Offset: scaled, rotated about the origin, then moved. Range: "
                      "[-360, 360].");
    section.declare_vector("Offset", {0, 0, 0}, "[m] Geometry = file: moves the part after its rotation.");
    prm.declare_entry("Place", "", Anything(),
                      "Geometry = file: moves the rotated part by its bounding box before Offset, so that a "
                      "part from a CAD assembly need not be measured first: ','-separated 'centred' (the box's "
                      "centre to x = y = 0), 'centred in x' (or y, z), 'lowest point at z = V' [m]; e.g. "
                      "'lowest point at z = 0, centred'. The move is logged. Empty: none.");
    prm.declare_entry("Clamped faces", "", Anything(),
                      "Geometry = file: the faces bolted or welded to the shell, which the mesh motion holds "
                      "and which do not wear; selectors separated by ';': 'group NAME' (a physical group of "
                      "a .msh, by name or number, or a CAD face by its number), 'box x0, y0, z0, x1, y1, z1' "
                      "(faces whose centre lies in the box, in metres, in the part's frame after scale and "
                      "placement), 'normal nx, ny, nz[, angle]' (faces whose outward normal is within angle "
                      "degrees, default 10, of the direction), 'cylinder px, py, pz, ax, ay, az, r[, tolerance]' "
                      "(faces on the cylinder of radius r about the axis through p along a: a bore or a pin, "
                      "whose CAD face may be split in halves; the facets' centres r from the axis within the "
                      "tolerance, default 0.15 r, their normals across it). Empty: none (every face wears). "
                      "The part job lists the part's faces.");
    prm.declare_entry("Wearable faces", "", Anything(),
                      "Geometry = file: the faces that wear (selectors as for Clamped faces); faces that "
                      "neither list takes are held. Empty: every face that is not clamped wears.");
    prm.declare_entry("Minimum mesh quality", "0.05", Double(0, 1),
                      "[-] Geometry = file: a mesh whose smallest scaled Jacobian is below this is optimised "
                      "once more (Gmsh's optimisers, harder) and, if still below, reported with the place of "
                      "its worst cell. Range: [0, 1].");
    prm.leave_subsection();
  }

  namespace
  {
    /// The parametric knife of @p part: its geometry, its meshing budget before Gmsh is asked,
    /// and no entry that only a part from a file has (face selectors, placement).
    void check_parametric_knife(ParameterFile &file, const PartParameters &part)
    {
      const auto &k  = part.geometry;
      const auto &fs = part.file_settings;
      try
        {
          k.check();
        }
      catch (const InputError &e)
        {
          // "knife geometry: <problem>" -> "FILE: Part: <problem>"
          const std::string what = e.what();
          throw InputError(file.file_name(), "Part: " + what.substr(what.find(": ") + 2));
        }
      // the meshing budget, before Gmsh is asked (the plate's volume is an upper bound)
      const double cells = fem::estimated_cells(k.length * k.height * k.thickness, part.mesh_size);
      if (fs.max_cells > 0 && cells > fs.max_cells)
        {
          char text[300];
          std::snprintf(text, sizeof text,
                        "%.3g m needs about %.3g tetrahedra for this part, more than Maximum cells = %.3g; a "
                        "Mesh size of %.3g m needs about half the limit",
                        part.mesh_size, cells, fs.max_cells, part.mesh_size * std::cbrt(cells / (0.5 * fs.max_cells)));
          file.fail({"Part"}, "Mesh size", text);
        }
      if (!part.clamped_faces.empty() || !part.wearable_faces.empty())
        file.fail({"Part"}, part.clamped_faces.empty() ? "Wearable faces" : "Clamped faces",
                  "the parametric knife's clamped face is its top (bolted to the shell); face selectors are for "
                  "Geometry = file");
      // the parametric knife is built in the part's frame: nothing to place
      if (fs.rotation_angle != 0)
        file.fail({"Part"}, "Rotation angle", "the parametric knife is built in the part's frame: placement is for Geometry = file");
      if (fs.offset.norm() > 0)
        file.fail({"Part"}, "Offset", "the parametric knife is built in the part's frame: placement is for Geometry = file");
      if (!fs.place.text.empty())
        file.fail({"Part"}, "Place", "the parametric knife is built in the part's frame: placement is for Geometry = file");
    }
  } // namespace

  double read_part_length(ParameterFile &file)
  {
    auto &prm = file.handler();
    prm.enter_subsection("Part");
    const double length = prm.get_double("Length");
    prm.leave_subsection();
    return length;
  }

  PartParameters read_part_parameters(ParameterFile &file)
  {
    auto           &prm = file.handler();
    PartParameters  part;
    auto           &k = part.geometry;
    prm.enter_subsection("Part");
    k.length     = prm.get_double("Length");
    k.height     = prm.get_double("Height");
    k.thickness  = prm.get_double("Thickness");
    k.bevel      = prm.get_double("Bevel height");
    k.bevel_side = get_choice(prm, "Bevel side", bevel_sides);
    k.tip_radius = prm.get_double("Tip radius");
    k.lip_height = prm.get_double("Lip height");
    k.lip_width  = prm.get_double("Lip width");
    k.lip_offset = prm.get_double("Lip offset");
    part.mesh_size = prm.get_double("Mesh size");
    part.density   = prm.get_double("Density");
    part.from_file = prm.get("Geometry") == "file";
    part.file      = prm.get("File");
    auto &fs     = part.file_settings;
    fs.scale          = prm.get_double("File scale");
    fs.max_cells      = prm.get_double("Maximum cells");
    fs.max_volume     = 1e6 / part.density; // 1,000 t: no knife, liner or tooth weighs that
    fs.solid          = dealii::Utilities::trim(prm.get("Solid"));
    fs.min_quality    = prm.get_double("Minimum mesh quality");
    fs.rotation_axis  = get_tensor(prm, "Rotation axis");
    fs.rotation_angle = prm.get_double("Rotation angle");
    fs.offset         = get_tensor(prm, "Offset");
    try
      {
        fem::parse_part_placement(prm.get("Place"), fs);
      }
    catch (const std::invalid_argument &e)
      {
        prm.leave_subsection();
        file.fail({"Part"}, "Place", e.what());
      }
    part.clamped_faces  = get_selectors(file, prm, "Clamped faces");
    part.wearable_faces = get_selectors(file, prm, "Wearable faces");
    prm.leave_subsection();
    if (part.from_file && fs.rotation_angle != 0 && !(fs.rotation_axis.norm() > 0))
      file.fail({"Part"}, "Rotation axis", "must not be zero");
    if (part.from_file)
      part.file = file.path_beside(part.file);
    if (part.from_file && part.file.empty())
      file.fail({"Part"}, "File", "Geometry = file needs a solid file");
    if (!part.from_file)
      check_parametric_knife(file, part);
    else if (!fem::is_cad_file(part.file) && fs.solid != "all" && !fs.solid.empty())
      file.fail({"Part"}, "Solid", "only a CAD file (STEP/IGES) can hold several solids; " + part.file + " is read whole");
    return part;
  }

  PartMesh mesh_part(const PartParameters &part, ParameterFile &file, const std::string &directory)
  {
    PartMesh m;
    m.tria = std::make_unique<dealii::Triangulation<3>>();
    if (!part.from_file)
      {
        part.geometry.mesh(*m.tria, part.mesh_size, directory + "/part.msh");
        return m;
      }
    fem::SolidFileSettings settings = part.file_settings;
    settings.work_directory         = directory; // the run's own (nothing written outside it)
    m.report     = fem::read_solid(part.file, part.mesh_size, *m.tria, settings);
    m.file_faces = fem::part_faces(*m.tria, m.report.face_names);
    try
      {
        m.faces = fem::assign_faces(*m.tria, part.clamped_faces, part.wearable_faces, m.report.face_names,
                                    fem::wearable_boundary, fem::clamped_boundary);
      }
    catch (const std::invalid_argument &e)
      {
        std::string faces;
        for (const auto &f : m.file_faces)
          if (faces.size() < 600)
            faces += (faces.empty() ? "" : "; ") + std::to_string(f.id) + (f.name.empty() ? "" : " '" + f.name + "'") +
                     " at (" + io::format_number(f.centre[0]) + ", " + io::format_number(f.centre[1]) + ", " + io::format_number(f.centre[2]) + ")";
        const std::string what = e.what();
        file.fail({"Part"}, what.rfind("Wearable faces:", 0) == 0 ? "Wearable faces" : "Clamped faces",
                  (what.rfind("Wearable faces: ", 0) == 0 || what.rfind("Clamped faces: ", 0) == 0
                     ? what.substr(what.find(':') + 2)
                     : what) +
                    "; the part's faces: " + faces);
      }
    return m;
  }

  void report_part_mesh(const PartParameters &part, const PartMesh &m, io::Log &log, std::vector<std::string> *warnings)
  {
    if (!part.from_file)
      return;
    for (const auto &n : m.report.notes)
      log.line("Part: " + part.file + ": " + n);
    std::ostringstream faces;
    faces << "Part: " << m.file_faces.size() << " faces in the file; wearable " << m.faces.wearable_area
          << " m^2, clamped " << m.faces.clamped_area << " m^2"
          << (part.clamped_faces.empty() && part.wearable_faces.empty() ? " (no Clamped faces given: every face wears)" : "");
    log.line(faces.str());
    for (const auto &t : m.faces.taken) // which faces each selector took (summary.json: selectors)
      {
        std::string ids;
        for (const auto id : t.faces)
          ids += (ids.empty() ? "" : ", ") + std::to_string(id);
        log.line("Part: " + t.list + " '" + t.selector + "' took " + io::format_number(t.area) + " m^2 of face(s) " +
                 ids);
      }
    for (const auto &w : m.report.warnings)
      {
        log.warning("Part: " + part.file + ": " + w);
        if (warnings)
          warnings->push_back(part.file + ": " + w);
      }
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

  std::string fit_mounted_parts(DemCase &c, const fem::SolidSurface &design)
  {
    if (design.vertices.empty())
      return {};
    double x0 = design.vertices[0][0], x1 = x0, z0 = design.vertices[0][2], y0 = design.vertices[0][1], y1 = y0;
    for (const auto &p : design.vertices)
      x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), z0 = std::min(z0, p[2]), y0 = std::min(y0, p[1]),
      y1 = std::max(y1, p[1]);
    const bool mounted = std::any_of(c.walls.begin(), c.walls.end(), [](const auto &w) { return w.solid_model && !w.mount.empty(); });
    for (auto &wc : c.walls)
      if (wc.solid_model && !wc.mount.empty())
        {
          // mount_parts placed x = length / 2 at the lip's centre and z = 0 'protrusion' beyond it
          const double length = c.mounted_part_length;
          wc.offset += wc.rotation * dem::Vec3(0.5 * length - 0.5 * (x0 + x1), 0, -z0);
        }
    if (mounted && !(y0 < 0 && y1 > 0))
      return "the mounted part lies at y = " + io::format_number(y0) + " ... " + io::format_number(y1) +
             " m in the part's frame: its y = 0 plane is put on the lip's line (the middle of the plate "
             "should be there); Part/Offset moves it";
    return {};
  }

  void fill_solid_model_walls(DemCase &c, ParameterFile &file, const std::string &directory, io::Log &log)
  {
    if (std::none_of(c.walls.begin(), c.walls.end(), [](const auto &w) { return w.solid_model; }))
      return;
    fem::init_mpi_once();
    const PartParameters   part = read_part_parameters(file);
    const PartMesh         m  = mesh_part(part, file, directory);
    report_part_mesh(part, m, log);
    const fem::SolidSurface surface = fem::extract_surface(*m.tria);
    if (part.from_file)
      if (const std::string w = fit_mounted_parts(c, surface); !w.empty())
        log.warning(w);
    for (auto &wc : c.walls)
      if (wc.solid_model)
        wc.wall.mesh = place_surface(surface, wc);
  }

} // namespace abrade::coupling
