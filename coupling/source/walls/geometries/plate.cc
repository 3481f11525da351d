// Geometry = plate: a rectangle normal to a coordinate axis (wall_geometry.h).
#include <abrade/coupling/walls/wall_geometry.h>

#include <limits>

namespace abrade::coupling
{
  namespace
  {
    class Plate : public WallGeometry
    {
    public:
      std::string name() const override { return "plate"; }
      std::string documentation() const override { return "a rectangle"; }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_vector("Plate centre", {0, 0, 0}, "[m] Plate: centre.");
        prm.declare_choice("Plate normal", "z", {"x", "y", "z", "-x", "-y", "-z"}, "Plate: normal direction.");
        prm.declare_numbers("Plate size", "1, 1", 2, 2, 0, std::numeric_limits<double>::max(),
                            "[m] Plate: side lengths along the two in-plane axes (cyclic order after "
                            "the normal: y,z for x; z,x for y; x,y for z).");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &) const override
      {
        const std::string normal = prm.text("Plate normal");
        const auto        size   = prm.numbers("Plate size");
        const auto        c      = prm.vector("Plate centre");
        WallShape         shape;
        shape.mesh = dem::primitives::plate(dem::Vec3(c[0], c[1], c[2]), normal.back() - 'x', size[0], size[1], 0,
                                            normal[0] == '-');
        return shape;
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(Plate);
} // namespace abrade::coupling
