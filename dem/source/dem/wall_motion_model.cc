// The registry of wall motions and the default velocity, the wall's table (wall_motion_model.h).
// The motions themselves are in wall_motions/, a library of their own linked whole.
#include <abrade/dem/wall_motion_model.h>

namespace abrade::dem
{
  using Registry = io::PluginRegistry<WallMotionModel>;

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
