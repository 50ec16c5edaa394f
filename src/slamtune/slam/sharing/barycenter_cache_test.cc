#include "slamtune/slam/sharing/barycenter_cache.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/same_bits.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::SameBits;

// The barycentre a scan computes itself at `pose` (no cache).
Pose2 OwnBarycenter(LaserScan scan, const Pose2& pose) {
  scan.SetCorrectedPose(pose);
  return scan.barycenter();
}

TEST(BarycenterCache, ServesTheSameScanAtTheSamePoseBitForBit) {
  const LaserScan scan = testing::CastScan(testing::AsymmetricRoom(), testing::CarmenLikeLaser(), {2.0, 2.0, 0.3});
  const Pose2 pose{2.01, 1.98, 0.31};
  BarycenterCache cache;
  LaserScan first = scan;
  first.SetCorrectedPose(pose);
  cache.Provide(first);
  EXPECT_EQ(cache.counters().misses, 1u);
  EXPECT_EQ(cache.counters().entries, 1u);

  LaserScan second = scan;  // another run's copy: same readings, same pose
  second.SetCorrectedPose(pose);
  ASSERT_FALSE(second.barycenter_known());
  cache.Provide(second);
  EXPECT_EQ(cache.counters().hits, 1u);
  ASSERT_TRUE(second.barycenter_known());
  EXPECT_TRUE(SameBits(second.barycenter(), OwnBarycenter(scan, pose)));
  // The readout computed later agrees with the served barycentre (it checks, slam/laser_scan.h).
  EXPECT_EQ(second.filtered_points().size(), first.filtered_points().size());
  // Known already: nothing looked up.
  cache.Provide(second);
  EXPECT_EQ(cache.counters().hits + cache.counters().misses, 2u);
}

TEST(BarycenterCache, AnyChangeOfPoseReadingsOrLaserIsAMiss) {
  const auto room = testing::AsymmetricRoom();
  const LaserScan scan = testing::CastScan(room, testing::CarmenLikeLaser(), {2.0, 2.0, 0.3});
  const Pose2 pose{2.0, 2.0, 0.3};
  BarycenterCache cache;
  LaserScan base = scan;
  cache.Provide(base);

  // One ulp of heading.
  LaserScan turned = scan;
  const Pose2 nudged{pose.x, pose.y, std::nextafter(pose.theta, 1.0)};
  turned.SetCorrectedPose(nudged);
  cache.Provide(turned);
  EXPECT_TRUE(SameBits(turned.barycenter(), OwnBarycenter(scan, nudged)));
  // Other readings (a scan cast elsewhere, placed at the same pose).
  LaserScan other = testing::CastScan(room, testing::CarmenLikeLaser(), {8.5, 4.5, 2.5});
  other.SetCorrectedPose(pose);
  cache.Provide(other);
  // The same readings under another laser (range threshold), same pose.
  auto laser = std::make_shared<LaserGeometry>(scan.geometry());
  laser->range_threshold = 3.0;
  LaserScan clipped(laser, scan.ranges_ptr(), pose, scan.time());
  cache.Provide(clipped);
  EXPECT_TRUE(SameBits(clipped.barycenter(), OwnBarycenter(clipped, pose)));
  EXPECT_FALSE(SameBits(clipped.barycenter(), base.barycenter()));
  EXPECT_EQ(cache.counters().hits, 0u);
  EXPECT_EQ(cache.counters().misses, 4u);
  EXPECT_EQ(cache.counters().entries, 4u);
}

TEST(BarycenterCache, StaysWithinItsBudgetAndKeepsServingCorrectValues) {
  const LaserScan scan = testing::CastScan(testing::AsymmetricRoom(), testing::CarmenLikeLaser(), {2.0, 2.0, 0.3});
  BarycenterCache cache(2048);  // room for a handful of entries
  for (int round = 0; round < 2; ++round) {
    for (int k = 0; k < 50; ++k) {
      const Pose2 pose{2.0 + 0.01 * k, 2.0, 0.3};
      LaserScan s = scan;
      s.SetCorrectedPose(pose);
      cache.Provide(s);
      ASSERT_TRUE(SameBits(s.barycenter(), OwnBarycenter(scan, pose))) << k;
    }
  }
  const CacheCounters c = cache.counters();
  EXPECT_GT(c.evictions, 0u);
  EXPECT_LE(c.bytes, 2048u);
  EXPECT_EQ(c.hits + c.misses, 100u);
}

TEST(BarycenterCache, ConcurrentCallersGetTheSameValues) {
  const LaserScan scan = testing::CastScan(testing::AsymmetricRoom(), testing::CarmenLikeLaser(), {2.0, 2.0, 0.3});
  BarycenterCache cache;
  std::vector<Pose2> expected;
  for (int k = 0; k < 40; ++k) expected.push_back(OwnBarycenter(scan, {2.0, 2.0 + 0.02 * k, 0.3 - 0.01 * k}));
  std::vector<int> wrong(3, 0);
  std::vector<std::thread> threads;
  for (int t = 0; t < 3; ++t) {
    threads.emplace_back([&, t] {
      for (int k = 0; k < 40; ++k) {
        LaserScan s = scan;
        s.SetCorrectedPose({2.0, 2.0 + 0.02 * k, 0.3 - 0.01 * k});
        cache.Provide(s);
        wrong[t] += !SameBits(s.barycenter(), expected[k]);
      }
    });
  }
  for (std::thread& t : threads) t.join();
  EXPECT_EQ(wrong, std::vector<int>(3, 0));
  EXPECT_EQ(cache.counters().entries, 40u);
}

TEST(BarycenterCache, ZeroBudgetIsAnInputError) { EXPECT_THROW(BarycenterCache(0), InputError); }

}  // namespace
}  // namespace slamtune::slam
