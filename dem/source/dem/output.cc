// DEM output for ParaView and for analysis: particles and walls per snapshot (output.h).
#include <abrade/dem/output.h>
#include <abrade/dem/simulation.h>

#include <cstdio>
#include <filesystem>

namespace abrade::dem
{
  DemOutput::DemOutput(const std::string &dir, const Simulation &sim, bool write_particles)
    : particle_dir(dir + "/particles"), wall_dir(dir + "/walls"), particles_on(write_particles)
  {
    std::filesystem::create_directories(wall_dir);
    if (particles_on)
      {
        std::filesystem::create_directories(particle_dir);
        particle_series.set_path(particle_dir + "/particles.pvd");
      }
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        const std::string &name = sim.wall(w).name;
        wall_series.emplace_back(wall_dir + "/" + name + ".pvd");
        force_csv.push_back(std::make_unique<io::CsvWriter>(
          wall_dir + "/" + name + "_forces.csv",
          std::vector<std::string>{"phase", "time", "fx", "fy", "fz", "tx", "ty", "tz", "cx", "cy", "cz"}));
      }
  }

  void DemOutput::add_triangle_field(const std::string &name, TriangleField f)
  {
    fields.emplace_back(name, std::move(f));
  }

  void DemOutput::write_snapshot(const Simulation &sim)
  {
    char tag[16];
    std::snprintf(tag, sizeof tag, "%05d", counter++);
    if (particles_on)
      {
        const ParticleStore P = sim.gather_particles(); // all ranks' particles on rank 0
        io::PolyData d;
        const std::size_t n = P.size();
        d.points.resize(3 * n);
        io::Field radius{"radius", 1, P.radius}, id{"id", 1, std::vector<double>(n)};
        io::Field vel{"velocity", 3, std::vector<double>(3 * n)}, force{"force", 3, std::vector<double>(3 * n)};
        io::Field omega{"angular_velocity", 3, std::vector<double>(3 * n)};
        for (std::size_t i = 0; i < n; ++i)
          {
            const double p[3] = {P.x[i], P.y[i], P.z[i]}, v[3] = {P.vx[i], P.vy[i], P.vz[i]},
                         f[3] = {P.fx[i], P.fy[i], P.fz[i]}, w[3] = {P.wx[i], P.wy[i], P.wz[i]};
            for (int k = 0; k < 3; ++k)
              {
                d.points[3 * i + k] = p[k];
                vel.values[3 * i + k] = v[k], force.values[3 * i + k] = f[k], omega.values[3 * i + k] = w[k];
              }
            id.values[i] = static_cast<double>(P.id[i]);
          }
        d.point_fields = {radius, id, vel, force, omega};
        const std::string file = std::string("particles_") + tag + ".vtp";
        io::write_vtp(particle_dir + "/" + file, d);
        particle_series.add(sim.time(), file);
      }
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        const Wall  &wall = sim.wall(w);
        io::PolyData d;
        d.points = wall.current;
        for (const auto &t : wall.mesh.triangles)
          d.triangles.push_back({t[0], t[1], t[2]});
        std::vector<double> normal = wall.normal_impulse, tangential = wall.tangential_impulse;
        sim.parallel().sum(normal), sim.parallel().sum(tangential); // each rank has its own contacts'
        d.cell_fields.push_back({"normal_impulse", 1, normal});
        d.cell_fields.push_back({"tangential_impulse", 1, tangential});
        for (const auto &[name, f] : fields)
          d.cell_fields.push_back({name, 1, f(sim, w)});
        const std::string file = wall.name + "_" + tag + ".vtp";
        io::write_vtp(wall_dir + "/" + file, d);
        wall_series[w].add(sim.time(), file);
      }
  }

  void DemOutput::write_forces(const Simulation &sim)
  {
    for (std::size_t w = 0; w < sim.n_walls(); ++w)
      {
        const Wall &wall = sim.wall(w);
        const Vec3  c    = wall.current_centre();
        force_csv[w]->row(sim.phase().empty() ? "-" : sim.phase(),
                          {sim.time(), wall.force[0], wall.force[1], wall.force[2], wall.torque[0], wall.torque[1],
                           wall.torque[2], c[0], c[1], c[2]});
      }
  }

  void DemOutput::close()
  {
    for (auto &csv : force_csv)
      csv->close();
  }
} // namespace abrade::dem
