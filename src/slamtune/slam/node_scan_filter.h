// Which scans a ROS node hands to its Karto (docs/engine.md §3.4, docs/ros-nodes.md "Node
// modes"), before Karto's own gate (HasMovedEnough, §3.2 step 5) sees them. One rule per
// MapperParams::node_mode:
//
//   slam_karto (SlamKarto::laserCallback): counts every message and keeps those whose 1-based
//     count is a multiple of throttle_scans (the n-th, 2n-th, ...).
//   slam_toolbox asynchronous node (AsynchronousSlamToolbox::laserCallback): every scan;
//     throttle_scans and minimum_time_interval are not read on that path.
//   slam_toolbox synchronous node, online sync and offline launch (SlamToolbox::shouldProcessScan
//     in slam_toolbox_common.cpp), in its order: a counter of calls is incremented; the first
//     scan passes and is remembered; a scan whose count is not a multiple of throttle_scans is
//     refused; so is one whose header stamp is less than minimum_time_interval after the last
//     passed scan's (integer nanoseconds, the interval truncated to them as
//     rclcpp::Duration::from_seconds does); and one whose base moved (odometry, x and y only)
//     less than sqrt(0.8) x minimum_travel_distance from the last passed scan's pose
//     (dx^2 + dy^2 < 0.8 d^2), or that comes before the fifth call. There is no heading test, so
//     a pure rotation is never mapped. A passed scan becomes the last one.
//
// The filter is a value (copied with the LogRunner) and reads the parameters at each call, so a
// fork with other parameters goes on from the same state.
#pragma once

#include <cstdint>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {

// What the node did with a scan, in the order its tests run.
enum class NodeVerdict {
  kPass,       // handed to Karto
  kThrottled,  // throttle_scans
  kTooSoon,    // synchronous node: minimum_time_interval
  kNotMoved,   // synchronous node: less than sqrt(0.8) x minimum_travel_distance of travel
  kWarmingUp,  // synchronous node: one of the first four calls after the first scan
};
inline constexpr int kNumNodeVerdicts = 5;
// "passed", "throttled", "too_soon", "not_moved", "warming_up" (run.json's names).
const char* NameOf(NodeVerdict verdict);

class NodeScanFilter {
 public:
  // The node's verdict on the next scan, whose base sits at `base_odometry` (odometry frame) with
  // header stamp `stamp_ns`.
  NodeVerdict Offer(const MapperParams& params, const Pose2& base_odometry, std::int64_t stamp_ns);

 private:
  NodeVerdict OfferSynchronous(const MapperParams& params, const Pose2& base_odometry, std::int64_t stamp_ns);

  std::int64_t calls_ = 0;  // messages seen (slam_karto's laser_count_, the toolbox's scan_ctr)
  bool first_ = true;
  Pose2 last_pose_;
  std::int64_t last_stamp_ns_ = 0;
};

// rclcpp::Duration::from_seconds: the nanoseconds of `seconds`, truncated.
std::int64_t DurationNs(double seconds);

}  // namespace slamtune::slam
