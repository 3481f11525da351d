// The registry of wall motions and the default velocity, the wall's table (wall_motion_model.h).
// The motions themselves are in wall_motions/, a library of their own linked whole.
#include <abrade/common/list_items.h>
#include <abrade/dem/wall_motion_model.h>

#include <algorithm>
#include <cmath>

namespace abrade::dem
{
  using Registry = io::PluginRegistry<WallMotionModel>;

  void declare_velocity_table(ParameterSection &p)
  {
    p.declare_text("Velocities", "",
                   "[m/s] Translational velocity per phase: 'phase: vx, vy, vz; phase: vx, vy, "
                   "vz'. Phases not listed: at rest.");
    p.declare_text("Angular velocities", "",
                   "[rad/s] Angular velocity per phase about the centre: 'phase: wx, wy, wz; "
                   "...'. Phases not listed: not rotating.");
  }

  namespace
  {
    /// "phase: a, b, c; phase: a, b, c" of entry @p key, by phase.
    std::map<std::string, Vec3> phase_vectors(const ParameterSection &p, const std::string &key,
                                              const MotionContext &c)
    {
      std::map<std::string, Vec3> out;
      for (const std::string &item : io::list_items(p.text(key), ';'))
        {
          const auto colon = item.find(':');
          if (colon == std::string::npos)
            p.fail(key, "expected 'phase: x, y, z', got '" + item + "'");
          const std::string phase  = io::trimmed(item.substr(0, colon));
          const std::string values = io::trimmed(item.substr(colon + 1));
          std::vector<std::string> v; // (every item, an empty one too: "0, , 1" is not three numbers)
          for (std::size_t at = 0; at <= values.size();)
            {
              const std::size_t comma = std::min(values.find(',', at), values.size());
              v.push_back(io::trimmed(values.substr(at, comma - at)));
              at = comma + 1;
            }
          Vec3              vec;
          bool              read = v.size() == 3;
          for (int d = 0; read && d < 3; ++d)
            try
              {
                std::size_t used = 0;
                vec[d]           = std::stod(v[d], &used);
                read             = used == v[d].size() && std::isfinite(vec[d]);
              }
            catch (const std::exception &)
              {
                read = false;
              }
          if (!read)
            p.fail(key, "phase '" + phase + "': expected three finite numbers, got '" + values + "'");
          if (std::find(c.phases.begin(), c.phases.end(), phase) == c.phases.end() && phase != "settle")
            p.fail(key, "unknown phase '" + phase + "' (Simulation/Phases defines the phases)");
          out[phase] = vec;
        }
      return out;
    }
  } // namespace

  void read_velocity_table(const ParameterSection &p, const MotionContext &c, WallMotion &motion)
  {
    for (const auto &[phase, v] : phase_vectors(p, "Velocities", c))
      motion.phases[phase].velocity = v;
    for (const auto &[phase, v] : phase_vectors(p, "Angular velocities", c))
      motion.phases[phase].angular_velocity = v;
  }

  PhaseVelocity WallMotionModel::velocity(const WallMotion &motion, const std::string &phase, double) const
  {
    const auto it = motion.phases.find(phase);
    return it == motion.phases.end() ? PhaseVelocity{} : it->second;
  }

  WallMotionRegistration::WallMotionRegistration(WallMotionFactory make) { Registry::add(make, "wall motion"); }

  std::vector<std::unique_ptr<WallMotionModel>> make_wall_motions() { return Registry::make_all(); }

  std::vector<std::string> wall_motion_names()
  {
    std::vector<std::string> names;
    for (const auto &m : make_wall_motions())
      names.push_back(m->name());
    return names;
  }

  std::unique_ptr<WallMotionModel> make_wall_motion(const std::string &name) { return Registry::make(name); }
} // namespace abrade::dem
