// A new wear source is one file and one registration line (wear_source.h): this test is that
// file. Its toy source wears every wearable vertex by a depth Toy rate [m] per cycle, the same
// on every bed; registered here, outside the library, it must be a choice of Lifetime/Wear
// source with its entry declared and read, and drive a lifetime run to the analytic life.
//
// The truth: a depth d per cycle everywhere moves the surface to the offset surface, d below the
// design after each cycle; with 1 t per cycle and the life's limit 3 mm at 2 um per cycle the
// life is 1500 t (the run's updates are 750 cycles: 1.5 mm, a tenth of the 15 mm mesh).
#include "lifetime_in_process.h"

#include <abrade/coupling/lifetime/wear_source.h>
#include <abrade/fem/parametric_knife.h>
#include <abrade/fem/surface_filter.h>

#include <gtest/gtest.h>

#include <fstream>


namespace
{
  using namespace abrade::coupling::lifetime;

  class UniformDepth : public WearSource
  {
  public:
    explicit UniformDepth(double depth) : depth(depth) {}
    CycleWear cycle(const abrade::fem::SolidSurface &surface, double, const std::vector<int> &beds) override
    {
      CycleWear w;
      w.tonnes_per_cycle = 1;
      const auto          area = abrade::fem::vertex_areas(surface, abrade::fem::wearable_boundary);
      std::vector<double> volume(area.size());
      for (std::size_t v = 0; v < area.size(); ++v)
        volume[v] = depth * area[v];
      w.seed_volume.assign(beds.size(), volume);
      return w;
    }
    std::vector<std::string> phases() const override { return {}; }
    bool                     removes_volume() const override { return false; }
    std::string              name() const override { return "toy"; }

  private:
    double depth;
  };

  class ToySource : public WearSourceChoice
  {
  public:
    std::string name() const override { return "toy"; }
    std::string documentation() const override { return "a depth of Toy/Rate per cycle everywhere"; }
    std::string section() const override { return "Toy"; }
    bool        from_particles() const override { return false; }
    void        declare_parameters(dealii::ParameterHandler &prm) const override
    {
      prm.declare_entry("Rate", "1e-6", dealii::Patterns::Double(0), "[m] Wear source = toy: depth per cycle.");
    }
    void parse_parameters(abrade::coupling::ParameterFile &file) override { rate = file.handler().get_double("Rate"); }
    std::unique_ptr<WearSource> make(const WearSourceSetUp &) const override
    {
      return std::make_unique<UniformDepth>(rate);
    }
    std::string description() const override { return "the toy's uniform depth"; }

  private:
    double rate = 0;
  };
} // namespace

ABRADE_REGISTER_WEAR_SOURCE(ToySource);

TEST(ToyWearSource, IsAChoiceBesideTheBuiltInOnes)
{
  std::vector<std::string> names;
  for (const auto &c : make_wear_source_choices())
    names.push_back(c->name());
  EXPECT_EQ(names, (std::vector<std::string>{"analytic", "dem", "replay", "toy"}));
}

TEST(ToyWearSource, DrivesALifeToTheAnalyticCrossing)
{
  abrade::io::Json results = run_analytic_lifetime("abrade_toy_wear_source",
                                                   {"Lifetime/Wear source=toy", "Lifetime/Toy/Rate=2e-6",
                                                    "Lifetime/Maximum depth=0.003", "Lifetime/Maximum updates=4"});
  const std::string summary = results.dump();
  EXPECT_NE(summary.find("\"wear_source\": \"toy\""), std::string::npos) << summary;
  EXPECT_NEAR(results["lifetime"]["predicted_tonnes_to_end_of_life"].number(), 1500.0, 1.5) << summary;
}

// the outputs that hold the wear field's volume are named after the field (Output/Wear field):
// an Oka run's trajectory and summary say oka_volume, and none says archard
TEST(ToyWearSource, NamesItsOutputsAfterTheWearField)
{
  std::string            dir;
  const abrade::io::Json results =
    run_analytic_lifetime("abrade_toy_wear_field",
                          {"Lifetime/Wear source=toy", "Lifetime/Toy/Rate=2e-6", "Lifetime/Maximum depth=0.003",
                           "Lifetime/Maximum updates=1", "Output/Wear field=oka_volume"},
                          &dir);
  const std::string summary = results.dump();
  EXPECT_NE(summary.find("\"oka_volume\""), std::string::npos) << summary;
  EXPECT_NE(summary.find("\"worn_over_oka\""), std::string::npos) << summary;
  std::ifstream trajectory(dir + "/trajectory.csv");
  std::string   header;
  std::getline(trajectory, header);
  EXPECT_NE(header.find(",oka_volume,swept_over_oka,"), std::string::npos) << header;
  EXPECT_EQ(header.find("archard"), std::string::npos) << header;
  EXPECT_EQ(summary.find("archard"), std::string::npos) << summary;
}
