#include "slamtune/report/scan_losses_json.h"

#include <gtest/gtest.h>

namespace slamtune::report {
namespace {

// Every kind appears under its name; a cut-off tail has a null count and its bytes.
TEST(ScanLossesJson, EveryKindUnderItsNameWithItsCount) {
  io::LaserLog log;
  log.recording.emplace();
  log.recording->scans_unplaced = 3;
  log.recording->unplaced_examples = {"scan 4 at 1.000000 s: outside its samples"};
  log.recording->data_end.dropped_bytes = 120;
  log.recording->data_end.dropped_reason = "byte 900 (Chunk record): content length 500 runs past the end";
  const nlohmann::json j = ScanLossesJson(io::ReadingLosses(log, io::KartoLaserRule::kSlamKarto));
  std::vector<std::string> names;
  for (const auto& [name, value] : j.items()) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"cut_off", "malformed", "no_odometry", "wrong_reading_count"}));
  EXPECT_EQ(j["no_odometry"]["count"], 3);
  EXPECT_EQ(j["no_odometry"]["data_loss"], true);
  EXPECT_EQ(j["no_odometry"]["first"], "scan 4 at 1.000000 s: outside its samples");
  EXPECT_EQ(j["malformed"]["count"], 0);
  EXPECT_FALSE(j["malformed"].contains("first"));
  EXPECT_TRUE(j["cut_off"]["count"].is_null());
  EXPECT_EQ(j["cut_off"]["bytes"], 120);
  EXPECT_EQ(j["wrong_reading_count"]["by"]["slam_toolbox"], 0);
}

}  // namespace
}  // namespace slamtune::report
