// Motion/Type = rigid body: the degrees of freedom listed as free move under gravity and the
// particles' forces, the others follow the wall's velocity table; walls of one Body move as one
// (wall_motion_model.h, Wall::accelerate()).
#include <abrade/common/list_items.h>
#include <abrade/dem/wall_motion_model.h>

#include <algorithm>
#include <limits>

namespace abrade::dem
{
  namespace
  {
    const std::vector<std::string> degrees_of_freedom = {"tx", "ty", "tz", "rx", "ry", "rz"};

    class RigidBody : public WallMotionModel
    {
    public:
      std::string      name() const override { return "rigid body"; }
      std::string      documentation() const override
      {
        return "the degrees of freedom listed in 'Free degrees of freedom' move under gravity and particle forces, "
               "the others follow the prescribed velocities";
      }
      WallMotion::Kind kind() const override { return WallMotion::Kind::rigid_body; }

      void declare_parameters(ParameterSection &p) const override
      {
        declare_velocity_table(p); // (the degrees of freedom that are not free, and every one outside Free in phases)
        p.declare_number("Mass", 0, 0, unbounded, "[kg] Rigid body: mass. Range: >= 0.");
        p.declare_vector("Inertia", {0, 0, 0}, "[kg m^2] Rigid body: principal moments about the centre.");
        p.declare_choices("Free degrees of freedom", "", degrees_of_freedom,
                          "Rigid body: which of tx, ty, tz, rx, ry, rz move freely.");
        p.declare_bool("Gravity", true, "Rigid body: whether gravity acts on it.");
        p.declare_text("Body", "",
                       "Rigid body: walls with the same Body name move as one body (a grab's two shells): their "
                       "forces, torques about the common Centre, masses and inertias add up. They need the same "
                       "Type, Centre, free degrees of freedom and free phases. Empty: a body of its own.");
        p.declare_text("Free in phases", "",
                       "Rigid body: the phases in which the free degrees of freedom are free, comma separated; in "
                       "the others the wall follows Velocities and Angular velocities entirely (a grab hoisted by "
                       "its crane). Empty: all phases.");
      }

      void parse_parameters(const ParameterSection &p, const MotionContext &c, WallMotion &m) override
      {
        read_velocity_table(p, c, m);
        m.mass          = p.number("Mass");
        const auto i    = p.vector("Inertia");
        m.inertia       = Vec3(i[0], i[1], i[2]);
        m.gravity       = p.boolean("Gravity");
        for (const auto &d : p.chosen("Free degrees of freedom"))
          m.free[std::find(degrees_of_freedom.begin(), degrees_of_freedom.end(), d) - degrees_of_freedom.begin()] = true;
        m.body = p.text("Body");
        if (m.body.empty() && !(m.mass > 0))
          p.fail("Mass", "a rigid-body wall needs a positive mass (or a Body whose other walls have one)");
        for (const std::string &phase : io::list_items(p.text("Free in phases"), ','))
          {
            if (std::find(c.phases.begin(), c.phases.end(), phase) == c.phases.end())
              p.fail("Free in phases", "'" + phase + "' is not a phase of Simulation/Phases");
            m.free_phases.insert(phase);
          }
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_MOTION(RigidBody);
} // namespace abrade::dem
