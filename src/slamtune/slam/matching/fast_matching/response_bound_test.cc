// The response bound must never be below what the matcher finds (that would skip a near-chain
// edge Karto adds), and MayExceed must agree with the bound it stops computing early.
#include "slamtune/slam/matching/fast_matching/response_bound.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "slamtune/common/karto_math.h"
#include "slamtune/slam/matching/scan_matcher.h"
#include "slamtune/slam/params/mapper_params.h"
#include "slamtune/slam/testing/log_slice.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

// The sequential matchers of the two presets (slam_toolbox: wider window and smear,
// response expansion on), as the mapper builds them.
ScanMatcherOptions KartoSequential() { return MapperParams::Preset("slam_karto").SequentialMatcherOptions(12.0); }
ScanMatcherOptions ToolboxSequential() { return MapperParams::Preset("slam_toolbox").SequentialMatcherOptions(20.0); }

double BoundOf(ResponseBound& bound, const LaserScan& scan, const std::vector<const LaserScan*>& base) {
  return static_cast<double>(bound.MaxSumBound(scan, base)) / (100.0 * static_cast<double>(scan.ranges().size()));
}

// Checks, for one scan and chain: the bound is >= the matcher's response, and MayExceed(t)
// is exactly "bound > t" at thresholds around it. Returns the bound.
double CheckCase(ScanMatcher& matcher, ResponseBound& bound, const LaserScan& scan,
                 const std::vector<const LaserScan*>& base) {
  const double limit = BoundOf(bound, scan, base);
  const MatchResult m = matcher.Match(scan, base, Penalize::kNo, Refine::kYes);
  EXPECT_LE(m.response, limit) << "the bound is below the matcher's best response";
  for (const double t : {0.05, 0.3, 0.5, 0.8 - 1e-6, 0.95, limit - 1e-9, limit}) {
    EXPECT_EQ(bound.MayExceed(scan, base, t), limit > t) << "threshold " << t << ", bound " << limit;
  }
  return limit;
}

TEST(ResponseBound, NeverBelowTheBestResponseInTheSyntheticRoom) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> x(1.0, 9.0), y(1.0, 7.0), heading(-3.1, 3.1);
  std::uniform_real_distribution<double> jitter(-0.12, 0.12), turn(-0.3, 0.3);
  for (const ScanMatcherOptions& options : {KartoSequential(), ToolboxSequential()}) {
    ScanMatcher matcher(options);
    ResponseBound bound(options);
    int below = 0, above = 0;
    for (int trial = 0; trial < 40; ++trial) {
      const Pose2 truth{x(rng), y(rng), heading(rng)};
      // The scan at a perturbed pose; a chain of 3 scans taken elsewhere in the room, so
      // that the overlap ranges from none to most of the view.
      LaserScan scan = testing::AsymmetricRoomScan(truth);
      scan.SetSensorPose({truth.x + jitter(rng), truth.y + jitter(rng), truth.theta + turn(rng)});
      const Pose2 elsewhere{x(rng), y(rng), heading(rng)};
      std::vector<LaserScan> chain;
      for (int k = 0; k < 3; ++k) {
        chain.push_back(testing::AsymmetricRoomScan({elsewhere.x + 0.2 * k, elsewhere.y, elsewhere.theta + 0.1 * k}));
      }
      std::vector<const LaserScan*> base;
      for (const LaserScan& c : chain) base.push_back(&c);
      SCOPED_TRACE("trial " + std::to_string(trial));
      (CheckCase(matcher, bound, scan, base) < 0.8 ? below : above)++;
    }
    // The cases must exercise both outcomes, or the test proves nothing.
    EXPECT_GT(below, 0);
    EXPECT_GT(above, 0);
  }
}

// intel: real clutter and 81.83 m no-returns, whose reads wrap rows of the grid (§4.5).
TEST(ResponseBound, NeverBelowTheBestResponseOnAnIntelSlice) {
  const std::string path = testing::DatasetPath("intel.clf.gz");
  if (path.empty()) GTEST_SKIP() << "intel.clf.gz not found under SLAMTUNE_DATASETS_DIR";
  const std::vector<LaserScan> scans = testing::ReadLogSlice(path, 600);
  ASSERT_EQ(scans.size(), 600u);
  ScanMatcher matcher(KartoSequential());
  ResponseBound bound(KartoSequential());
  int below = 0, above = 0;
  for (std::size_t i = 100; i < scans.size(); i += 50) {
    // Chains of 10 scans from near (just before i) to far back in the log.
    for (const std::size_t back : {15u, 60u, 100u}) {
      std::vector<const LaserScan*> base;
      for (std::size_t j = i - back; j < i - back + 10; ++j) base.push_back(&scans[j]);
      SCOPED_TRACE("scan " + std::to_string(i) + ", chain from " + std::to_string(i - back));
      (CheckCase(matcher, bound, scans[i], base) < 0.8 ? below : above)++;
    }
  }
  EXPECT_GT(below, 0);
  EXPECT_GT(above, 0);
}

TEST(ResponseBound, AChainOutOfReachProvesRejection) {
  const LaserScan scan = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  // The same room seen from a pose 30 m away: no chain point lies in the grid.
  LaserScan far = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  far.SetSensorPose({35.0, 4.0, 0.3});
  ScanMatcher matcher(KartoSequential());
  ResponseBound bound(KartoSequential());
  const std::vector<const LaserScan*> base{&far};
  EXPECT_FALSE(bound.MayExceed(scan, base, 0.1));
  EXPECT_EQ(matcher.Match(scan, base, Penalize::kNo, Refine::kYes).response, 0.0);
  // Seen from its own pose, the chain matches perfectly and the bound cannot rule it out.
  const LaserScan same = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  const std::vector<const LaserScan*> near{&same};
  EXPECT_TRUE(bound.MayExceed(scan, near, 0.8 - 1e-6));
  EXPECT_GT(matcher.Match(scan, near, Penalize::kNo, Refine::kYes).response, 0.8);
}

// Karto's linear index wraps: a beam reading past the grid's right edge reads the next row's
// left border (§1.2, §4.5). A single 12.3 m beam along +x and a wall just inside the grid's
// left edge make the match score only through that wrap; the bound must count the beam.
TEST(ResponseBound, CountsBeamsWhoseReadsWrapOntoAnotherRow) {
  const auto laser = testing::CarmenLikeLaser();  // beam 90 points along the heading
  std::vector<double> ranges(180, std::nan(""));
  ranges[90] = 12.30;
  const LaserScan scan(laser, std::make_shared<const std::vector<double>>(ranges), {0.0, 0.0, 0.0}, 0.0);
  // A wall facing the scan at x = -12.14 (inside the ROI, which starts at -12.15 m), seen
  // from 1 m in front of it on the scan's side (the back-face filter keeps it).
  std::vector<double> wall(180, std::nan(""));
  for (int i = 60; i <= 120; ++i) wall[static_cast<std::size_t>(i)] = 1.0 / std::cos((i - 90) * kPi / 180.0);
  const LaserScan chain(laser, std::make_shared<const std::vector<double>>(wall), {-11.14, 0.0, kPi}, 0.0);
  const std::vector<const LaserScan*> base{&chain};
  ScanMatcher matcher(KartoSequential());
  ResponseBound bound(KartoSequential());
  const double response = matcher.Match(scan, base, Penalize::kNo, Refine::kYes).response;
  ASSERT_GT(response, 0.0) << "the wrapped read scored nothing; the test does not exercise the wrap";
  EXPECT_LE(response, BoundOf(bound, scan, base));
  EXPECT_TRUE(bound.MayExceed(scan, base, 0.5 * response));
}

TEST(ResponseBound, AHeadingRangeOfHalfATurnOrMoreIsNotBounded) {
  ScanMatcherOptions o = KartoSequential();
  o.coarse_angle_offset = 1.6;  // +-1.6 rad: the coarse mean heading is no longer confined
  ResponseBound bound(o);
  const LaserScan scan = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  LaserScan far = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  far.SetSensorPose({35.0, 4.0, 0.3});
  const std::vector<const LaserScan*> base{&far};
  EXPECT_TRUE(bound.MayExceed(scan, base, 0.5));
  EXPECT_EQ(bound.MaxSumBound(scan, base), 100 * static_cast<std::int64_t>(scan.ranges().size()));
}

TEST(ResponseBound, AThresholdOfOneOrMoreIsNeverReached) {
  const LaserScan scan = testing::AsymmetricRoomScan({5.0, 4.0, 0.3});
  const std::vector<const LaserScan*> base{&scan};
  ResponseBound bound(KartoSequential());
  EXPECT_TRUE(bound.MayExceed(scan, base, 0.99));
  EXPECT_FALSE(bound.MayExceed(scan, base, 1.0));  // responses are clipped to 1 (§4.5)
}

}  // namespace
}  // namespace slamtune::slam
