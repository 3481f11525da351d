// Walls: a triangle mesh with a material and a motion, and what the particles do to it
// (wall.h).
#include <abrade/dem/wall.h>
#include <abrade/dem/wall_motion_model.h>

#include <Eigen/Geometry>

#include <cmath>

namespace abrade::dem
{
  void Wall::initialise()
  {
    rotation    = Eigen::Matrix3d::Identity();
    translation = Vec3::Zero();
    current.resize(3 * mesh.vertices.size());
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      for (int d = 0; d < 3; ++d)
        current[3 * v + d] = mesh.vertices[v][d];
    at_build = current;
    normal_impulse.assign(mesh.n_triangles(), 0.0);
    tangential_impulse.assign(mesh.n_triangles(), 0.0);
  }

  void Wall::set_phase(const std::string &name)
  {
    if (motion.kind == WallMotion::Kind::fixed)
      return;
    phase         = name;
    time_in_phase = 0;
    if (motion.kind == WallMotion::Kind::driven) // (its mechanism knows the phase too)
      return;
    free_in_phase = motion.free_phases.empty() || motion.free_phases.count(phase) > 0;
    if (motion.model)
      prescribe(motion.model->velocity(motion, phase, 0));
    else if (auto it = motion.phases.find(phase); it != motion.phases.end())
      prescribe(it->second);
    else
      prescribe({});
  }

  void Wall::prescribe(const PhaseVelocity &pv)
  {
    const bool rb = free_now();
    for (int d = 0; d < 3; ++d)
      {
        if (!(rb && motion.free[d]))
          velocity[d] = pv.velocity[d];
        if (!(rb && motion.free[3 + d]))
          angular_velocity[d] = pv.angular_velocity[d];
      }
  }

  void Wall::advance(double dt)
  {
    if (motion.kind == WallMotion::Kind::fixed)
      return;
    if (motion.model && motion.model->time_dependent()) // (midpoint: second order in dt)
      prescribe(motion.model->velocity(motion, phase, time_in_phase + 0.5 * dt));
    time_in_phase += dt;
    const double angle = angular_velocity.norm() * dt;
    if (angle > 0)
      rotation = Eigen::AngleAxisd(angle, angular_velocity.normalized()).toRotationMatrix() * rotation;
    translation += velocity * dt;
    const Vec3 c0 = motion.centre, c = current_centre();
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
      {
        const Vec3 p = c + rotation * (mesh.vertices[v] - c0);
        for (int d = 0; d < 3; ++d)
          current[3 * v + d] = p[d];
      }
    // the contacts at the new positions see the velocity there, not the step's middle one
    if (motion.model && motion.model->time_dependent())
      prescribe(motion.model->velocity(motion, phase, time_in_phase));
  }

  void Wall::accelerate(const Vec3 &gravity, double dt, const Vec3 &f, const Vec3 &t, double mass, const Vec3 &inertia)
  {
    if (!free_now())
      return;
    for (int d = 0; d < 3; ++d)
      {
        if (motion.free[d])
          velocity[d] += dt * (f[d] / mass + (motion.gravity ? gravity[d] : 0.0));
        if (motion.free[3 + d] && inertia[d] > 0)
          angular_velocity[d] += dt * t[d] / inertia[d];
      }
  }

  double Wall::max_displacement_since_build() const
  {
    if (motion.kind == WallMotion::Kind::fixed)
      return 0;
    double m = 0;
    for (std::size_t k = 0; k < current.size(); k += 3)
      {
        const double dx = current[k] - at_build[k], dy = current[k + 1] - at_build[k + 1],
                     dz = current[k + 2] - at_build[k + 2];
        m = std::max(m, dx * dx + dy * dy + dz * dz);
      }
    return std::sqrt(m);
  }

  TriangleMesh Wall::current_mesh() const
  {
    TriangleMesh m = mesh;
    for (std::size_t v = 0; v < m.vertices.size(); ++v)
      m.vertices[v] = Vec3(current[3 * v], current[3 * v + 1], current[3 * v + 2]);
    return m;
  }
} // namespace abrade::dem
