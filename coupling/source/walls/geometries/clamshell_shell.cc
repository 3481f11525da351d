// Geometry = clamshell shell: one shell of a grab, its hinge the origin and its axis y, with the
// lip a part can be mounted on (wall_geometry.h; the surface: dem::primitives::clamshell_shell).
#include <abrade/dem/parameter_section.h>
#include <abrade/coupling/walls/wall_geometry.h>

#include <cmath>
#include <limits>

namespace abrade::coupling
{
  namespace
  {
    class ClamshellShell : public WallGeometry
    {
    public:
      std::string name() const override { return "clamshell shell"; }
      std::string documentation() const override { return "one shell of a grab: Shell ... below"; }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_number("Shell radius", 0.6, 0, dem::unbounded,
                           "[m] Clamshell shell: radius of its bottom about the hinge (the hinge is the "
                           "shell's origin, its axis along Y; Offset places it). Range: > 0.");
        prm.declare_number("Shell width", 1, 0, dem::unbounded, "[m] Clamshell shell: width along the hinge (Y). Range: > 0.");
        prm.declare_number("Shell sector", 90, 1, 180,
                           "[deg] Clamshell shell: angle its bottom spans, from the lip. Range: [1, 180].");
        prm.declare_number("Shell opening", 0, 0, 180,
                           "[deg] Clamshell shell: angle of its lip from straight down at t = 0 (0: "
                           "closed). Range: [0, 180].");
        prm.declare_choice("Shell side", "+x", {"+x", "-x"},
                           "Clamshell shell: which way it opens (the other shell of the grab: the other side).");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &context) const override
      {
        const double r = prm.number("Shell radius"), h = context.maximum_edge_length;
        for (const char *size : {"Shell radius", "Shell width"})
          if (!(prm.number(size) > 0))
            prm.fail(size, "a shell needs a positive size (it was 0)");
        WallShape    shape;
        const auto  &sh = shape.shell = ShellShape{r, prm.number("Shell opening") * M_PI / 180,
                                                   prm.text("Shell side") == "+x" ? 1 : -1};
        shape.mesh = dem::primitives::clamshell_shell(r, prm.number("Shell width"), prm.number("Shell sector") * M_PI / 180,
                                                      sh->opening, sh->side, h > 0 ? h : 0.1 * r);
        // along the hinge, mirrored with the shell, so that a knife's +y face is inside both shells
        const double th = sh->opening;
        shape.lip       = WallLip{dem::Vec3(sh->side * r * std::sin(th), 0, -r * std::cos(th)), dem::Vec3(0, sh->side, 0),
                                  dem::Vec3(sh->side * std::cos(th), 0, std::sin(th))};
        shape.fixed_orientation = "a clamshell shell opens about its hinge (Shell opening): no rotation";
        return shape;
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(ClamshellShell);
} // namespace abrade::coupling
