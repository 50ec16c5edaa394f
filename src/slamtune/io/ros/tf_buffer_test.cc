#include "slamtune/io/ros/tf_buffer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/io/testing/planar_transform.h"

namespace slamtune::io {
namespace {

using testing::Planar;

constexpr std::int64_t kSecond = 1000000000;

void ExpectPose(const Pose2& p, double x, double y, double theta, double tol = 1e-12) {
  EXPECT_NEAR(p.x, x, tol);
  EXPECT_NEAR(p.y, y, tol);
  EXPECT_NEAR(p.theta, theta, tol);
}

TEST(TfBuffer, ExactSampleIsReturnedAsRecordedAndBetweenSamplesInterpolated) {
  TfBuffer tf;
  tf.Add("odom", "base", 10 * kSecond, Planar(1.0, 2.0, 0.1), false);
  tf.Add("odom", "base", 10 * kSecond + kSecond / 10, Planar(2.0, 2.0, 0.3), false);
  const TfLookup exact = tf.Lookup("odom", "base", 10 * kSecond);
  ASSERT_TRUE(exact.transform) << exact.failure;
  EXPECT_EQ(exact.transform->translation.x(), 1.0);
  EXPECT_EQ(exact.transform->rotation.coeffs(), Planar(1.0, 2.0, 0.1).rotation.coeffs());
  const TfLookup mid = tf.Lookup("odom", "base", 10 * kSecond + kSecond / 40);  // a quarter of the way
  ASSERT_TRUE(mid.transform);
  ExpectPose(ToPose2(*mid.transform), 1.25, 2.0, 0.15);
}

TEST(TfBuffer, InterpolatesYawAcrossTheWrapAlongTheShorterArc) {
  TfBuffer tf;
  tf.Add("odom", "base", 0, Planar(0, 0, 3.1), false);
  tf.Add("odom", "base", kSecond / 10, Planar(0, 0, -3.1), false);
  const TfLookup mid = tf.Lookup("odom", "base", kSecond / 20);
  ASSERT_TRUE(mid.transform);
  EXPECT_NEAR(std::fabs(ToPose2(*mid.transform).theta), M_PI, 1e-9);
}

TEST(TfBuffer, NoExtrapolationAndNoBridgingOfGaps) {
  TfBuffer tf;
  tf.Add("odom", "base", 1 * kSecond, Planar(0, 0, 0), false);
  tf.Add("odom", "base", 2 * kSecond, Planar(1, 0, 0), false);
  tf.Add("odom", "base", 2 * kSecond + kSecond / 10, Planar(1.1, 0, 0), false);
  EXPECT_THAT(tf.Lookup("odom", "base", kSecond / 2).failure, ::testing::HasSubstr("outside its samples"));
  EXPECT_THAT(tf.Lookup("odom", "base", 3 * kSecond).failure, ::testing::HasSubstr("outside its samples"));
  EXPECT_THAT(tf.Lookup("odom", "base", 3 * kSecond / 2).failure, ::testing::HasSubstr("gap"));
  EXPECT_TRUE(tf.Lookup("odom", "base", 2 * kSecond + kSecond / 20).transform);
  EXPECT_TRUE(tf.Lookup("odom", "base", 3 * kSecond / 2, 1.5).transform);  // a wider gap allowed
}

// A gap limit beyond what nanoseconds in an int64 hold is no limit; a negative one bridges no
// gap (the conversion to nanoseconds was undefined behaviour: a fuzzer's finding).
TEST(TfBuffer, AGapLimitOfAnySizeIsHeldToNanosecondsThatExist) {
  TfBuffer tf;
  tf.Add("odom", "base", 1 * kSecond, Planar(0, 0, 0), false);
  tf.Add("odom", "base", 2 * kSecond, Planar(1, 0, 0), false);
  EXPECT_TRUE(tf.Lookup("odom", "base", 3 * kSecond / 2, 1e300).transform);
  EXPECT_TRUE(tf.Lookup("odom", "base", 3 * kSecond / 2, 1e10).transform);
  EXPECT_THAT(tf.Lookup("odom", "base", 3 * kSecond / 2, -1e300).failure, ::testing::HasSubstr("gap"));
  EXPECT_TRUE(tf.Lookup("odom", "base", 1 * kSecond, -1e300).transform);  // a sample itself needs no gap
}

// A transform published the wrong way round closes a loop: tf2 refuses lookups through it, and
// the buffer names it, as the transforms go, from any frame whose path up the tree enters it.
TEST(TfBuffer, LoopsAreNamedAsTheTransformsGo) {
  TfBuffer tf;
  tf.Add("odom", "base_link", 0, Planar(1, 0, 0), false);
  tf.Add("base_link", "laser", 0, Planar(0.1, 0, 0), true);
  tf.Add("laser", "odom", 0, Planar(0, 0, 0), true);   // odom had no parent yet: accepted
  tf.Add("map", "camera", 0, Planar(0, 0, 0), true);   // a tree beside it, without a loop
  tf.Add("laser", "sonar", 0, Planar(0, 0, 0), true);  // a branch off the loop
  const std::vector<std::string> loop = {"base_link", "laser", "odom", "base_link"};
  EXPECT_EQ(tf.LoopAbove("base_link"), loop);
  EXPECT_EQ(tf.LoopAbove("laser"), (std::vector<std::string>{"laser", "odom", "base_link", "laser"}));
  EXPECT_EQ(tf.LoopAbove("sonar"), (std::vector<std::string>{"laser", "odom", "base_link", "laser"}));
  EXPECT_TRUE(tf.LoopAbove("camera").empty());
  EXPECT_TRUE(tf.LoopAbove("unknown").empty());
  EXPECT_EQ(tf.Loops(), std::vector<std::vector<std::string>>{loop});
  // Two frames that are each other's parent; and the tree without loops.
  TfBuffer pair;
  pair.Add("a", "b", 0, Planar(0, 0, 0), true);
  pair.Add("b", "a", 0, Planar(0, 0, 0), false);
  EXPECT_EQ(pair.Loops(), (std::vector<std::vector<std::string>>{{"a", "b", "a"}}));
  TfBuffer tree;
  tree.Add("odom", "base_link", 0, Planar(1, 0, 0), false);
  EXPECT_TRUE(tree.Loops().empty());
}

// tf2 refuses a frame as its own parent and empty frame ids; so does the buffer, counting them.
TEST(TfBuffer, SelfTransformsAndEmptyFrameIdsAreRefused) {
  TfBuffer tf;
  EXPECT_FALSE(tf.Add("base_link", "base_link", 0, Planar(0, 0, 0), true));
  EXPECT_FALSE(tf.Add("", "laser", 0, Planar(0, 0, 0), true));
  EXPECT_FALSE(tf.Add("base_link", "", 0, Planar(0, 0, 0), true));
  EXPECT_EQ(tf.refused_frames(), 3u);
  EXPECT_FALSE(tf.HasFrame("base_link"));
  EXPECT_TRUE(tf.Loops().empty());
}

TEST(TfBuffer, StaticChainComposesAndProjects) {
  TfBuffer tf;
  tf.Add("base_footprint", "base_link", 0, Planar(0, 0, 0, 0.1), true);
  tf.Add("base_link", "laser", 0, Planar(0.12, -0.04, 0.05, 0.25), true);
  tf.Add("odom", "base_footprint", 5 * kSecond, Planar(3, 4, 1.0), false);
  const TfLookup offset = tf.Lookup("base_footprint", "laser", 123 * kSecond);  // static: any time
  ASSERT_TRUE(offset.transform) << offset.failure;
  EXPECT_EQ(offset.transform->translation.x(), 0.12);  // identity parent: exact
  EXPECT_EQ(offset.transform->translation.y(), -0.04);
  EXPECT_NEAR(offset.transform->translation.z(), 0.35, 1e-15);
  EXPECT_NEAR(YawOf(offset.transform->rotation), 0.05, 1e-15);
  // odom -> laser through the tree = odom -> base (+) offset.
  const TfLookup laser = tf.Lookup("odom", "laser", 5 * kSecond);
  ASSERT_TRUE(laser.transform);
  const Pose2 expected = Compose(Pose2{3, 4, 1.0}, Pose2{0.12, -0.04, 0.05});
  ExpectPose(ToPose2(*laser.transform), expected.x, expected.y, expected.theta);
  // And the other way round: the inverse.
  const TfLookup back = tf.Lookup("laser", "odom", 5 * kSecond);
  ASSERT_TRUE(back.transform);
  const Pose2 inverse = Inverse(expected);
  ExpectPose(ToPose2(*back.transform), inverse.x, inverse.y, inverse.theta);
  EXPECT_EQ(tf.PathToRoot("laser"), (std::vector<std::string>{"laser", "base_link", "base_footprint", "odom"}));
}

TEST(TfBuffer, UnknownOrUnconnectedFramesSayWhy) {
  TfBuffer tf;
  tf.Add("odom", "base", 0, Planar(0, 0, 0), true);
  tf.Add("map", "other", 0, Planar(0, 0, 0), true);
  EXPECT_THAT(tf.Lookup("odom", "laser", 0).failure, ::testing::HasSubstr("'laser' is in no transform"));
  EXPECT_THAT(tf.Lookup("odom", "other", 0).failure, ::testing::HasSubstr("not connected"));
}

TEST(TfBuffer, SecondParentAndBadRotationsAreRefusedAndCounted) {
  TfBuffer tf;
  EXPECT_TRUE(tf.Add("odom", "base", 0, Planar(0, 0, 0), false));
  EXPECT_FALSE(tf.Add("map", "base", 1, Planar(0, 0, 0), false));
  RigidTransform3 bad = Planar(0, 0, 0);
  bad.rotation = Eigen::Quaterniond(0, 0, 0, 0);
  EXPECT_FALSE(tf.Add("odom", "base", 2, bad, false));
  bad = Planar(std::nan(""), 0, 0);
  EXPECT_FALSE(tf.Add("odom", "base", 3, bad, false));
  EXPECT_EQ(tf.parent_conflicts(), 1u);
  EXPECT_EQ(tf.bad_rotations(), 2u);
  EXPECT_EQ(tf.ParentOf("base"), "odom");
}

TEST(TfBuffer, OutOfOrderSamplesAreSortedBeforeLookup) {
  TfBuffer tf;
  tf.Add("odom", "base", 2 * kSecond / 10, Planar(2, 0, 0), false);
  tf.Add("odom", "base", 0, Planar(0, 0, 0), false);
  const TfLookup mid = tf.Lookup("odom", "base", kSecond / 10);
  ASSERT_TRUE(mid.transform);
  EXPECT_NEAR(mid.transform->translation.x(), 1.0, 1e-12);
}

TEST(TfBuffer, UpsideDownLaserHasItsZAxisDown) {
  RigidTransform3 t = Planar(0, 0, 0.3);
  t.rotation = t.rotation * Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, Eigen::Vector3d::UnitX()));
  EXPECT_LT((t.rotation * Eigen::Vector3d::UnitZ()).z(), 0.0);
  EXPECT_NEAR(YawOf(t.rotation), 0.3, 1e-12);
}

}  // namespace
}  // namespace slamtune::io
