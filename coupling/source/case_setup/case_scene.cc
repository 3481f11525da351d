// The case around a part, for its preview (case_scene.h).
#include <abrade/coupling/case_setup/case_scene.h>
#include <abrade/coupling/parameters/part_parameters.h>
#include <abrade/coupling/parameters/parameters.h>
#include <abrade/coupling/walls/wall_parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace abrade::coupling
{
  std::vector<std::array<double, 6>> feature_edges(const std::vector<Eigen::Vector3d> &vertices,
                                                   const std::vector<std::array<int, 3>> &triangles, double angle_degrees)
  {
    // each edge (smaller vertex first) with the normals of the triangles that hold it
    std::map<std::pair<int, int>, std::vector<Eigen::Vector3d>> edges;
    for (const auto &t : triangles)
      {
        const Eigen::Vector3d n = (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]);
        if (!(n.norm() > 0))
          continue;
        for (int k = 0; k < 3; ++k)
          {
            const int a = t[k], b = t[(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back(n.normalized());
          }
      }
    const double                       turn = std::cos(angle_degrees * M_PI / 180);
    std::vector<std::array<double, 6>> out;
    for (const auto &[e, normals] : edges)
      {
        bool feature = normals.size() != 2;
        for (std::size_t i = 0; i < normals.size() && !feature; ++i)
          for (std::size_t j = i + 1; j < normals.size(); ++j)
            feature = feature || normals[i].dot(normals[j]) < turn;
        if (feature)
          {
            const Eigen::Vector3d &p = vertices[e.first], &q = vertices[e.second];
            out.push_back({p[0], p[1], p[2], q[0], q[1], q[2]});
          }
      }
    return out;
  }

  CaseScene case_scene(ParameterFile &file, const fem::SolidSurface &part)
  {
    CaseScene scene;
    // a part on its own (no wall holds it) has no case around it: its file's DEM keys are
    // defaults, and reading them would check a bed nobody asked for
    if (!a_wall_is_the_part(file) || part.vertices.empty())
      return scene;
    DemCase c = read_dem_case(file);
    scene.present = true;
    scene.notes  = c.notes; // (what the reading left out)
    for (int d = 0; d < 3; ++d)
      {
        scene.domain[d] = c.settings.domain_min[d], scene.domain[3 + d] = c.settings.domain_max[d];
        scene.fill_region[d] = c.fill.box_min[d], scene.fill_region[3 + d] = c.fill.box_max[d];
      }
    scene.particles = c.fill.count;
    fit_mounted_parts(c, part); // (a part mounted on a shell's lip: placed by it)
    for (auto &wc : c.walls)
      {
        if (!wc.solid_model)
          {
            const auto &mesh = wc.wall.mesh;
            scene.outlines.push_back({wc.wall.name, feature_edges({mesh.vertices.begin(), mesh.vertices.end()},
                                                                  mesh.triangles)});
            continue;
          }
        scene.placements.push_back({wc.wall.name, wc.rotation, wc.offset});
        // the path of the part's lowest point: the wall's pose through the phases, one point
        // per 1/40 of each phase (a straight leg needs two; a turning one shows its arc)
        const dem::TriangleMesh placed = place_surface(part, wc);
        dem::Vec3               lowest = placed.vertices.front();
        for (const auto &p : placed.vertices)
          if (p[2] < lowest[2])
            lowest = p;
        dem::Wall w = wc.wall;
        w.mesh      = dem::TriangleMesh();
        w.mesh.vertices = {lowest};
        w.initialise();
        if (c.grab_mechanism && std::any_of(c.grab_mechanism->walls.begin(), c.grab_mechanism->walls.end(),
                                            [&](const auto &m) { return m.first == wc.wall.name; }))
          {
            scene.notes.push_back("wall " + wc.wall.name + " rides on the grab's rope mechanism, which its winches and "
                                  "the particles move: its path is not drawn");
            continue;
          }
        if (w.motion.kind == dem::WallMotion::Kind::fixed)
          continue;
        if (w.motion.kind == dem::WallMotion::Kind::rigid_body)
          scene.notes.push_back("wall " + wc.wall.name + " is a rigid body: its free degrees of freedom follow the "
                                "particles and are not drawn (the path shows its prescribed velocities only)");
        for (const auto &[phase, duration] : c.phases)
          {
            CaseScene::Leg leg{wc.wall.name, phase, {}};
            w.set_phase(phase);
            const int steps = 40;
            leg.points.push_back({w.current[0], w.current[1], w.current[2]});
            for (int k = 0; k < steps; ++k)
              {
                w.advance(duration / steps);
                leg.points.push_back({w.current[0], w.current[1], w.current[2]});
              }
            scene.path.push_back(std::move(leg));
          }
      }
    return scene;
  }
} // namespace abrade::coupling
