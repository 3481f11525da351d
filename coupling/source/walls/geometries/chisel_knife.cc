// Geometry = chisel knife: the knife-bed reference knife as a surface of its own, a plate with a
// chisel edge (docs/cases.md; wall_geometry.h). Not the FEM part (Geometry = solid model).
#include <abrade/dem/parameter_section.h>
#include <abrade/coupling/walls/wall_geometry.h>

#include <limits>

namespace abrade::coupling
{
  namespace
  {
    class ChiselKnife : public WallGeometry
    {
    public:
      std::string name() const override { return "chisel knife"; }
      std::string documentation() const override { return "the knife-bed reference knife, see cases.md"; }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_number("Knife length", 0.4, 0, dem::unbounded, "[m] Chisel knife: length along X.");
        prm.declare_number("Knife height", 0.5, 0, dem::unbounded, "[m] Chisel knife: height along Z.");
        prm.declare_number("Knife thickness", 0.03, 0, dem::unbounded, "[m] Chisel knife: thickness along Y.");
        prm.declare_number("Bevel height", 0.04, 0, dem::unbounded,
                           "[m] Chisel knife: height of the bevel that forms the bottom edge.");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &) const override
      {
        WallShape shape;
        shape.mesh = dem::primitives::chisel_knife(prm.number("Knife length"), prm.number("Knife height"),
                                                   prm.number("Knife thickness"), prm.number("Bevel height"));
        return shape;
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(ChiselKnife);
} // namespace abrade::coupling
