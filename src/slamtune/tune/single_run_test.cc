#include "slamtune/tune/single_run.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/io/relations.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class SingleRun : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::UniqueTempDir("single_run");
    sim::Simulation s = sim::Simulate(sim::SimulationOptions{});
    io::WriteCarmenLog((dir_ / "office.clf").string(), s.log);
    io::WriteRelations((dir_ / "office.relations").string(), s.relations);
    options_.inputs.log = (dir_ / "office.clf").string();
    options_.inputs.relations = (dir_ / "office.relations").string();
    options_.inputs.input.max_scans = 300;
    options_.out = (dir_ / "out").string();
    options_.quiet = true;
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  RunOptions options_;
  Progress progress_{Progress::Mode::kQuiet};
};

TEST_F(SingleRun, WritesEveryFileAndTheErrorOfTheRelations) {
  const RunOutcome outcome = RunAndWrite(options_, progress_);
  for (const char* name : {"map.pgm", "map.yaml", "map.png", "trajectory.txt", "loop_closures.csv", "front_end.csv",
                           "front_end_map.png", "run.json"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(dir_ / "out" / name)) << name;
  }
  ASSERT_TRUE(outcome.error.has_value());
  EXPECT_GT(outcome.error->relations_used, 0u);
  EXPECT_EQ(outcome.run.trajectory.size(), 300u);
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(dir_ / "out" / "run.json"));
  EXPECT_EQ(run.at("scans"), 300);
  EXPECT_EQ(run.at("gt_error").at("relations_used"), outcome.error->relations_used);
  EXPECT_EQ(run.at("map").at("occupied_cells"), outcome.run.quality.occupied_cells);
  EXPECT_EQ(run.at("params").at("do_loop_closing"), true);
}

TEST_F(SingleRun, NoLoopClosureIsTheBaseWithoutIt) {
  options_.no_loop_closure = true;
  const RunOutcome outcome = RunAndWrite(options_, progress_);
  EXPECT_TRUE(outcome.run.summary.loop_closures.empty());
  const nlohmann::json run = nlohmann::json::parse(std::ifstream(dir_ / "out" / "run.json"));
  EXPECT_EQ(run.at("params").at("do_loop_closing"), false);
}

TEST_F(SingleRun, TheOutputFolderIsCheckedBeforeTheLogIsRead) {
  std::ofstream(dir_ / "file") << "x";
  options_.out = (dir_ / "file" / "out").string();
  options_.inputs.log = (dir_ / "missing.clf").string();
  EXPECT_THAT([&] { RunAndWrite(options_, progress_); }, ThrowsMessage<InputError>(HasSubstr("file/out")));
}

TEST(RunSummaryTexts, TheNodesRefusalsAreCountedByReason) {
  slam::RunSummary summary;
  EXPECT_EQ(NodeRefusalsText(summary, slam::NodeMode::kSlamToolboxSync), "");
  summary.scans_refused_by_node[static_cast<int>(slam::NodeVerdict::kNotMoved)] = 100;
  summary.scans_refused_by_node[static_cast<int>(slam::NodeVerdict::kTooSoon)] = 16;
  const std::string text = NodeRefusalsText(summary, slam::NodeMode::kSlamToolboxSync);
  EXPECT_THAT(text, ::testing::StartsWith("; " + std::string(slam::LaunchOf(slam::NodeMode::kSlamToolboxSync)) +
                                          " kept 116 scans from Karto ("));
  EXPECT_THAT(text, HasSubstr("100 not moved"));
  EXPECT_THAT(text, HasSubstr("16 too soon"));
}

TEST(RunSummaryTexts, TheErrorIsSaidOnlyWithRelations) {
  EXPECT_EQ(RelationErrorText(std::nullopt), "");
  metrics::GtError error;
  error.trans_mean_m = 0.0123;
  error.trans_std_m = 0.01;
  error.rot_mean_deg = 0.52;
  error.rot_std_deg = 0.4;
  error.relations_used = 812;
  EXPECT_EQ(RelationErrorText(error), ", error 0.0123 +- 0.0100 m, 0.52 +- 0.40 deg (812 relations)");
}

TEST_F(SingleRun, OneLaserIsNotListed) {
  const RunOutcome outcome = RunAndWrite(options_, progress_);
  EXPECT_EQ(LasersText(outcome.run.lasers, outcome.run.summary), "");
  EXPECT_THAT(RelationErrorText(outcome.error), HasSubstr(" relations)"));
}

}  // namespace
}  // namespace slamtune::tune
