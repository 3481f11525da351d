// Motion/Type = fixed: the wall never moves (wall_motion_model.h).
#include <abrade/dem/wall_motion_model.h>

namespace abrade::dem
{
  namespace
  {
    class Fixed : public WallMotionModel
    {
    public:
      std::string      name() const override { return "fixed"; }
      std::string      documentation() const override { return {}; }
      WallMotion::Kind kind() const override { return WallMotion::Kind::fixed; }
    };
  } // namespace

  ABRADE_REGISTER_WALL_MOTION(Fixed);
} // namespace abrade::dem
