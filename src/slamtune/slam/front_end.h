// The small rules of Karto's front end (docs/engine.md §3.2, §3.3, §5.3 step 4): the initial
// guess from the odometry increment, the acceptance test HasMovedEnough, the running-buffer
// trim and the weighted mean of several matches. Free functions on values so that each rule
// has its own unit test; Mapper::Process strings them together in Karto's order (docs/engine.md §3.2).
#pragma once

#include <Eigen/Core>
#include <deque>
#include <functional>
#include <span>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam {

// §3.2 step 4: T(last.odometric -> last.corrected) applied to `odometric`: rotation by
// dtheta = corrected.theta - odometric.theta (not normalised, as Karto's Transform),
// translation corrected.xy - R(dtheta) last_odometric.xy, heading normalised.
Pose2 InitialGuess(const Pose2& last_odometric, const Pose2& last_corrected, const Pose2& odometric);

struct MovementOptions {
  double minimum_time_interval = 3600;    // s
  double minimum_travel_distance = 0.2;   // m
  double minimum_travel_heading = 0.174;  // rad
};

// Which test of HasMovedEnough accepted a scan, or kNotMoved.
enum class MoveDecision { kFirstScan, kTime, kHeading, kDistance, kNotMoved };
const char* MoveDecisionName(MoveDecision decision);

// §3.2 step 5, tests in Karto's order on the sensor poses of the *odometric* poses:
// first scan; dt >= minimum_time_interval; |normalize(dtheta)| >= minimum_travel_heading;
// d^2 >= minimum_travel_distance^2 - 1e-6. `last` is null for the first scan.
MoveDecision HasMovedEnough(const LaserScan& scan, const LaserScan* last, const MovementOptions& options);

// §3.3: after appending, drop the front while size > max_size or the squared distance between
// the sensor positions of front and back exceeds max_distance^2 - 1e-6. `sensor_pose(id)` gives
// the current (corrected) sensor pose of a buffered scan.
void TrimRunningBuffer(std::deque<int>& buffer, const std::function<Pose2(int)>& sensor_pose, int max_size,
                       double max_distance);

// §5.3 step 4: xy = sum_k (sum_j C_j^-1)^-1 C_k^-1 (x_k, y_k, theta_k), first two rows; heading =
// atan2(sum sin theta_k, sum cos theta_k). Inverses are Karto's cofactor inverses. Needs at least
// one mean.
Pose2 WeightedMean(std::span<const Pose2> means, std::span<const Eigen::Matrix3d> covariances);

}  // namespace slamtune::slam
