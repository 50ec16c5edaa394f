#include "slamtune/io/beam_geometry.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

constexpr double kDeg = 3.14159265358979323846 / 180.0;

// A scan whose reading i is 1000 * beam angle in degrees + 100 (so each reading names its
// angle), max range 80.
LaserScanRecord ScanRecord(std::size_t n, double first_deg, double step_deg) {
  LaserScanRecord s;
  s.angle_min = first_deg * kDeg;
  s.angle_increment = step_deg * kDeg;
  s.max_range = 80.0;
  for (std::size_t i = 0; i < n; ++i) s.ranges.push_back(0.001 * (first_deg + i * step_deg) + 0.1);
  return s;
}

LaserLog LogOf(std::vector<LaserScanRecord> scans) {
  LaserLog log;
  log.scans = std::move(scans);
  for (const auto& s : log.scans) log.total_readings += s.ranges.size();
  return log;
}

TEST(BeamGeometry, OneGeometryLeavesTheLogUntouched) {
  LaserLog log = LogOf({ScanRecord(181, -90, 1), ScanRecord(181, -90, 1)});
  const LaserLog before = log;
  HarmonizeBeams(BeamPolicy::kNearestBeam, &log);
  EXPECT_EQ(log.scans[1].ranges, before.scans[1].ranges);
  EXPECT_EQ(log.scans[1].angle_min, before.scans[1].angle_min);
  EXPECT_EQ(log.beams.policy, "nearest-beam");
  ASSERT_EQ(log.beams.geometries.size(), 1u);
  EXPECT_FALSE(log.beams.varies());
  EXPECT_EQ(log.beams.scans_resampled, 0u);
}

// The real case: scans alternating between 180 and 181 readings with several start angles.
TEST(BeamGeometry, AlternatingCountsAndStartAnglesAreResampledOntoTheMostCommon) {
  std::vector<LaserScanRecord> scans;
  for (int k = 0; k < 12; ++k) {
    if (k % 2 == 0) {
      scans.push_back(ScanRecord(181, -90, 1));
    } else {
      scans.push_back(ScanRecord(180, k % 4 == 1 ? -90 : -89.5, 1));
    }
  }
  scans.push_back(ScanRecord(181, -90, 1));  // 7 of 13 are the reference geometry
  LaserLog log = LogOf(scans);
  HarmonizeBeams(BeamPolicy::kNearestBeam, &log);
  ASSERT_EQ(log.beams.geometries.size(), 3u);
  EXPECT_EQ(log.beams.geometries[0].geometry.readings, 181u);
  EXPECT_EQ(log.beams.geometries[0].scans, 7u);
  EXPECT_EQ(log.beams.scans_resampled, 6u);
  for (const LaserScanRecord& s : log.scans) {
    ASSERT_EQ(s.ranges.size(), 181u);
    EXPECT_EQ(s.angle_min, -90 * kDeg);
    EXPECT_EQ(s.angle_increment, 1 * kDeg);
  }
  // -90..89 onto -90..90: same readings, the +90 beam has no source.
  const LaserScanRecord& a = log.scans[1];
  EXPECT_DOUBLE_EQ(a.ranges[0], 0.001 * -90 + 0.1);
  EXPECT_DOUBLE_EQ(a.ranges[179], 0.001 * 89 + 0.1);
  EXPECT_TRUE(std::isinf(a.ranges[180]));
  EXPECT_EQ(a.no_returns, 1u);
  // -89.5..89.5: each beam is half a step from two beams and takes the later one; -90 is half
  // a step from -89.5, so it is still covered, +90 is not.
  const LaserScanRecord& b = log.scans[3];
  EXPECT_DOUBLE_EQ(b.ranges[0], 0.001 * -89.5 + 0.1);
  EXPECT_DOUBLE_EQ(b.ranges[1], 0.001 * -88.5 + 0.1);
  EXPECT_TRUE(std::isinf(b.ranges[180]));
  EXPECT_EQ(log.beams.readings_outside, 6u);  // the +90 beam of each of the six 180-beam scans
  EXPECT_EQ(log.total_readings, 13u * 181u);
}

TEST(BeamGeometry, NodeKeepsEveryScanAsRecordedAndCountsWhatTheNodeDrops) {
  LaserLog log =
      LogOf({ScanRecord(181, -90, 1), ScanRecord(180, -90, 1), ScanRecord(181, -90, 1), ScanRecord(182, -90, 1)});
  HarmonizeBeams(BeamPolicy::kNode, &log);
  EXPECT_EQ(log.scans[1].ranges.size(), 180u);
  EXPECT_EQ(log.beams.policy, "node");
  EXPECT_TRUE(log.beams.varies());
  EXPECT_EQ(log.beams.scans_resampled, 0u);
  // CARMEN-like records carry no angle_max: the laser expects the first scan's count.
  EXPECT_EQ(log.beams.slam_karto.expected, 181u);
  EXPECT_EQ(log.beams.slam_karto.dropped, 2u);
  EXPECT_EQ(log.beams.slam_toolbox.dropped, 2u);
  HarmonizeBeams(BeamPolicy::kPerGeometry, &log);
  EXPECT_EQ(log.beams.policy, "per-geometry");
  EXPECT_EQ(log.scans[3].ranges.size(), 182u);
}

// A ROS scan's angles decide the count the node's laser expects (Karto's LaserRangeFinder::Update).
TEST(BeamGeometry, ExpectedReadingsFollowEachNodesRule) {
  LaserScanRecord scan;
  // 360 readings over a closed circle, -pi .. pi step 2pi/360, as many 360-degree drivers publish.
  const float inc = static_cast<float>(2.0 * kPi / 360.0);
  scan.angle_min = static_cast<float>(-kPi);
  scan.angle_max = static_cast<double>(static_cast<float>(kPi));
  scan.angle_increment = inc;
  scan.ranges.assign(360, 1.0);
  EXPECT_EQ(ExpectedReadings(KartoLaserRule::kSlamKarto, scan), 361u);    // open_karto: + 1 always
  EXPECT_EQ(ExpectedReadings(KartoLaserRule::kSlamToolbox, scan), 360u);  // laser_utils.cpp: a 360 laser
  // The same angles with 361 readings (a last beam repeating the first): not a 360 laser to slam_toolbox.
  scan.ranges.assign(361, 1.0);
  EXPECT_EQ(ExpectedReadings(KartoLaserRule::kSlamToolbox, scan), 361u);
  // 180 degrees in 181 readings: both count 181.
  LaserScanRecord half;
  half.angle_min = static_cast<float>(-kPi / 2);
  half.angle_max = static_cast<double>(static_cast<float>(kPi / 2));
  half.angle_increment = static_cast<float>(kPi / 180);
  half.ranges.assign(181, 1.0);
  EXPECT_EQ(ExpectedReadings(KartoLaserRule::kSlamKarto, half), 181u);
  EXPECT_EQ(ExpectedReadings(KartoLaserRule::kSlamToolbox, half), 181u);
  // Whole logs: slam_karto drops every scan of the 360 laser, slam_toolbox none.
  LaserLog log = LogOf({ScanRecord(181, -90, 1)});
  scan.ranges.assign(360, 1.0);
  log.scans = {scan, scan, scan};
  HarmonizeBeams(BeamPolicy::kNode, &log);
  EXPECT_EQ(log.beams.slam_karto.expected, 361u);
  EXPECT_EQ(log.beams.slam_karto.dropped, 3u);
  EXPECT_EQ(log.beams.slam_toolbox.dropped, 0u);
}

TEST(BeamGeometry, SameCountOtherAnglesAreResampledFloatNoiseIsNot) {
  LaserScanRecord noisy = ScanRecord(181, -90, 1);
  noisy.angle_min = static_cast<double>(static_cast<float>(noisy.angle_min));  // float32 rounding
  LaserLog log = LogOf({ScanRecord(181, -90, 1), ScanRecord(181, -90, 1), noisy, ScanRecord(181, -80, 1)});
  HarmonizeBeams(BeamPolicy::kNearestBeam, &log);
  EXPECT_EQ(log.beams.geometries.size(), 2u);
  EXPECT_EQ(log.beams.scans_resampled, 1u);
  EXPECT_EQ(log.scans[2].angle_min, noisy.angle_min);  // untouched
  EXPECT_EQ(log.scans[3].angle_min, -90 * kDeg);
  EXPECT_TRUE(std::isinf(log.scans[3].ranges[0]));  // -90 .. -81 are outside -80..100
  EXPECT_DOUBLE_EQ(log.scans[3].ranges[10], 0.001 * -80 + 0.1);
  EXPECT_EQ(log.beams.readings_outside, 10u);
}

TEST(BeamGeometry, HarmonizeIsIdempotent) {
  LaserLog log = LogOf({ScanRecord(181, -90, 1), ScanRecord(180, -90, 1), ScanRecord(181, -90, 1)});
  HarmonizeBeams(BeamPolicy::kNearestBeam, &log);
  const LaserLog once = log;
  HarmonizeBeams(BeamPolicy::kNearestBeam, &log);
  EXPECT_EQ(log.scans[1].ranges.size(), once.scans[1].ranges.size());
  EXPECT_EQ(log.beams.scans_resampled, 0u);
}

TEST(BeamGeometry, PolicyNamesParseAndUnknownIsAnInputError) {
  EXPECT_EQ(ParseBeamPolicy("node"), BeamPolicy::kNode);
  EXPECT_EQ(ParseBeamPolicy("per-geometry"), BeamPolicy::kPerGeometry);
  EXPECT_EQ(ParseBeamPolicy("nearest-beam"), BeamPolicy::kNearestBeam);
  // Older run folders' names.
  EXPECT_EQ(ParseBeamPolicy("resample"), BeamPolicy::kNearestBeam);
  EXPECT_EQ(ParseBeamPolicy("strict"), BeamPolicy::kNode);
  try {
    ParseBeamPolicy("nearest");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("--beams 'nearest'"));
  }
}

}  // namespace
}  // namespace slamtune::io
