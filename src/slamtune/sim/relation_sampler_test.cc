#include "slamtune/sim/relation_sampler.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

// Two laps of a circle of radius 5 m at 0.5 m/s, 5 poses per second (62.8 s per lap).
std::vector<io::TimedPose> TwoLaps() {
  std::vector<io::TimedPose> truth;
  for (int k = 0; k <= 650; ++k) {
    const double t = 10.0 + k * 0.2, a = 0.1 * t;  // angular rate 0.5 / 5
    truth.push_back({t, Pose2{5 * std::cos(a), 5 * std::sin(a), NormalizeAngle(a + kPi / 2)}});
  }
  return truth;
}

TEST(SampleRelations, DeltasAreRelativeTruePoses) {
  const auto truth = TwoLaps();
  std::map<double, Pose2> by_time;
  for (const auto& p : truth) by_time[p.time] = p.pose;
  const RelationSample sample = SampleRelations(truth, RelationSamplingOptions());
  ASSERT_FALSE(sample.relations.empty());
  EXPECT_EQ(sample.relations.size(), sample.local_pairs + sample.revisit_pairs);
  for (const io::Relation& r : sample.relations) {
    ASSERT_TRUE(by_time.count(r.t1) && by_time.count(r.t2));
    EXPECT_LT(r.t1, r.t2);
    const Pose2 expected = Between(by_time[r.t1], by_time[r.t2]);
    EXPECT_DOUBLE_EQ(r.delta.x, expected.x);
    EXPECT_DOUBLE_EQ(r.delta.y, expected.y);
    EXPECT_DOUBLE_EQ(r.delta.theta, expected.theta);
  }
}

TEST(SampleRelations, LocalPairsSpanTheGapAndRevisitsCloseTheLap) {
  const auto truth = TwoLaps();
  const RelationSample sample = SampleRelations(truth, RelationSamplingOptions());
  // Local: every 5th pose from the 2 s mark on (t = 12.0, 13.0, ...): 130 - 1 pairs of exactly 2 s.
  EXPECT_EQ(sample.local_pairs, 129u);
  // Revisits: only possible one lap (62.8 s) apart; the second lap starts at index 314.
  EXPECT_GE(sample.revisit_pairs, 60u);
  EXPECT_LE(sample.revisit_pairs, 75u);
  for (const io::Relation& r : sample.relations) {
    const double gap = r.t2 - r.t1;
    const double distance = std::hypot(r.delta.x, r.delta.y);
    if (gap < 30.0) {
      EXPECT_NEAR(gap, 2.0, 1e-9);
    } else {
      EXPECT_LE(distance, 1.0);
      EXPECT_NEAR(gap, 62.83, 2.1);  // about one lap earlier (1 m of arc = 2 s)
    }
  }
  EXPECT_NEAR(sample.longest_revisit_gap_s, 62.83, 2.1);
}

TEST(RelationSamplingOptions, ValidateNamesFieldValueAndRule) {
  RelationSamplingOptions options;
  options.stride = 0;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("relations stride = 0: must be >= 1")));
  options = RelationSamplingOptions();
  options.revisit_radius_m = 0;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("revisit_radius_m = 0")));
}

}  // namespace
}  // namespace slamtune::sim
