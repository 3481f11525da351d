// Lifetime/Wear source = dem: every update runs the DEM's operating cycle on the knife's current
// surface, one bed per seed (dem_wear_source.cc; wear_source.h).
#include <abrade/coupling/lifetime/wear_source.h>

namespace abrade::coupling::lifetime
{
  namespace
  {
    class DemSource : public WearSourceChoice
    {
    public:
      std::string name() const override { return "dem"; }
      std::string documentation() const override
      {
        return "every update runs the DEM cycles on the knife's current surface";
      }
      bool        from_particles() const override { return true; }
      std::string description() const override { return "the DEM"; }
      std::unique_ptr<WearSource> make(const WearSourceSetUp &s) const override
      {
        return make_dem_wear_source(s.dem_case, s.seeds, s.tonnes_per_cycle, s.ctx);
      }
    };
  } // namespace

  ABRADE_REGISTER_WEAR_SOURCE(DemSource);
} // namespace abrade::coupling::lifetime
