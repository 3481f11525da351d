// Motion/Type = prescribed: the wall moves with the velocities its table gives each phase
// (Motion/Velocities and Angular velocities, constant in a phase: its position piecewise linear)
// (wall_motion_model.h).
#include <abrade/dem/wall_motion_model.h>

namespace abrade::dem
{
  namespace
  {
    class Prescribed : public WallMotionModel
    {
    public:
      std::string      name() const override { return "prescribed"; }
      std::string      documentation() const override { return "velocities per phase"; }
      WallMotion::Kind kind() const override { return WallMotion::Kind::prescribed; }

      void declare_parameters(ParameterSection &p) const override { declare_velocity_table(p); }
      void parse_parameters(const ParameterSection &p, const MotionContext &c, WallMotion &m) override
      {
        read_velocity_table(p, c, m);
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_MOTION(Prescribed);
} // namespace abrade::dem
