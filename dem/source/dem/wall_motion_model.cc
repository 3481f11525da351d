// The registry of wall motions and the default velocity, the wall's table (wall_motion_model.h).
// The motions themselves are in wall_motions/, a library of their own linked whole.
#include <abrade/dem/wall_motion_model.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace abrade::dem
{
  namespace
  {
    std::vector<WallMotionFactory> &factories()
    {
      static std::vector<WallMotionFactory> f;
      return f;
    }
  } // namespace

  PhaseVelocity WallMotionModel::velocity(const WallMotion &motion, const std::string &phase, double) const
  {
    const auto it = motion.phases.find(phase);
    return it == motion.phases.end() ? PhaseVelocity{} : it->second;
  }

  WallMotionRegistration::WallMotionRegistration(WallMotionFactory make)
  {
    const std::string name = make()->name();
    for (const auto &other : factories())
      if (other()->name() == name)
        {
          std::fprintf(stderr, "abrade: the wall motion '%s' is registered twice\n", name.c_str());
          std::abort();
        }
    factories().push_back(make);
  }

  std::vector<std::unique_ptr<WallMotionModel>> make_wall_motions()
  {
    std::vector<std::unique_ptr<WallMotionModel>> all;
    for (const auto &make : factories())
      all.push_back(make());
    // (the order of registration is the linker's: by name, the same in every build)
    std::sort(all.begin(), all.end(), [](const auto &a, const auto &b) { return a->name() < b->name(); });
    return all;
  }

  std::vector<std::string> wall_motion_names()
  {
    std::vector<std::string> names;
    for (const auto &m : make_wall_motions())
      names.push_back(m->name());
    return names;
  }

  std::unique_ptr<WallMotionModel> make_wall_motion(const std::string &name)
  {
    for (const auto &make : factories())
      if (auto m = make(); m->name() == name)
        return m;
    return nullptr;
  }
} // namespace abrade::dem
