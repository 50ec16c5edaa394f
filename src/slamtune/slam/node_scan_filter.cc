#include "slamtune/slam/node_scan_filter.h"

#include "slamtune/common/error.h"

namespace slamtune::slam {

const char* NameOf(NodeVerdict verdict) {
  switch (verdict) {
    case NodeVerdict::kPass: return "passed";
    case NodeVerdict::kThrottled: return "throttled";
    case NodeVerdict::kTooSoon: return "too_soon";
    case NodeVerdict::kNotMoved: return "not_moved";
    case NodeVerdict::kWarmingUp: return "warming_up";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

std::int64_t DurationNs(double seconds) { return static_cast<std::int64_t>(seconds * 1e9); }

NodeVerdict NodeScanFilter::Offer(const MapperParams& params, const Pose2& base_odometry, std::int64_t stamp_ns) {
  switch (params.node_mode) {
    case NodeMode::kSlamKarto:
      ++calls_;
      return calls_ % params.throttle_scans == 0 ? NodeVerdict::kPass : NodeVerdict::kThrottled;
    case NodeMode::kSlamToolboxAsync: return NodeVerdict::kPass;
    case NodeMode::kSlamToolboxSync:
    case NodeMode::kSlamToolboxOffline: return OfferSynchronous(params, base_odometry, stamp_ns);
  }
  SLAMTUNE_CHECK(false);
  return NodeVerdict::kPass;
}

NodeVerdict NodeScanFilter::OfferSynchronous(const MapperParams& params, const Pose2& base_odometry,
                                             std::int64_t stamp_ns) {
  ++calls_;
  if (first_) {
    first_ = false;
    last_pose_ = base_odometry;
    last_stamp_ns_ = stamp_ns;
    return NodeVerdict::kPass;
  }
  if (calls_ % params.throttle_scans != 0) return NodeVerdict::kThrottled;
  if (stamp_ns - last_stamp_ns_ < DurationNs(params.sync_minimum_time_interval)) return NodeVerdict::kTooSoon;
  const double dx = base_odometry.x - last_pose_.x;
  const double dy = base_odometry.y - last_pose_.y;
  const double min_dist2 = params.minimum_travel_distance * params.minimum_travel_distance;
  if (dx * dx + dy * dy < 0.8 * min_dist2) return NodeVerdict::kNotMoved;
  if (calls_ < 5) return NodeVerdict::kWarmingUp;
  last_pose_ = base_odometry;
  last_stamp_ns_ = stamp_ns;
  return NodeVerdict::kPass;
}

}  // namespace slamtune::slam
