// Lifetime/Wear source = dem: every update runs the DEM's operating cycle on the part's current
// surface, one bed per seed (dem_wear_source.cc; wear_source.h); under mpirun the beds side by
// side on groups of the ranks.
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
        return "every update runs the DEM cycles on the part's current surface";
      }
      std::string section() const override { return "DEM"; }
      bool        from_particles() const override { return true; }
      std::string description() const override { return "the DEM"; }
      void declare_parameters(dealii::ParameterHandler &prm) const override
      {
        prm.declare_entry("Ranks per bed", "0", dealii::Patterns::Integer(0),
                          "[-] Wear source = dem, under mpirun: the beds of an update run side by side on "
                          "groups of ranks, as many groups as the rank count divided by this (rounded down; at "
                          "least one, at most one per bed), their sizes differing by one at most (3 ranks, 2 per bed: one "
                          "group of 3); a bed's wear is the same as on its group's number of ranks alone. 0: "
                          "the ranks shared out evenly among the beds (4 ranks, 2 beds: 2 groups of 2; 2 ranks, "
                          "3 beds: 2 groups of 1, one running 2 beds). A number at least the rank count: every "
                          "bed on all ranks, one after another. Range: [0, inf).");
      }

      void parse_parameters(ParameterFile &file) override { ranks_per_bed = file.handler().get_integer("Ranks per bed"); }

      std::unique_ptr<WearSource> make(const WearSourceSetUp &s) const override
      {
        return make_dem_wear_source(s.dem_case, s.seeds, s.tonnes_per_cycle, ranks_per_bed, s.ctx);
      }

    private:
      int ranks_per_bed = 0;
    };
  } // namespace

  ABRADE_REGISTER_WEAR_SOURCE(DemSource);
} // namespace abrade::coupling::lifetime
