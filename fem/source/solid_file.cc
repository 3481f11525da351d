// Reading a user's part (solid_file.h): Gmsh for CAD, STL and the physical names of .msh files,
// deal.II's GridIn for the volume mesh.
#include "gmsh_session.h"
#include <abrade/common/error.h>
#include <abrade/common/input_file.h>
#include <abrade/common/temporary_directory.h>
#include <abrade/common/file_extension.h>
#include <abrade/common/finite_number.h>
#include <abrade/common/format_number.h>
#include <abrade/common/termination.h>
#include <abrade/common/vtk_input.h>
#include <abrade/fem/cad_check.h>
#include <abrade/fem/meshing_job.h>
#include <abrade/fem/part_faces.h>
#include <abrade/fem/solid_file.h>
#include <abrade/fem/solid_output.h>
#include <abrade/fem/surface_repair.h>
#include <abrade/fem/triangle_folds.h>

#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/physics/transformations.h>

#include <gmsh.h>
#include <vtkPolyData.h>

#include "quiet_stdout.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <unistd.h>

namespace abrade::fem
{
  using namespace dealii;
  using io::format_number;
  using io::lower_extension;

  namespace
  {
    /// A warning among the notes a meshing job returns.
    const std::string warning_prefix = "warning: ";
    /// The number of solids in the file, among the notes.
    const std::string solids_prefix = "solids in the file: ";
    /// ... and the name of a physical surface group of a .msh file: "face name: ID NAME"
    const std::string face_name_prefix = "face name: ";

    void read_msh_file(const std::string &path, Triangulation<3> &tria)
    {
      std::ifstream file(path);
      GridIn<3>     in;
      in.attach_triangulation(tria);
      try
        {
          in.read_msh(file); // deal.II's own parser: physical surface tags become boundary ids
        }
      catch (const std::exception &e)
        {
          std::string what = e.what();
          // deal.II's messages are long: what is wrong, without the stack trace, on one line
          const auto at = what.find("Additional information:");
          if (at != std::string::npos)
            what = what.substr(at + 23);
          what = what.substr(0, what.find("Stacktrace"));
          std::string line;
          for (const char c : what)
            if (!std::isspace(static_cast<unsigned char>(c)) || (!line.empty() && line.back() != ' '))
              line += std::isspace(static_cast<unsigned char>(c)) ? ' ' : c;
          while (!line.empty() && line.back() == ' ')
            line.pop_back();
          throw InputError(path, "not a readable Gmsh volume mesh: " + line.substr(0, 400));
        }
      if (tria.n_active_cells() == 0)
        throw InputError(path, "the mesh holds no volume elements (tetrahedra or hexahedra)");
    }

    /// Runs @p f on a fresh Gmsh session; a Gmsh error becomes an InputError naming @p label and
    /// saying what Gmsh could not @p do.
    template <typename F>
    void with_gmsh(const std::string &label, F &&f, const std::string &doing = "mesh it")
    {
      start_gmsh();
      io::install_termination_handlers(); // (Gmsh installs its own, which ignored SIGTERM and Ctrl-C)
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
          throw InputError(label, "Gmsh could not " + doing + ": " + (last.empty() ? std::string("unknown error") : last));
        }
      gmsh::finalize();
    }

    /// A user's .msh file, read by Gmsh (whose reader knows every .msh version and stops on a
    /// broken file; deal.II's looped forever on a cut one) and written again as .msh 2.2 to
    /// @p clean, for deal.II. Returns the names of its physical surfaces, by tag.
    std::map<types::boundary_id, std::string> normalise_msh(const std::string &path, const std::string &clean)
    {
      std::map<types::boundary_id, std::string> names;
      with_gmsh(path, [&] {
        gmsh::open(path);
        std::vector<std::size_t> tags;
        std::vector<double>      xyz, parametric;
        gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
        for (std::size_t k = 0; k < xyz.size(); ++k)
          if (!std::isfinite(xyz[k]))
            throw InputError(path, "node " + std::to_string(tags[k / 3]) + " has a coordinate that is not a finite number");
        std::vector<int>                      types;
        std::vector<std::vector<std::size_t>> elements, nodes;
        gmsh::model::mesh::getElements(types, elements, nodes, 3, -1);
        if (types.empty())
          throw InputError(path, "the mesh holds no volume elements (tetrahedra or hexahedra)");
        gmsh::vectorpair groups;
        gmsh::model::getPhysicalGroups(groups, 2);
        for (const auto &[dim, tag] : groups)
          {
            std::string name;
            gmsh::model::getPhysicalName(dim, tag, name);
            if (!name.empty())
              names[types::boundary_id(tag)] = name;
          }
        // Gmsh writes the elements of physical groups (with their tags, deal.II's boundary ids);
        // the volume, if the file gives it no group, gets one
        gmsh::vectorpair volume_groups;
        gmsh::model::getPhysicalGroups(volume_groups, 3);
        if (volume_groups.empty())
          {
            gmsh::vectorpair volumes;
            gmsh::model::getEntities(volumes, 3);
            std::vector<int> vtags;
            for (const auto &v : volumes)
              vtags.push_back(v.second);
            gmsh::model::addPhysicalGroup(3, vtags);
          }
        gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
        gmsh::write(clean);
      }, "read it");
      return names;
    }

    /// Gmsh: the volumes of the current model -> tetrahedra -> .msh 2.2. Every surface that
    /// bounds the part (one volume on its side) is a physical group of its own number, which
    /// deal.II reads as the boundary id: the file's face numbers. @p again: a second, harder
    /// optimisation (after a first mesh was poor).
    /// @p curved: at least 12 elements around a full circle of a curved face (a bolt hole of a
    /// CAD part; STL facets have no curvature to follow).
    /// @p fill: the surface's own triangles are filled as they are (a worn surface built as a
    /// set: many small triangles of marching cubes) by HXT without Gmsh's optimiser: 2.2 s on a
    /// chisel's 17,000 triangles, where the Delaunay mesher took 11 s and either with the
    /// optimiser over 60 s (it ran into the 120 s limit and the update failed); the cells'
    /// quality is checked by the caller as any mesh's is.
    void mesh_volume_with_gmsh(const std::string &label, double h, const std::string &msh, bool again, bool curved,
                               bool fill = false)
    {
      gmsh::vectorpair volumes;
      gmsh::model::getEntities(volumes, 3);
      if (volumes.empty())
        throw InputError(label, "the geometry encloses no volume (is the surface closed?)");
      gmsh::vectorpair surfaces;
      gmsh::model::getEntities(surfaces, 2);
      std::vector<int> vtags;
      for (const auto &v : volumes)
        vtags.push_back(v.second);
      gmsh::model::addPhysicalGroup(3, vtags, 1);
      for (const auto &f : surfaces)
        {
          std::vector<int> up, down;
          gmsh::model::getAdjacencies(2, f.second, up, down);
          if (up.size() <= 1) // not a face between two solids of one part
            gmsh::model::addPhysicalGroup(2, {f.second}, f.second);
        }
      gmsh::option::setNumber("Mesh.MeshSizeMax", h);
      gmsh::option::setNumber("Mesh.MeshSizeMin", 0.1 * h);
      gmsh::option::setNumber("Mesh.MshFileVersion", 2.2);
      gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", curved ? 12 : 0);
      gmsh::option::setNumber("Mesh.Optimize", 1);
      // again: the other tetrahedral mesher (HXT), whose meshes of thin plates keep no slivers
      // where the Delaunay mesher's do (a 30 mm plate at 20 mm: scaled Jacobian 3.5e-5 -> 0.2),
      // then Gmsh's optimisers on every cell below 0.5 (Debian's Gmsh has no Netgen optimiser)
      gmsh::option::setNumber("Mesh.Algorithm3D", again || fill ? 10 : 1);
      // HXT on one thread: with more its mesh depends on the threads' timing (the child's
      // addresses are fixed for the rest: meshing_job.cc), and its threads spin on a busy
      // machine (two threads under a load of 6 on two cores ran into the 120 s limit); on two
      // idle cores a fill took 3.5 s instead of 3.3 s
      gmsh::option::setNumber("General.NumThreads", 1);
      gmsh::option::setNumber("Mesh.MaxNumThreads3D", 1);
      if (fill && !again)
        gmsh::option::setNumber("Mesh.Optimize", 0);
      gmsh::model::mesh::generate(3);
      if (again)
        {
          gmsh::option::setNumber("Mesh.OptimizeThreshold", 0.5);
          gmsh::model::mesh::optimize("Relocate3D", true, 5);
          gmsh::model::mesh::optimize("", true, 5);
        }
      gmsh::write(msh);
    }

    /// Loads the shapes of a STEP or IGES file into the current Gmsh model, in metres:
    /// OpenCASCADE converts the unit the file declares to millimetres (its default), which is
    /// scaled here to metres. (Gmsh 4.8's Geometry.OCCTargetUnit does not change that.)
    void import_cad(const std::string &path)
    {
      check_cad_file(path);
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

    /// A CAD file of faces and no solid (a surface model, as IGES files often are): the faces
    /// sewn into one closed shell (their shared edges matched geometrically) and the volume it
    /// encloses, said in @p report; an error naming the file when they do not close.
    void sew_faces_into_a_solid(const std::string &path, SolidFileReport &report)
    {
      gmsh::vectorpair volumes, faces;
      gmsh::model::getEntities(volumes, 3);
      gmsh::model::getEntities(faces, 2);
      if (!volumes.empty() || faces.empty())
        return;
      std::vector<int> tags;
      for (const auto &f : faces)
        tags.push_back(f.second);
      try
        {
          const int shell = gmsh::model::occ::addSurfaceLoop(tags, -1, true);
          gmsh::model::occ::addVolume({shell});
          gmsh::model::occ::synchronize();
        }
      catch (...)
        {
          throw InputError(path, "holds " + std::to_string(faces.size()) +
                                   " faces and no solid, and the faces do not sew into a closed shell");
        }
      report.notes.push_back("no solid in the file: its " + std::to_string(faces.size()) +
                             " faces sewn into a closed shell and the volume it encloses");
    }

    /// Keeps the solid @p choice ("" or "all": all of them, fused into one conforming part) of
    /// the current model; says which in @p report.
    void choose_solid(const std::string &path, const std::string &choice, SolidFileReport &report)
    {
      gmsh::vectorpair volumes;
      gmsh::model::getEntities(volumes, 3);
      report.n_solids = unsigned(volumes.size());
      std::string list;
      for (const auto &v : volumes)
        {
          double m = 0;
          gmsh::model::occ::getMass(3, v.second, m);
          list += (list.empty() ? "" : ", ") + std::to_string(v.second) + " (" + format_number(m) + " m^3)";
        }
      if (choice.empty() || choice == "all")
        {
          if (volumes.size() > 1)
            {
              gmsh::vectorpair out;
              std::vector<gmsh::vectorpair> map;
              gmsh::model::occ::fragment(volumes, {}, out, map);
              gmsh::model::occ::synchronize();
              report.notes.push_back(std::to_string(volumes.size()) + " solids (" + list +
                                     "), all taken as one part (Part/Solid = NUMBER takes one)");
            }
          return;
        }
      std::size_t used = 0;
      int         tag  = -1;
      try
        {
          tag = std::stoi(choice, &used);
        }
      catch (const std::exception &)
        {
          used = 0;
        }
      const bool known = used == choice.size() && std::any_of(volumes.begin(), volumes.end(),
                                                                  [&](const auto &v) { return v.second == tag; });
      if (!known)
        throw InputError(path, "Part/Solid = '" + choice + "' is not one of its solids: " +
                                 (list.empty() ? std::string("it holds none") : list) + " (or 'all')");
      gmsh::vectorpair others;
      for (const auto &v : volumes)
        if (v.second != tag)
          others.push_back(v);
      if (!others.empty())
        {
          gmsh::model::occ::remove(others, true);
          gmsh::model::occ::synchronize();
        }
      report.notes.push_back("solid " + choice + " of " + std::to_string(volumes.size()) + " (" + list + ")");
    }

    /// Refuses a part whose size is implausible for its unit, naming its bounding box (in metres,
    /// after @p scale) and the likely scale.
    void check_extent(const std::string &path, const std::array<double, 6> &box, double scale,
                      const SolidFileSettings &s, bool has_units)
    {
      double extent[3], largest = 0;
      for (int k = 0; k < 3; ++k)
        largest = std::max(largest, extent[k] = scale * (box[k + 3] - box[k]));
      if (!std::isfinite(largest))
        throw InputError(path, "the part has coordinates that are not finite numbers");
      const std::string size = format_number(extent[0]) + " x " + format_number(extent[1]) + " x " +
                               format_number(extent[2]) + " m";
      // a CAD file's unit is converted on import: its File scale (s.scale) multiplies on top
      const double      now = has_units ? s.scale : scale;
      const std::string fix =
        has_units ? (s.scale != 1 ? "the file declares its unit, which is converted: is Part/File scale = " +
                                      format_number(s.scale) + " meant? (1 reads it as declared); or set it"
                                  : "check the unit the file declares, or set Part/File scale")
                  : "set Part/File scale (the file has no unit)";
      // a box a million times larger than its smallest side is no part in another unit: a point
      // far from the rest (a corrupt coordinate)
      const double smallest = std::min({extent[0], extent[1], extent[2]});
      if (largest > s.max_extent && smallest > 0 && largest > 1e6 * smallest)
        throw InputError(path, "the part's bounding box is " + size + ": a point lies far from the others (a "
                                 "corrupt coordinate?), no change of unit makes it a part");
      if (largest > s.max_extent)
        throw InputError(path, "the part's bounding box is " + size + ", larger than " + format_number(s.max_extent) +
                                 " m: is it in millimetres? " + fix + " = " + format_number(0.001 * now));
      if (largest < s.min_extent)
        throw InputError(path, "the part's bounding box is " + size + ", smaller than " + format_number(s.min_extent) +
                                 " m: is it in metres read as millimetres? " + fix + " = " + format_number(1000 * now));
    }

    /// Refuses a part that is implausibly heavy, or that would need more than the allowed
    /// tetrahedra (with the estimate and a mesh size that fits).
    void check_volume(const std::string &path, double volume, double h, const SolidFileSettings &s)
    {
      if (s.max_volume > 0 && volume > s.max_volume)
        throw InputError(path, "the part's volume is " + format_number(volume) + " m^3, more than " +
                                 format_number(s.max_volume) +
                                 " m^3 (the mass limit at its density): is it in millimetres? set Part/File scale");
      if (s.max_cells <= 0 || h <= 0)
        return;
      const double cells = estimated_cells(volume, h);
      if (cells > s.max_cells)
        throw InputError(path, "meshing the part (" + format_number(volume) + " m^3) with Part/Mesh size " +
                                 format_number(h) + " m needs about " + format_number(cells) +
                                 " tetrahedra, more than Part/Maximum cells = " + format_number(s.max_cells) +
                                 "; a Mesh size of " + format_number(h * std::cbrt(cells / (0.5 * s.max_cells))) +
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

    /// The current Gmsh model from a CAD file, in metres, the solid chosen and checked.
    void load_cad(const std::string &path, double h, const SolidFileSettings &settings, SolidFileReport &report)
    {
      import_cad(path);
      sew_faces_into_a_solid(path, report);
      choose_solid(path, settings.solid, report);
      if (settings.scale != 1)
        {
          report.warnings.push_back("Part/File scale = " + format_number(settings.scale) +
                                    " multiplies the part on top of the unit the file declares (converted to metres "
                                    "on import): 1 reads it as declared");
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
      check_volume(path, volume, h, settings);
    }

    /// Removes the slivers (folds::is_sliver: three points on or within 1e-8 of the part's size
    /// of a line, an STL exporter's) from the merged STL: Gmsh's surface mesher throws inside a
    /// parallel region on one, and the process aborts; and repeated facets. Returns how many of
    /// each were removed.
    std::pair<std::size_t, std::size_t> remove_zero_area_triangles()
    {
      std::size_t duplicates = 0;
      gmsh::vectorpair surfaces;
      gmsh::model::getEntities(surfaces, 2);
      double box[6];
      gmsh::model::getBoundingBox(-1, -1, box[0], box[1], box[2], box[3], box[4], box[5]);
      const double sliver_height =
        folds::sliver_height_fraction *
        std::sqrt(std::pow(box[3] - box[0], 2) + std::pow(box[4] - box[1], 2) + std::pow(box[5] - box[2], 2));
      struct Surface
      {
        int                      tag;
        std::vector<std::size_t> nodes, triangles, corners;
        std::vector<double>      xyz;
      };
      std::vector<Surface> kept;
      std::size_t          removed = 0;
      std::set<std::array<std::size_t, 3>> seen;
      for (const auto &[dim, tag] : surfaces)
        {
          Surface                  s{tag, {}, {}, {}, {}};
          std::vector<double>      parametric;
          std::vector<std::size_t> triangles, corners;
          gmsh::model::mesh::getNodes(s.nodes, s.xyz, parametric, 2, tag, true, false);
          gmsh::model::mesh::getElementsByType(2, triangles, corners, tag);
          std::map<std::size_t, std::size_t> index;
          for (std::size_t k = 0; k < s.nodes.size(); ++k)
            index[s.nodes[k]] = k;
          for (std::size_t t = 0; t < triangles.size(); ++t)
            {
              double p[3][3];
              for (int c = 0; c < 3; ++c)
                for (int d = 0; d < 3; ++d)
                  p[c][d] = s.xyz[3 * index[corners[3 * t + c]] + d];
              // a facet given twice (the same three corners, either orientation) sends METIS,
              // called from Gmsh's surface classification, into an endless loop
              std::array<std::size_t, 3> corner_set = {corners[3 * t], corners[3 * t + 1], corners[3 * t + 2]};
              std::sort(corner_set.begin(), corner_set.end());
              if (folds::is_sliver(p[0], p[1], p[2], sliver_height))
                ++removed;
              else if (!seen.insert(corner_set).second)
                ++duplicates;
              else
                {
                  s.triangles.push_back(triangles[t]);
                  s.corners.insert(s.corners.end(), corners.begin() + 3 * t, corners.begin() + 3 * t + 3);
                }
            }
          kept.push_back(std::move(s));
        }
      if (removed + duplicates == 0)
        return {0, 0};
      // the mesh again without them (nodes where they were, on the entities they were on)
      gmsh::model::mesh::clear();
      for (const auto &s : kept)
        {
          gmsh::model::mesh::addNodes(2, s.tag, s.nodes, s.xyz);
          gmsh::model::mesh::addElementsByType(s.tag, 2, s.triangles, s.corners);
        }
      return {removed, duplicates};
    }

    /// A part's STL must bound one solid: every edge shared by exactly two triangles, all of
    /// them one connected piece. Gmsh meshed nothing of a surface with a hole, of two disjoint
    /// solids or of edges shared by three or more triangles, and said only "No elements in
    /// volume 1"; here the first such edge is named.
    void check_closed_surface(const std::string &path)
    {
      std::vector<std::size_t> nodes, triangles, corners;
      std::vector<double>      xyz, parametric;
      gmsh::model::mesh::getNodes(nodes, xyz, parametric, -1, -1, true, false);
      gmsh::model::mesh::getElementsByType(2, triangles, corners, -1);
      std::map<std::size_t, std::size_t> index;
      for (std::size_t k = 0; k < nodes.size(); ++k)
        index[nodes[k]] = k;
      auto point = [&](std::size_t node) {
        const std::size_t k = index[node];
        return "(" + format_number(xyz[3 * k]) + ", " + format_number(xyz[3 * k + 1]) + ", " +
               format_number(xyz[3 * k + 2]) + ")";
      };
      std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edges; // -> triangles
      for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int c = 0; c < 3; ++c)
          {
            const std::size_t a = corners[3 * t + c], b = corners[3 * t + (c + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back(t);
          }
      std::size_t open = 0, shared = 0;
      std::string first_open, first_shared;
      for (const auto &[e, ts] : edges)
        if (ts.size() == 1 && open++ == 0)
          first_open = point(e.first) + " and " + point(e.second);
        else if (ts.size() > 2 && shared++ == 0)
          first_shared = point(e.first) + " and " + point(e.second) + " (" + std::to_string(ts.size()) + " triangles)";
      if (open > 0)
        throw InputError(path, "the surface is not closed: " + std::to_string(open) +
                                 " edge(s) belong to one triangle only, the first between " + first_open +
                                 " (a hole); a solid part needs a closed surface");
      if (shared > 0)
        throw InputError(path, std::to_string(shared) + " edge(s) are shared by more than two triangles, the first "
                                                         "between " + first_shared +
                                 ": not the surface of one solid (solids touching along an edge?)");
      // connected pieces: triangles joined across their edges
      std::vector<std::size_t> parent(triangles.size());
      for (std::size_t t = 0; t < parent.size(); ++t)
        parent[t] = t;
      auto root = [&](std::size_t t) { // (iterative, halving the paths: no recursion on a large STL)
        while (parent[t] != t)
          t = parent[t] = parent[parent[t]];
        return t;
      };
      for (const auto &[e, ts] : edges)
        parent[root(ts[0])] = root(ts[1]);
      std::set<std::size_t> pieces;
      for (std::size_t t = 0; t < parent.size(); ++t)
        pieces.insert(root(t));
      if (pieces.size() > 1)
        throw InputError(path, "the surface is " + std::to_string(pieces.size()) +
                                 " separate closed pieces: a part is one solid (give each its own file, or "
                                 "join them in the CAD tool)");
    }

    /// The current Gmsh model from a closed STL surface (in the file's unit), checked: sharp
    /// edges (more than 15 degrees) stay edges, the facets become remeshable surfaces. With
    /// @p keep_triangles the facets are not remeshed: they bound the volume as they are (a
    /// worn surface whose remeshing failed).
    void load_stl(const std::string &path, double h, const SolidFileSettings &settings, SolidFileReport *report,
                  bool keep_triangles = false)
    {
      {
        // Gmsh's STL reader drops a file with a coordinate it cannot read (inf, 1e30) and says
        // only that it "holds no triangles": read by abrade's checked reader first, which names
        // the point, and checked for its size while Gmsh has not seen it
        const auto poly = io::read_polydata(path);
        if (poly->GetNumberOfCells() == 0)
          throw InputError(path, "holds no triangles");
        double b[6];
        poly->GetBounds(b);
        check_extent(path, {b[0], b[2], b[4], b[1], b[3], b[5]}, settings.scale, settings, false);
        // overlapping facets (a planar face tessellated as a fan from a point outside it, a flap
        // folded back) stop Gmsh's volume mesher: such planes are triangulated again from their
        // outlines (surface_repair.h) and Gmsh reads the repaired copy
        const io::PolyData facets = io::triangles_of(poly);
        const double size = std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
        SurfaceRepair repair;
        try
          {
            // (an STL's single-precision corners lie up to ~1e-7 of the part's size off their
            // plane: a tolerance of 1e-6 of it)
            repair = repair_overlapping_facets(facets, 1e-6 * size);
          }
        catch (const std::runtime_error &e)
          {
            throw InputError(path, std::string("overlapping facets: ") + e.what());
          }
        if (repair.folds > 0)
          {
            const std::string repaired = io::private_temporary_directory() + "/repaired-" +
                                         std::filesystem::path(path).filename().string();
            io::write_stl(repaired, repair.surface);
            if (report)
              report->notes.push_back(std::to_string(repair.folds) + " overlapping facet pair(s) in " +
                                      std::to_string(repair.planes) +
                                      " planar face(s) re-triangulated from their outlines, the first at (" +
                                      format_number(repair.first_fold[0]) + ", " + format_number(repair.first_fold[1]) +
                                      ", " + format_number(repair.first_fold[2]) + ") in the file's unit");
            gmsh::merge(repaired);
          }
        else
          gmsh::merge(path);
      }
      {
        // a coordinate that is not a number sends Gmsh's meshers into an endless loop
        std::vector<std::size_t> tags;
        std::vector<double>      xyz, parametric;
        gmsh::model::mesh::getNodes(tags, xyz, parametric, -1, -1, false, false);
        for (std::size_t k = 0; k < xyz.size(); ++k)
          if (!std::isfinite(xyz[k]))
            throw InputError(path, "vertex " + std::to_string(k / 3 + 1) + " has a coordinate that is not a finite number");
        if (xyz.empty())
          throw InputError(path, "holds no triangles");
      }
      const auto [removed, duplicates] = remove_zero_area_triangles();
      if (removed > 0 && report)
        report->notes.push_back(std::to_string(removed) + " triangle(s) of zero area removed from the STL");
      if (duplicates > 0 && report)
        report->notes.push_back(std::to_string(duplicates) + " repeated facet(s) removed from the STL");
      if (report) // a user's part (a worn surface, filled as it is, was checked where it was built)
        check_closed_surface(path);
      check_extent(path, model_box(), settings.scale, settings, false);
      check_volume(path, enclosed_volume_of_triangles() * std::pow(settings.scale, 3), h, settings);
      if (!keep_triangles)
        {
          gmsh::model::mesh::classifySurfaces(settings.classify_angle * M_PI / 180, true, true, M_PI);
          gmsh::model::mesh::createGeometry();
        }
      gmsh::vectorpair surfaces;
      gmsh::model::getEntities(surfaces, 2);
      std::vector<int> tags;
      for (const auto &f : surfaces)
        tags.push_back(f.second);
      const int loop = gmsh::model::geo::addSurfaceLoop(tags);
      gmsh::model::geo::addVolume({loop});
      gmsh::model::geo::synchronize();
    }

    /// The centre of active cell @p index.
    Point<3> cell_centre(const Triangulation<3> &tria, unsigned index)
    {
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->active_cell_index() == index)
          return cell->center();
      return {};
    }

    /// The file's faces (boundary ids) that active cell @p index touches, by a vertex of it, and
    /// their areas: where a poor cell sits on the part's surface.
    std::map<types::boundary_id, double> faces_at_cell(const Triangulation<3> &tria, unsigned index)
    {
      std::set<unsigned> vertices;
      for (const auto &cell : tria.active_cell_iterators())
        if (cell->active_cell_index() == index)
          for (const unsigned v : cell->vertex_indices())
            vertices.insert(cell->vertex_index(v));
      std::set<types::boundary_id> touched;
      for (const auto &cell : tria.active_cell_iterators())
        for (const unsigned f : cell->face_indices())
          if (cell->face(f)->at_boundary())
            for (const unsigned v : cell->face(f)->vertex_indices())
              if (vertices.count(cell->face(f)->vertex_index(v)))
                touched.insert(cell->face(f)->boundary_id());
      std::map<types::boundary_id, double> out;
      for (const auto &face : part_faces(tria))
        if (touched.count(face.id))
          out[face.id] = face.area;
      return out;
    }
  } // namespace

  namespace
  {
    /// A user's volume mesh must be one solid: no cell given twice (a tetrahedron three times
    /// over was blamed on Part/Clamped faces), no pieces that share no face (two disjoint
    /// tetrahedra were taken as one part).
    std::string format_point(const Point<3> &p)
    {
      return "(" + format_number(p[0]) + ", " + format_number(p[1]) + ", " + format_number(p[2]) + ")";
    }

    void check_one_solid(const std::string &path, const Triangulation<3> &tria)
    {
      std::map<std::vector<unsigned>, unsigned> seen;
      for (const auto &cell : tria.active_cell_iterators())
        {
          std::vector<unsigned> vertices;
          for (const unsigned v : cell->vertex_indices())
            vertices.push_back(cell->vertex_index(v));
          std::sort(vertices.begin(), vertices.end());
          const auto [it, inserted] = seen.emplace(vertices, cell->active_cell_index());
          if (!inserted)
            throw InputError(path, "cell " + std::to_string(cell->active_cell_index()) + " (at " +
                                     format_point(cell->center()) + ") repeats cell " + std::to_string(it->second) +
                                     ": a volume mesh holds each cell once");
        }
      std::vector<bool>     reached(tria.n_active_cells(), false);
      std::vector<unsigned> todo = {0};
      reached[0]                 = true;
      std::vector<typename Triangulation<3>::active_cell_iterator> cells;
      for (const auto &cell : tria.active_cell_iterators())
        cells.push_back(cell);
      std::size_t n_reached = 1;
      while (!todo.empty())
        {
          const auto cell = cells[todo.back()];
          todo.pop_back();
          for (const unsigned f : cell->face_indices())
            if (!cell->at_boundary(f))
              {
                const unsigned n = cell->neighbor(f)->active_cell_index();
                if (!reached[n])
                  reached[n] = true, todo.push_back(n), ++n_reached;
              }
        }
      if (n_reached < cells.size())
        {
          const auto away = std::find(reached.begin(), reached.end(), false) - reached.begin();
          throw InputError(path, "the mesh is in separate pieces: " + std::to_string(cells.size() - n_reached) + " of " +
                                   std::to_string(cells.size()) + " cells share no face with cell 0 (the first at " +
                                   format_point(cells[away]->center()) + "); a part is one solid");
        }
    }
  } // namespace

  double estimated_cells(double volume, double h) { return 8.5 * volume / (h * h * h); }

  void parse_part_placement(const std::string &text, SolidFileSettings &settings)
  {
    auto &pl = settings.place;
    pl       = {};
    pl.text  = Utilities::trim(text);
    for (const auto &raw : Utilities::split_string_list(text, ','))
      {
        // (spaces do not matter: 'lowest point at z=0' and 'lowest point at z = 0' are one)
        std::string item;
        for (const char c : raw)
          if (c != ' ' && c != '\t')
            item += char(std::tolower(static_cast<unsigned char>(c)));
        const std::string lowest = "lowestpointatz=";
        if (item == "centred" || item == "centered")
          pl.centred[0] = pl.centred[1] = true;
        else if (item == "centredinx" || item == "centeredinx")
          pl.centred[0] = true;
        else if (item == "centrediny" || item == "centerediny")
          pl.centred[1] = true;
        else if (item == "centredinz" || item == "centeredinz")
          pl.centred[2] = true;
        else if (item.rfind(lowest, 0) == 0)
          {
            const auto z = io::finite_number(item.substr(lowest.size()));
            if (!z)
              throw std::invalid_argument("'" + Utilities::trim(raw) + "': the height is not a number (lowest point at z = V, in metres)");
            pl.lowest = true, pl.lowest_z = *z;
          }
        else
          throw std::invalid_argument("'" + Utilities::trim(raw) + "': a placement is 'centred', 'centred in x' (y, z) or "
                                      "'lowest point at z = V' [m], separated by ','");
      }
  }

  Tensor<2, 3> rotation_matrix(const Tensor<1, 3> &axis, double degrees)
  {
    if (degrees == 0)
      return unit_symmetric_tensor<3>();
    if (!(axis.norm() > 0))
      throw std::invalid_argument("the rotation axis must not be zero");
    return Physics::Transformations::Rotations::rotation_matrix_3d(Point<3>(axis / axis.norm()),
                                                                   degrees * M_PI / 180);
  }

  namespace
  {
    /// The settings' work directory, else this process's private temporary one.
    std::string work_directory(const SolidFileSettings &settings)
    {
      if (settings.work_directory.empty())
        return io::private_temporary_directory();
      std::error_code ec;
      std::filesystem::create_directories(settings.work_directory, ec);
      if (ec)
        throw RunError("cannot create " + settings.work_directory + ": " + ec.message());
      return settings.work_directory;
    }
  } // namespace

  namespace
  {
    /// A user's .msh file: Gmsh reads it in the mesher process and writes it again as .msh
    /// 2.2 (its face names in the notes), deal.II reads that; hexahedra split into
    /// tetrahedra, scaled, its extent and volume checked.
    void read_user_msh(const std::string &path, const SolidFileSettings &settings, Triangulation<3> &tria,
                       SolidFileReport &report)
    {
      const std::string clean = (std::filesystem::path(work_directory(settings)) /
                                 ("abrade-msh-" + std::to_string(::getpid()) + "-" +
                                  std::filesystem::path(path).filename().string()))
                                  .string();
      // Gmsh reads the user's file in the mesher process (meshing_job.h): a file that makes
      // its reader crash or loop costs the child
      MeshingJob job{path, clean, 0, false, false, settings, settings.mesher_time_limit};
      job.kind = "msh";
      for (const auto &note : run_meshing_job(job))
        if (note.rfind(face_name_prefix, 0) == 0)
          {
            std::istringstream words(note.substr(face_name_prefix.size()));
            unsigned           id = 0;
            std::string        name;
            words >> id;
            std::getline(words >> std::ws, name);
            report.face_names[types::boundary_id(id)] = name;
          }
      try
        {
          read_msh_file(clean, tria);
        }
      catch (const InputError &e)
        {
          std::filesystem::remove(clean);
          const std::string what = e.what(); // named after the clean copy: name the user's file
          throw InputError(path, what.substr(what.find(": ") + 2));
        }
      std::filesystem::remove(clean);
      check_one_solid(path, tria);
      bool hexahedra = false;
      for (const auto &cell : tria.active_cell_iterators())
        hexahedra = hexahedra || !cell->reference_cell().is_simplex();
      if (hexahedra)
        {
          // the part model (mesh motion, remeshing, checkpoints) works on tetrahedra: each
          // hexahedron becomes tetrahedra (deal.II), boundary ids kept
          Triangulation<3> tets;
          GridGenerator::convert_hypercube_to_simplex_mesh(tria, tets);
          tria.clear();
          tria.copy_triangulation(tets);
          report.notes.push_back("hexahedra split into " + std::to_string(tria.n_active_cells()) + " tetrahedra");
        }
      if (settings.scale != 1)
        GridTools::scale(settings.scale, tria);
      const BoundingBox<3> b = GridTools::compute_bounding_box(tria);
      check_extent(path, {b.lower_bound(0), b.lower_bound(1), b.lower_bound(2), b.upper_bound(0), b.upper_bound(1),
                          b.upper_bound(2)},
                   1.0, settings, false);
      check_volume(path, mesh_volume(tria), 0, settings);
    }

    /// A CAD file or a closed STL surface meshed by Gmsh (in the mesher process) to @p h; a
    /// mesh below the quality asked is meshed again (HXT and Gmsh's optimisers) and the better
    /// one kept.
    void mesh_cad_or_stl(const std::string &path, double h, bool cad, const SolidFileSettings &settings,
                         Triangulation<3> &tria, SolidFileReport &report)
    {
      if (!(h > 0))
        throw InputError(path, "meshing a CAD or STL solid needs a positive mesh size");
      // a name of this process's own: MPI ranks and the parallel runs of a study mesh at once
      static int        meshed = 0;
      const std::string msh    = (std::filesystem::path(work_directory(settings)) /
                               (std::filesystem::path(path).stem().string() + "-abrade-volume-" +
                                std::to_string(::getpid()) + "-" + std::to_string(meshed++) + ".msh"))
                                .string();
      // the file's own length unit: h in it (STL), or the model scaled to metres first (CAD)
      // Gmsh in its own process (meshing_job.h): a crash or a hang there is an InputError here
      auto mesh = [&](bool again, Triangulation<3> &into) {
        MeshingJob job{path, msh, h, again, false, settings, settings.mesher_time_limit};
        for (const auto &note : run_meshing_job(job))
          if (note.rfind(warning_prefix, 0) == 0)
            report.warnings.push_back(note.substr(warning_prefix.size()));
          else if (note.rfind(solids_prefix, 0) == 0)
            report.n_solids = unsigned(std::stoul(note.substr(solids_prefix.size())));
          else
            report.notes.push_back(note);
        read_msh_file(msh, into);
        std::filesystem::remove(msh);
        if (!cad && settings.scale != 1)
          GridTools::scale(settings.scale, into);
      };
      mesh(false, tria);
      const double first = mesh_quality(tria).min_scaled_jacobian;
      if (first < settings.min_quality)
        {
          const auto       notes = report.notes; // the same notes again from the second pass
          Triangulation<3> again;
          try
            {
              mesh(true, again);
            }
          catch (const InputError &)
            {
              again.clear(); // the first mesh stays
            }
          report.notes       = notes;
          const double other = again.n_active_cells() ? mesh_quality(again).min_scaled_jacobian : 0.0;
          if (other > first)
            {
              tria.clear();
              tria.copy_triangulation(again);
            }
          report.notes.push_back("minimum scaled Jacobian " + format_number(first) + ", " + format_number(other) +
                                 " meshed again (Gmsh's HXT mesher and optimisers)" +
                                 (other > first ? "" : " (not taken)"));
        }
    }

    /// The part into place: rotated about the origin, its bounding box centred and its lowest
    /// point at a height as Part/Place says, then moved by Offset.
    void place_part(const std::string &path, const SolidFileSettings &settings, Triangulation<3> &tria,
                    SolidFileReport &report)
    {
      const Tensor<2, 3> r = [&] {
        try
          {
            return rotation_matrix(settings.rotation_axis, settings.rotation_angle);
          }
        catch (const std::invalid_argument &e)
          {
            throw InputError(path, e.what());
          }
      }();
      if (settings.rotation_angle != 0)
        GridTools::transform([&](const Point<3> &p) { return Point<3>(r * p); }, tria);
      // Part/Place: the rotated part's bounding box centred, its lowest point at a height
      Tensor<1, 3> move = settings.offset;
      {
        const auto &pl = settings.place;
        if (pl.lowest || pl.centred[0] || pl.centred[1] || pl.centred[2])
          {
            const BoundingBox<3> box = GridTools::compute_bounding_box(tria);
            for (unsigned d = 0; d < 3; ++d)
              if (pl.centred[d])
                move[d] -= 0.5 * (box.lower_bound(d) + box.upper_bound(d));
            if (pl.lowest)
              move[2] += pl.lowest_z - box.lower_bound(2);
            report.notes.push_back("Part/Place '" + pl.text + "' moved the part by " + format_number(move[0] - settings.offset[0]) +
                                   ", " + format_number(move[1] - settings.offset[1]) + ", " +
                                   format_number(move[2] - settings.offset[2]) + " m (before Offset)");
          }
      }
      if (move.norm() > 0)
        GridTools::transform([&](const Point<3> &p) { return Point<3>(p + move); }, tria);
    }

    /// Inverted cells refused; a poor cell warned about, with the file's faces there and
    /// whether one of them is a sliver a smaller mesh size cannot help.
    void judge_quality(const std::string &path, double h, const std::string &ext, const SolidFileSettings &settings,
                       const Triangulation<3> &tria, SolidFileReport &report)
    {
      report.quality = mesh_quality(tria);
      if (report.quality.n_inverted > 0)
        throw InputError(path, "the mesh has " + std::to_string(report.quality.n_inverted) +
                                 " inverted cells (one near " + [&] {
                                   std::ostringstream s;
                                   s << cell_centre(tria, report.quality.worst_cell) << " m)";
                                   return s.str();
                                 }());
      if (report.quality.min_scaled_jacobian < settings.min_quality)
        {
          std::ostringstream s;
          s << "poor mesh: minimum scaled Jacobian " << format_number(report.quality.min_scaled_jacobian)
            << " (below " << settings.min_quality << ") in cell " << report.quality.worst_cell << " near ("
            << cell_centre(tria, report.quality.worst_cell) << ") m";
          // the file's faces there, and whether one holds only a few elements (a sliver: a
          // smaller mesh size does not help it, the CAD face must be cleaned or merged)
          const auto  faces = faces_at_cell(tria, report.quality.worst_cell);
          std::string slivers;
          if (!faces.empty())
            {
              s << ", on the file's face(s) ";
              bool first = true;
              for (const auto &[id, area] : faces)
                {
                  s << (first ? "" : ", ") << id << " (" << format_number(area, 3) << " m^2)";
                  first = false;
                  if (h > 0 && area < 2 * h * h) // (a face of a few elements at most)
                    slivers += (slivers.empty() ? "" : ", ") + std::to_string(id);
                }
            }
          s << "; "
            << (ext == ".msh" ? "improve the mesh in Gmsh (Mesh > Optimize 3D), or give the CAD file"
                : !slivers.empty()
                  ? "face(s) " + slivers + " hold only a few elements (below 2 Part/Mesh size^2): a smaller mesh "
                      "size only moves the poor cell; remove or merge them in the CAD tool (a face that continues "
                      "its neighbour, a short edge where two solids were fused), or select them with the others "
                      "(group " + slivers.substr(0, slivers.find(',')) + ") if the warning can stand"
                  : "a smaller Part/Mesh size there, or a cleaned CAD face there (slivers, short edges), helps");
          report.warnings.push_back(s.str());
        }
    }
  } // namespace

  SolidFileReport read_solid(const std::string &path, double h, Triangulation<3> &tria, const SolidFileSettings &settings)
  {
    if (!(settings.scale > 0))
      throw InputError(path, "the file scale must be positive");
    io::require_input_file(path, "solid file");
    const std::string ext = lower_extension(path);
    SolidFileReport   report;
    const bool        cad = is_cad_file(path);
    if (ext == ".msh")
      read_user_msh(path, settings, tria, report);
    else if (cad || ext == ".stl")
      mesh_cad_or_stl(path, h, cad, settings, tria, report);
    else
      throw InputError(path, "unknown solid format '" + ext + "' (use .msh, .step/.stp, .iges/.igs or a closed .stl)");
    place_part(path, settings, tria, report);
    judge_quality(path, h, ext, settings, tria, report);
    return report;
  }

  namespace
  {
    SolidSurface read_cad_surface_here(const std::string &path, double h);
    void         convert_to_step_here(const std::string &input, const std::string &step_file);

    /// A surface from the mesher: its vertices and triangles as text, every coordinate with
    /// 17 digits (the parent reads back exactly what the child made).
    void write_surface_file(const std::string &path, const SolidSurface &s)
    {
      std::ofstream out(path);
      out.precision(17);
      out << "abrade-surface 1\n" << s.vertices.size() << ' ' << s.triangles.size() << '\n';
      for (const auto &v : s.vertices)
        out << v[0] << ' ' << v[1] << ' ' << v[2] << '\n';
      for (const auto &t : s.triangles)
        out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
      if (!out)
        throw RunError("cannot write " + path);
    }

    SolidSurface read_surface_file(const std::string &path)
    {
      std::ifstream in(path);
      std::string   magic;
      int           version = 0;
      std::size_t   nv = 0, nt = 0;
      in >> magic >> version >> nv >> nt;
      if (magic != "abrade-surface" || version != 1)
        throw RunError("the mesher's surface " + path + " is not one it writes");
      SolidSurface s;
      s.vertices.resize(nv);
      s.triangles.resize(nt);
      for (auto &v : s.vertices)
        in >> v[0] >> v[1] >> v[2];
      for (auto &t : s.triangles)
        in >> t[0] >> t[1] >> t[2];
      if (!in)
        throw RunError("the mesher's surface " + path + " is cut short");
      for (const auto &t : s.triangles)
        for (const unsigned v : t)
          if (v >= nv)
            throw RunError("the mesher's surface " + path + " names a vertex it does not hold");
      return s;
    }
  } // namespace

  std::vector<std::string> run_meshing_job_here(const MeshingJob &job)
  {
    if (job.kind == "surface")
      {
        write_surface_file(job.output, read_cad_surface_here(job.input, job.mesh_size));
        return {};
      }
    if (job.kind == "step")
      {
        convert_to_step_here(job.input, job.output);
        return {};
      }
    if (job.kind == "msh")
      {
        std::vector<std::string> notes;
        for (const auto &[id, name] : normalise_msh(job.input, job.output))
          notes.push_back(face_name_prefix + std::to_string(id) + " " + name);
        return notes;
      }
    if (job.kind != "volume")
      throw RunError("the mesher knows no job '" + job.kind + "'");
    SolidFileReport report;
    const bool      cad = is_cad_file(job.input);
    with_gmsh(job.input, [&] {
      if (job.keep_triangles)
        load_stl(job.input, 0, job.settings, nullptr, true);
      else if (cad)
        load_cad(job.input, job.mesh_size, job.settings, report);
      else
        load_stl(job.input, job.mesh_size, job.settings, &report);
      mesh_volume_with_gmsh(job.input, cad ? job.mesh_size : job.mesh_size / job.settings.scale, job.output,
                            job.again, cad, job.keep_triangles);
    });
    for (const auto &w : report.warnings)
      report.notes.push_back(warning_prefix + w);
    report.notes.push_back(solids_prefix + std::to_string(report.n_solids));
    return report.notes;
  }

  void read_closed_triangles(const std::string &stl, double h, Triangulation<3> &tria, double time_limit)
  {
    const std::string msh = stl + ".volume.msh";
    SolidFileSettings as_is;
    run_meshing_job({stl, msh, h, false, true, as_is, time_limit});
    read_msh_file(msh, tria);
    std::filesystem::remove(msh);
  }

  void convert_to_step(const std::string &input, const std::string &step_file)
  {
    io::require_input_file(input);
    if (lower_extension(step_file) != ".step" && lower_extension(step_file) != ".stp")
      throw InputError(step_file, "the output is a STEP file (.step or .stp)");
    MeshingJob job{input, step_file, 0, false, false, {}, 0};
    job.kind = "step";
    run_meshing_job(job); // Gmsh in the mesher process
  }

  namespace
  {
  void convert_to_step_here(const std::string &input, const std::string &step_file)
  {
    with_gmsh(input, [&] {
      gmsh::open(input);
      gmsh::vectorpair volumes;
      gmsh::model::getEntities(volumes, 3);
      if (volumes.empty())
        throw InputError(input, "holds no solid (a .geo script needs SetFactory(\"OpenCASCADE\") and a volume)");
      with_stdout_silenced([&] { gmsh::write(step_file); });
    });
    if (!std::filesystem::exists(step_file))
      throw InputError(step_file, "Gmsh did not write it");
  }
  } // namespace

  bool is_cad_file(const std::string &path)
  {
    const std::string ext = lower_extension(path);
    return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
  }

  SolidSurface read_cad_surface(const std::string &path, double h)
  {
    io::require_input_file(path, "CAD file");
    if (!is_cad_file(path))
      throw InputError(path, "not a CAD file (.step/.stp or .iges/.igs)");
    if (!(h > 0))
      throw InputError(path, "meshing a CAD surface needs a positive mesh size");
    // Gmsh in the mesher process (meshing_job.h); the surface comes back in a file of this
    // process's own
    static int        made = 0;
    const std::string out  = io::private_temporary_directory() + "/" + std::filesystem::path(path).stem().string() +
                            "-surface-" + std::to_string(::getpid()) + "-" + std::to_string(made++) + ".txt";
    MeshingJob job{path, out, h, false, false, {}, 0};
    job.kind = "surface";
    run_meshing_job(job);
    SolidSurface s = read_surface_file(out);
    std::filesystem::remove(out);
    return s;
  }

  namespace
  {
  SolidSurface read_cad_surface_here(const std::string &path, double h)
  {
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
  } // namespace
} // namespace abrade::fem
