#include "slamtune/tune/trajectory_error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A straight drive of ten poses, 1 m and 1 s apart, and the relations of consecutive poses, the
// second one 0.1 m too long.
class TrajectoryErrorTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::UniqueTempDir("trajectory_error");
    std::vector<io::TimedPose> poses;
    for (int i = 0; i < 10; ++i) poses.push_back({100.0 + i, Pose2{1.0 * i, 0.0, 0.0}});
    io::WriteTrajectory((dir_ / "trajectory.txt").string(), poses);
    relations_ = {{100.0, 101.0, Pose2{1.0, 0.0, 0.0}, 0}, {101.0, 102.0, Pose2{1.1, 0.0, 0.0}, 0}};
    io::WriteRelations((dir_ / "drive.relations").string(), relations_);
    options_.trajectory = (dir_ / "trajectory.txt").string();
    options_.relations = (dir_ / "drive.relations").string();
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path dir_;
  std::vector<io::Relation> relations_;
  TrajectoryErrorOptions options_;
};

TEST_F(TrajectoryErrorTest, TheErrorOfEachRelationIsAveraged) {
  const metrics::GtError error = TrajectoryError(options_);
  EXPECT_EQ(error.relations_used, 2u);
  EXPECT_EQ(error.relations_missing, 0u);
  EXPECT_NEAR(error.trans_mean_m, 0.05, 1e-9);
  EXPECT_NEAR(error.trans_max_m, 0.1, 1e-9);
  const nlohmann::ordered_json j = ToJson(error);
  EXPECT_EQ(j.begin().key(), "trans_mean_m");
  EXPECT_NEAR(j.at("trans_mean_m").get<double>(), 0.05, 1e-9);
  EXPECT_EQ(j.at("relations_used"), 2);
  EXPECT_TRUE(j.at("missing_examples").empty());
}

TEST_F(TrajectoryErrorTest, RelationsOutsideTheTrajectoryAreCountedAndNamed) {
  relations_.push_back({150.0, 151.0, Pose2{1.0, 0.0, 0.0}, 0});
  io::WriteRelations(options_.relations, relations_);
  const metrics::GtError error = TrajectoryError(options_);
  EXPECT_EQ(error.relations_used, 2u);
  EXPECT_EQ(error.relations_missing, 1u);
  EXPECT_EQ(ToJson(error).at("missing_examples").size(), 1u);
}

TEST_F(TrajectoryErrorTest, TheToleranceDecidesWhichTimestampsMatch) {
  relations_ = {{100.0004, 101.0, Pose2{1.0, 0.0, 0.0}, 0}};
  io::WriteRelations(options_.relations, relations_);
  EXPECT_THAT([&] { TrajectoryError(options_); }, ThrowsMessage<InputError>(HasSubstr("none of the 1 relations")));
  options_.error.time_tolerance_s = 1e-3;
  EXPECT_EQ(TrajectoryError(options_).relations_used, 1u);
}

TEST_F(TrajectoryErrorTest, EmptyRelationsABadToleranceAndNoMatchAreRefused) {
  options_.error.time_tolerance_s = -1;
  EXPECT_THAT([&] { TrajectoryError(options_); }, ThrowsMessage<InputError>(HasSubstr("time_tolerance_s")));
  options_.error.time_tolerance_s = 1e-5;
  std::ofstream(dir_ / "empty.relations").close();
  options_.relations = (dir_ / "empty.relations").string();
  EXPECT_THAT([&] { TrajectoryError(options_); }, ThrowsMessage<InputError>(HasSubstr("no relations in the file")));
  io::WriteRelations(options_.relations, {{500.0, 501.0, Pose2{1.0, 0.0, 0.0}, 0}});
  EXPECT_THAT([&] { TrajectoryError(options_); },
              ThrowsMessage<InputError>(HasSubstr("has both timestamps in the trajectory (e.g. ")));
}

TEST(TrajectoryErrorJson, NumbersThatAreNotFiniteAreNull) {
  metrics::GtError error;
  error.trans_mean_m = std::numeric_limits<double>::quiet_NaN();
  const nlohmann::ordered_json j = ToJson(error);
  EXPECT_TRUE(j.at("trans_mean_m").is_null());
  EXPECT_EQ(j.at("rot_mean_deg"), 0.0);
}

}  // namespace
}  // namespace slamtune::tune
