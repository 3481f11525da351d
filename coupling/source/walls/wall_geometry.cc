// The registry of wall geometries (wall_geometry.h). The geometries themselves are in
// geometries/, a library of their own linked whole.
#include <abrade/coupling/walls/wall_geometry.h>

namespace abrade::coupling
{
  using Registry = io::PluginRegistry<WallGeometry>;

  WallGeometryRegistration::WallGeometryRegistration(WallGeometryFactory make) { Registry::add(make, "wall geometry"); }

  std::vector<std::unique_ptr<WallGeometry>> make_wall_geometries() { return Registry::make_all(); }

  std::unique_ptr<WallGeometry> make_wall_geometry(const std::string &name) { return Registry::make(name); }
} // namespace abrade::coupling
