#include "slamtune/slam/node_scan_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace slamtune::slam {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

MapperParams Sync() { return MapperParams::Preset("slam_toolbox_sync"); }

// Verdicts on scans at `poses`, one every `period_ns`.
std::vector<NodeVerdict> Verdicts(const MapperParams& params, const std::vector<Pose2>& poses,
                                  std::int64_t period_ns = kSecond) {
  NodeScanFilter filter;
  std::vector<NodeVerdict> out;
  for (std::size_t k = 0; k < poses.size(); ++k) {
    out.push_back(filter.Offer(params, poses[k], static_cast<std::int64_t>(k) * period_ns));
  }
  return out;
}

using enum NodeVerdict;

TEST(NodeScanFilter, AsynchronousNodePassesEveryScan) {
  MapperParams p = MapperParams::Preset("slam_toolbox");
  p.throttle_scans = 3;  // not read by the asynchronous node
  const std::vector<Pose2> still(7);
  for (NodeVerdict v : Verdicts(p, still, 1)) EXPECT_EQ(v, kPass);
}

TEST(NodeScanFilter, SlamKartoKeepsEveryNthMessageCountingFromOne) {
  MapperParams p = MapperParams::Preset("slam_karto");
  p.throttle_scans = 3;
  EXPECT_EQ(Verdicts(p, std::vector<Pose2>(7)),
            (std::vector<NodeVerdict>{kThrottled, kThrottled, kPass, kThrottled, kThrottled, kPass, kThrottled}));
  p.throttle_scans = 1;
  for (NodeVerdict v : Verdicts(p, std::vector<Pose2>(4))) EXPECT_EQ(v, kPass);
}

TEST(NodeScanFilter, SynchronousNodeNeverMapsARotationInPlace) {
  std::vector<Pose2> turning;
  for (int k = 0; k < 40; ++k) turning.push_back({0.0, 0.0, 0.3 * k});
  const std::vector<NodeVerdict> v = Verdicts(Sync(), turning);
  EXPECT_EQ(v[0], kPass);
  for (std::size_t k = 1; k < v.size(); ++k) EXPECT_EQ(v[k], kNotMoved) << k;
}

TEST(NodeScanFilter, SynchronousNodeRefusesTheFirstCallsAfterTheFirstScan) {
  // Each scan 1 m further: moved and late enough, so only the counter refuses calls 2 to 4.
  std::vector<Pose2> driving;
  for (int k = 0; k < 7; ++k) driving.push_back({1.0 * k, 0.0, 0.0});
  EXPECT_EQ(Verdicts(Sync(), driving),
            (std::vector<NodeVerdict>{kPass, kWarmingUp, kWarmingUp, kWarmingUp, kPass, kPass, kPass}));
}

TEST(NodeScanFilter, SynchronousDistanceGateIsPointEightTimesTheSquaredTravel) {
  MapperParams p = Sync();  // minimum_travel_distance 0.5: the gate is 0.8 x 0.25 = 0.2 m^2
  const double gate = std::sqrt(0.8 * 0.25);
  // Five scans to pass the counter, then one just short of the gate and one on it.
  std::vector<Pose2> poses(5, Pose2{});
  poses.push_back({std::nextafter(gate, 0.0), 0.0, 0.0});
  poses.push_back({0.0, gate + 1e-12, 0.0});
  const std::vector<NodeVerdict> v = Verdicts(p, poses);
  EXPECT_EQ(v[4], kNotMoved);  // the counter allows it, the distance does not
  EXPECT_EQ(v[5], kNotMoved);
  EXPECT_EQ(v[6], kPass);
}

TEST(NodeScanFilter, SynchronousTimeGateCountsNanosecondsFromTheLastPassedScan) {
  MapperParams p = Sync();
  p.sync_minimum_time_interval = 0.5;
  NodeScanFilter filter;
  const std::int64_t half = kSecond / 2;
  EXPECT_EQ(filter.Offer(p, {0, 0, 0}, 0), kPass);
  for (int k = 1; k < 4; ++k) EXPECT_EQ(filter.Offer(p, {double(k), 0, 0}, k * kSecond), kWarmingUp);
  EXPECT_EQ(filter.Offer(p, {5, 0, 0}, 5 * kSecond), kPass);                // the fifth call
  EXPECT_EQ(filter.Offer(p, {6, 0, 0}, 5 * kSecond + half - 1), kTooSoon);  // 1 ns short
  EXPECT_EQ(filter.Offer(p, {7, 0, 0}, 5 * kSecond + half), kPass);         // exactly the interval
  // A refused scan does not move the reference: distance and time still count from the pass.
  EXPECT_EQ(filter.Offer(p, {7.1, 0, 0}, 6 * kSecond), kNotMoved);
  EXPECT_EQ(filter.Offer(p, {7.6, 0, 0}, 6 * kSecond + 1), kPass);
}

TEST(NodeScanFilter, SynchronousThrottleCountsEveryCallIncludingTheFirst) {
  MapperParams p = Sync();
  p.throttle_scans = 2;
  std::vector<Pose2> driving;
  for (int k = 0; k < 9; ++k) driving.push_back({1.0 * k, 0.0, 0.0});
  // Calls 1..9: the first passes; odd calls are throttled; even calls 2 and 4 warm up.
  EXPECT_EQ(Verdicts(p, driving), (std::vector<NodeVerdict>{kPass, kWarmingUp, kThrottled, kWarmingUp, kThrottled,
                                                            kPass, kThrottled, kPass, kThrottled}));
}

TEST(NodeScanFilter, OfflineModeIsTheSynchronousNode) {
  std::vector<Pose2> driving;
  for (int k = 0; k < 12; ++k) driving.push_back({0.2 * k, 0.0, 0.1 * k});
  EXPECT_EQ(Verdicts(Sync(), driving, kSecond / 10),
            Verdicts(MapperParams::Preset("slam_toolbox_offline"), driving, kSecond / 10));
}

TEST(NodeScanFilter, ACopyGoesOnAsTheOriginal) {
  std::vector<Pose2> driving;
  for (int k = 0; k < 20; ++k) driving.push_back({0.3 * k, 0.05 * k, 0.0});
  NodeScanFilter a;
  for (int k = 0; k < 8; ++k) a.Offer(Sync(), driving[k], k * kSecond / 3);
  NodeScanFilter b = a;
  for (int k = 8; k < 20; ++k) {
    EXPECT_EQ(a.Offer(Sync(), driving[k], k * kSecond / 3), b.Offer(Sync(), driving[k], k * kSecond / 3));
  }
}

TEST(NodeScanFilter, DurationTruncatesToNanoseconds) {
  EXPECT_EQ(DurationNs(0.5), 500'000'000);
  EXPECT_EQ(DurationNs(0.0), 0);
  EXPECT_EQ(DurationNs(1e-9 * 0.999), 0);
}

}  // namespace
}  // namespace slamtune::slam
