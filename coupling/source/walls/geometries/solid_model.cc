// Geometry = solid model: the surface of the FEM part of subsection Part, which a lifetime run
// moves with its wear; the job fills the triangles in. It can be mounted on a shell's lip
// (wall_geometry.h).
#include <abrade/coupling/walls/wall_geometry.h>

#include <limits>

namespace abrade::coupling
{
  namespace
  {
    class SolidModel : public WallGeometry
    {
    public:
      std::string name() const override { return "solid model"; }
      std::string documentation() const override
      {
        return "the surface of the FEM part of subsection Part; lifetime runs move it with its wear";
      }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_text("Mounted on", "",
                         "Solid model: the name of a shell wall whose lip carries the part as its knife (a "
                         "clamshell shell, or a file with 'Lip centre' set). The part (subsection Part) lies "
                         "along the shell's width, its edge 'Protrusion' beyond the lip, its height along the "
                         "shell's bottom, and it moves with the shell (the shell's Motion is used; this wall's "
                         "own Motion and Offset are ignored). Empty: placed by Offset.");
        prm.declare_number("Protrusion", 0.02, 0, std::numeric_limits<double>::max(),
                           "[m] A part Mounted on a shell: how far its edge stands beyond the shell's lip. "
                           "Range: >= 0.");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &) const override
      {
        WallShape shape; // (no triangles: the job fills them in from the FEM part)
        shape.solid_model = true;
        shape.mount       = prm.text("Mounted on");
        shape.protrusion  = prm.number("Protrusion");
        if (!shape.mount.empty())
          shape.fixed_orientation = "a mounted knife is placed by its shell's lip: no rotation of its own";
        return shape;
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(SolidModel);
} // namespace abrade::coupling
