// Lifetime/Calibration's reading of calibration.json (wear_calibration.h), by hand-written files:
// the life's calibration component from W's error and the footprint's share along the ridge,
// each number worked out here from its definition, not through the reader's arithmetic.
//  - the footprint's share is |d ln L / d ln r| se(ln r), with the candidates' lives;
//  - without them (dlnlife_dlnr 0) it is |d ln W / d ln r| se(ln r), and the reader says so;
//  - the candidates' own error in W at the footprint widens W's error by itself over t(dof).
#include <abrade/coupling/lifetime/wear_calibration.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

using namespace abrade::coupling::lifetime;

namespace
{
  std::string write(const std::string &name, double dlnlife_dlnr, double candidate_sensitivity)
  {
    const std::string path = std::string(::testing::TempDir()) + name;
    std::ofstream(path) << R"({"runs": [{"run": "a", "archard_coefficient": 2e-14, "scale": 1,
      "scale_standard_error_fit": 0.03, "scale_standard_error_replicates": 0.04, "degrees_of_freedom": 6,
      "smoothing_radius": 0.0275}],
      "footprint": {"identifiable": true, "smoothing_radius": 0.014, "wear_coefficient": 3e-14,
        "log_smoothing_radius_standard_error": 0.05, "degrees_of_freedom": 8, "dlnw_dlnr": 0.2,
        "dlnlife_dlnr": )" << dlnlife_dlnr << R"(, "log_wear_coefficient_standard_error": 0.04,
        "wear_coefficient_degrees_of_freedom": 4, "log_wear_coefficient_candidate_sensitivity": )"
                           << candidate_sensitivity << "}}";
    return path;
  }
} // namespace

TEST(WearCalibration, FootprintShareFromTheLivesSlope)
{
  const WearCalibration c = read_wear_calibration(write("with_lives.json", -0.5, 0));
  EXPECT_TRUE(c.footprint);
  EXPECT_FALSE(c.footprint_slope_assumed);
  EXPECT_DOUBLE_EQ(c.coefficient, 3e-14);
  EXPECT_DOUBLE_EQ(c.smoothing_radius, 0.014);
  EXPECT_NEAR(c.footprint_relative_sd, 0.5 * 0.05, 1e-15);
  EXPECT_NEAR(c.relative_sd, std::sqrt(0.04 * 0.04 + 0.025 * 0.025), 1e-12);
  EXPECT_DOUBLE_EQ(c.dof, 4); // (the smaller of W's 4 and the footprint's 8)
}

TEST(WearCalibration, WithoutLivesTheRidgeSlopeStandsInAndIsSaid)
{
  const WearCalibration c = read_wear_calibration(write("without_lives.json", 0, 0));
  EXPECT_TRUE(c.footprint_slope_assumed);
  EXPECT_NEAR(c.footprint_relative_sd, 0.2 * 0.05, 1e-15);
}

TEST(WearCalibration, CandidatesOwnErrorWidensW)
{
  // t(0.975; 4) = 2.776445105
  const WearCalibration c = read_wear_calibration(write("candidates.json", -0.5, 0.03));
  const double          w = 0.04 + 0.03 / 2.776445105;
  EXPECT_NEAR(c.relative_sd, std::sqrt(w * w + 0.025 * 0.025), 1e-9);
}
