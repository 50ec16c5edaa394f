#include "slamtune/metrics/gt_error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_reader.h"

namespace slamtune::metrics {
namespace {

using ::testing::ElementsAre;

std::vector<io::TimedPose> RandomWalk(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> step(0.0, 0.3);
  std::vector<io::TimedPose> poses;
  Pose2 pose;
  for (std::size_t i = 0; i < n; ++i) {
    poses.push_back({1000.0 + 0.2 * static_cast<double>(i), pose});
    pose = Compose(pose, Pose2{0.5 + step(rng), step(rng), step(rng)});
  }
  return poses;
}

TEST(GtErrorTest, TrajectoryEqualToTheTruthHasZeroError) {
  const auto truth = RandomWalk(50, 42);
  std::vector<io::Relation> relations;
  for (std::size_t i = 0; i + 7 < truth.size(); i += 3) {
    relations.push_back({truth[i].time, truth[i + 7].time, Between(truth[i].pose, truth[i + 7].pose), 0});
  }
  const GtError e = ComputeGtError(truth, relations);
  EXPECT_EQ(e.relations_used, relations.size());
  EXPECT_EQ(e.relations_missing, 0u);
  EXPECT_NEAR(e.trans_mean_m, 0.0, 1e-12);
  EXPECT_NEAR(e.rot_mean_deg, 0.0, 1e-10);
  EXPECT_NEAR(e.trans_sq_mean, 0.0, 1e-20);
  EXPECT_NEAR(e.trans_max_m, 0.0, 1e-12);
  // The error is invariant to a global rigid motion of the estimate.
  std::vector<io::TimedPose> moved = truth;
  for (auto& p : moved) p.pose = Compose(Pose2{10, -5, 2.0}, p.pose);
  EXPECT_NEAR(ComputeGtError(moved, relations).trans_max_m, 0.0, 1e-9);
}

TEST(GtErrorTest, KnownPerturbationGivesTheHandComputedValues) {
  const std::vector<io::TimedPose> estimate = {
      {1.0, {0, 0, 0}}, {2.0, {1.1, 0.2, 0.1}}, {3.0, {5, 5, 0}}, {4.0, {6, 5, kPi / 2}}};
  const std::vector<io::Relation> relations = {
      // delta (1,0,0) vs estimate (1.1,0.2,0.1): err = (0.1, 0.2, 0.1 rad).
      {1.0, 2.0, {1.0, 0.0, 0.0}, 1},
      // delta (0,0,pi/2) vs estimate (1,0,pi/2): err = R(-pi/2)(1,0) = (0,-1), heading 0.
      {3.0, 4.0, {0.0, 0.0, kPi / 2}, 2}};
  const GtError e = ComputeGtError(estimate, relations);
  const double t1 = std::sqrt(0.05), t2 = 1.0;
  const double r1 = 0.1 * 180.0 / kPi, r2 = 0.0;
  EXPECT_EQ(e.relations_used, 2u);
  EXPECT_NEAR(e.trans_mean_m, (t1 + t2) / 2, 1e-12);
  EXPECT_NEAR(e.trans_std_m, (t2 - t1) / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e.rot_mean_deg, (r1 + r2) / 2, 1e-10);
  EXPECT_NEAR(e.rot_std_deg, r1 / std::sqrt(2.0), 1e-10);
  EXPECT_NEAR(e.trans_sq_mean, (0.05 + 1.0) / 2, 1e-12);
  EXPECT_NEAR(e.trans_sq_std, (1.0 - 0.05) / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(e.rot_sq_mean, r1 * r1 / 2, 1e-9);
  EXPECT_NEAR(e.rot_sq_std, r1 * r1 / std::sqrt(2.0), 1e-9);
  EXPECT_NEAR(e.trans_max_m, 1.0, 1e-12);
  EXPECT_NEAR(e.rot_max_deg, r1, 1e-10);
}

TEST(GtErrorTest, MissingTimestampsAreCountedAndNamed) {
  const std::vector<io::TimedPose> estimate = {{10.0, {}}, {11.0, {1, 0, 0}}};
  const std::vector<io::Relation> relations = {
      {10.0, 11.0, {1, 0, 0}, 1}, {10.0, 12.5, {1, 0, 0}, 2}, {9.0, 12.5, {1, 0, 0}, 3}, {9.5, 11.0, {1, 0, 0}, 0}};
  const GtError e = ComputeGtError(estimate, relations);
  EXPECT_EQ(e.relations_used, 1u);
  EXPECT_EQ(e.relations_missing, 3u);
  EXPECT_THAT(e.missing_examples, ElementsAre("line 2: t2 12.500000 not in the trajectory",
                                              "line 3: t1 9.000000 and t2 12.500000 not in the trajectory",
                                              "t1 9.500000 not in the trajectory"));
  EXPECT_EQ(e.trans_std_m, 0.0);  // one relation used
  GtErrorOptions few;
  few.max_missing_examples = 1;
  EXPECT_EQ(ComputeGtError(estimate, relations, few).missing_examples.size(), 1u);
}

TEST(GtErrorTest, TimestampsMatchWithinTheTolerance) {
  // Relations with 5 decimals against a log with 6 (mit-csail).
  const std::vector<io::TimedPose> estimate = {
      {1134864643.124184, {}}, {1134864643.124199, {9, 9, 0}}, {1134864650.000000, {1, 0, 0}}};
  const std::vector<io::Relation> relations = {{1134864643.12418, 1134864650.0, {1, 0, 0}, 1}};
  const GtError e = ComputeGtError(estimate, relations);
  EXPECT_EQ(e.relations_used, 1u);
  EXPECT_NEAR(e.trans_mean_m, 0.0, 1e-12);  // the nearer of the two candidates was taken
  GtErrorOptions strict;
  strict.time_tolerance_s = 1e-6;
  EXPECT_EQ(ComputeGtError({{100.0, {}}, {200.0, {}}}, {{100.00002, 200.0, {}, 1}}).relations_missing, 1u);
  EXPECT_EQ(ComputeGtError(estimate, relations, strict).relations_missing, 1u);  // 4e-6 s off
}

TEST(GtErrorTest, NothingUsedGivesNanAndBadOptionsThrow) {
  const GtError e = ComputeGtError({}, {{1, 2, {}, 1}});
  EXPECT_EQ(e.relations_used, 0u);
  EXPECT_TRUE(std::isnan(e.trans_mean_m));
  EXPECT_TRUE(std::isnan(e.rot_std_deg));
  GtErrorOptions bad;
  bad.time_tolerance_s = -1;
  try {
    ComputeGtError({}, {}, bad);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_STREQ(error.what(), "time_tolerance_s = -1: must be a finite number of seconds >= 0");
  }
}

TEST(GtErrorTest, FieldsUseTheJsonKeys) {
  GtError e;
  e.trans_mean_m = 1.5;
  e.relations_used = 7;
  const auto fields = GtErrorFields(e);
  ASSERT_GE(fields.size(), 12u);
  EXPECT_EQ(fields[0].first, "trans_mean_m");
  EXPECT_EQ(fields[0].second, 1.5);
  EXPECT_EQ(fields[10].first, "relations_used");
  EXPECT_EQ(fields[10].second, 7.0);
}

// Raw odometry (the FLASER laser poses) scored against the shared relations: every relation
// timestamp is found (mit-csail needs the 1e-5 s tolerance) and the error is clearly non-zero.
TEST(GtErrorTest, SharedLogOdometryAgainstItsRelations) {
  const std::string dir = SLAMTUNE_DATASETS_DIR;
  if (!std::filesystem::exists(dir + "/mit-csail.clf.gz")) GTEST_SKIP() << "datasets not available: " << dir;
  const io::LaserLog log = io::ReadCarmenLog(dir + "/mit-csail.clf.gz");
  std::vector<io::TimedPose> odometry;
  for (const auto& scan : log.scans) odometry.push_back({scan.ipc_time, scan.laser_pose});
  const GtError e = ComputeGtError(odometry, io::ReadRelations(dir + "/mit-csail.relations"));
  EXPECT_EQ(e.relations_missing, 0u);
  EXPECT_EQ(e.relations_used, 1172u);
  EXPECT_GT(e.trans_mean_m, 0.01);
  EXPECT_GT(e.rot_mean_deg, 0.1);
  RecordProperty("csail_odometry_trans_mean_m", std::to_string(e.trans_mean_m));
}

}  // namespace
}  // namespace slamtune::metrics
