#include "slamtune/report/front_end_json.h"

#include <gtest/gtest.h>

namespace slamtune::report {
namespace {

TEST(FrontEndEvidenceJson, CarriesBothKindsOfStretchAndTheVerdict) {
  slam::FrontEndEvidence e;
  e.matches = 100;
  e.median_response = 0.8;
  e.breaks = 0;
  e.degenerate = 70;
  e.degenerate_stretches.push_back(
      {.first_log_index = 10, .last_log_index = 150, .matches = 70, .length_m = 34.5, .max_anisotropy = 7.5});
  const nlohmann::json j = FrontEndEvidenceJson(e);
  EXPECT_EQ(j["sequential_matches"], 100);
  EXPECT_EQ(j["points_at_front_end"], true);
  EXPECT_TRUE(j["stretches"].empty());
  ASSERT_EQ(j["degenerate_stretches"].size(), 1u);
  EXPECT_EQ(j["degenerate_stretches"][0]["last_log_index"], 150);
  EXPECT_DOUBLE_EQ(j["degenerate_stretches"][0]["length_m"].get<double>(), 34.5);

  e.degenerate_stretches.clear();
  EXPECT_EQ(FrontEndEvidenceJson(e)["points_at_front_end"], false);
}

}  // namespace
}  // namespace slamtune::report
