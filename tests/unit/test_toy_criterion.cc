// A new end-of-life criterion is one file and one registration line (end_of_life_criterion.h):
// this test is that file. Its toy criterion, the largest wear depth below the design at the
// followed points (Lifetime/Recession points), is registered here, outside the library, and
// must then be declared, read, followed and able to end a life without a change anywhere else.
//
// The truth it is checked against: under a known uniform wear rate r (Wear source = analytic,
// depth), every point of a flat face lies r t below the design after t tonnes (the offset
// surface), so the life to a limit L is L / r: 3 mm at 1 um/t is 3000 t, crossed exactly at the
// end of the second 1500 t update. The run's own depth criterion is switched off (0), so only
// the toy can end it.
#include "lifetime_in_process.h"

#include <abrade/coupling/lifetime/end_of_life_criterion.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace
{
  using namespace abrade::coupling::lifetime;

  class MaximumPointDepth : public EndOfLifeCriterion
  {
  public:
    std::string parameter() const override { return "Maximum point depth"; }
    std::string name() const override { return "maximum point depth"; }
    void        declare_parameters(dealii::ParameterHandler &prm) const override
    {
      prm.declare_entry(parameter(), "0", dealii::Patterns::Double(0),
                        "[m] End of life: the largest wear depth at the Recession points; 0: no limit.");
    }
    void   parse_parameters(dealii::ParameterHandler &prm) override { maximum = prm.get_double(parameter()); }
    bool   active() const override { return maximum > 0; }
    double limit(const PartNow &, std::vector<std::string> &) const override { return maximum; }
    double value(const PartNow &now) const override
    {
      const auto d = now.part.wear_depth_below(now.followed_points);
      return *std::max_element(d.begin(), d.end());
    }
    std::vector<double> bed_rates(const PartNow &now, const BedRates &beds) const override
    {
      const auto        d       = now.part.wear_depth_below(now.followed_points);
      const std::size_t deepest = std::size_t(std::max_element(d.begin(), d.end()) - d.begin());
      std::vector<double> rates;
      for (const auto &bed : beds.followed)
        rates.push_back(bed[deepest]);
      return rates;
    }
    std::vector<double> where(const PartNow &now, const std::vector<double> &, bool) const override
    {
      const auto  d = now.part.wear_depth_below(now.followed_points);
      const auto &p = now.followed_points[std::size_t(std::max_element(d.begin(), d.end()) - d.begin())];
      return {p[0], p[1], p[2]};
    }
    std::string section_label() const override { return "depth at the followed point "; }

  private:
    double maximum = 0;
  };
} // namespace

ABRADE_REGISTER_END_OF_LIFE_CRITERION(MaximumPointDepth);

// registered beside the library's own, in the order of the names
TEST(ToyCriterion, IsRegisteredWithTheBuiltInOnes)
{
  std::vector<std::string> names;
  for (const auto &c : make_end_of_life_criteria())
    names.push_back(c->name());
  EXPECT_EQ(names, (std::vector<std::string>{"maximum depth", "maximum edge recession", "maximum point depth",
                                             "maximum recession", "maximum worn mass", "minimum plate thickness"}));
}

// its key is a parameter of subsection Lifetime like any other (abrade params, parameter files)
TEST(ToyCriterion, DeclaresItsParameter)
{
  abrade::coupling::ParameterFile p;
  auto                            &prm = p.handler();
  prm.enter_subsection("Lifetime");
  EXPECT_EQ(prm.get("Maximum point depth"), "0");
  EXPECT_EQ(prm.get("Maximum depth"), "0.012");
  prm.leave_subsection();
}

// a lifetime run that only the toy can end ends by it, at the analytic life
TEST(ToyCriterion, EndsALifeAtTheAnalyticCrossing)
{
  std::string      dir;
  abrade::io::Json results = run_analytic_lifetime("abrade_toy_criterion",
                                                   {"Lifetime/Maximum depth=0", "Lifetime/Maximum point depth=0.003",
                                                    "Lifetime/Maximum updates=4",
                                                    "Lifetime/Recession points=0.075, 0.03, 0.15"},
                                                   &dir);

  const std::string summary = results.dump();
  EXPECT_NE(summary.find("\"end_of_life_criterion\": \"maximum point depth\""), std::string::npos) << summary;
  EXPECT_NEAR(results["lifetime"]["predicted_tonnes_to_end_of_life"].number(), 3000.0, 3.0) << summary;
  // where: the toy's where(), the followed point
  EXPECT_NE(summary.find("\"end_of_life_where\": [0.075, 0.03, 0.15]"), std::string::npos) << summary;
  // it was followed and kept like the others: in the checkpoint, under its name
  std::ifstream      state(dir + "/checkpoint/loop-2.txt");
  std::ostringstream text;
  text << state.rdbuf();
  EXPECT_NE(text.str().find("history_maximum_point_depth"), std::string::npos);
}
