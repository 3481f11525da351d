// Geometry = box: an open-top container between two corners, its normals inward
// (wall_geometry.h).
#include <abrade/coupling/walls/wall_geometry.h>

namespace abrade::coupling
{
  namespace
  {
    class Box : public WallGeometry
    {
    public:
      std::string name() const override { return "box"; }
      std::string documentation() const override { return "open-top container, inward normals"; }

      void declare_parameters(dem::ParameterSection &prm) const override
      {
        prm.declare_vector("Box min", {-1, -1, 0}, "[m] Box: lower corner.");
        prm.declare_vector("Box max", {1, 1, 1}, "[m] Box: upper corner.");
      }

      WallShape make(const dem::ParameterSection &prm, const WallGeometryContext &) const override
      {
        const auto lo = prm.vector("Box min"), hi = prm.vector("Box max");
        WallShape  shape;
        shape.mesh = dem::primitives::box_container(dem::Vec3(lo[0], lo[1], lo[2]), dem::Vec3(hi[0], hi[1], hi[2]));
        return shape;
      }
    };
  } // namespace

  ABRADE_REGISTER_WALL_GEOMETRY(Box);
} // namespace abrade::coupling
