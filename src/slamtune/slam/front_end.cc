#include "slamtune/slam/front_end.h"

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam {

Pose2 InitialGuess(const Pose2& last_odometric, const Pose2& last_corrected, const Pose2& odometric) {
  const double dtheta = last_corrected.theta - last_odometric.theta;
  const double c = std::cos(dtheta), s = std::sin(dtheta);
  const double tx = last_corrected.x - (c * last_odometric.x - s * last_odometric.y);
  const double ty = last_corrected.y - (s * last_odometric.x + c * last_odometric.y);
  return {tx + (c * odometric.x - s * odometric.y), ty + (s * odometric.x + c * odometric.y),
          NormalizeAngle(dtheta + odometric.theta)};
}

const char* MoveDecisionName(MoveDecision decision) {
  switch (decision) {
    case MoveDecision::kFirstScan: return "first_scan";
    case MoveDecision::kTime: return "time";
    case MoveDecision::kHeading: return "heading";
    case MoveDecision::kDistance: return "distance";
    case MoveDecision::kNotMoved: return "not_moved";
  }
  return "?";
}

MoveDecision HasMovedEnough(const LaserScan& scan, const LaserScan* last, const MovementOptions& options) {
  if (last == nullptr) return MoveDecision::kFirstScan;
  if (scan.time() - last->time() >= options.minimum_time_interval) return MoveDecision::kTime;
  const Pose2 last_pose = last->OdometricSensorPose();
  const Pose2 pose = scan.OdometricSensorPose();
  if (std::fabs(NormalizeAngle(pose.theta - last_pose.theta)) >= options.minimum_travel_heading) {
    return MoveDecision::kHeading;
  }
  const double limit = options.minimum_travel_distance * options.minimum_travel_distance - kKartoTolerance;
  if (SquaredDistance(last_pose, pose) >= limit) return MoveDecision::kDistance;
  return MoveDecision::kNotMoved;
}

void TrimRunningBuffer(std::deque<int>& buffer, const std::function<Pose2(int)>& sensor_pose, int max_size,
                       double max_distance) {
  const double limit = max_distance * max_distance - kKartoTolerance;
  while (!buffer.empty()) {
    const bool too_many = static_cast<int>(buffer.size()) > max_size;
    if (!too_many && SquaredDistance(sensor_pose(buffer.front()), sensor_pose(buffer.back())) <= limit) break;
    buffer.pop_front();
  }
}

Pose2 WeightedMean(std::span<const Pose2> means, std::span<const Eigen::Matrix3d> covariances) {
  SLAMTUNE_CHECK(!means.empty() && means.size() == covariances.size());
  Eigen::Matrix3d sum_of_inverses = Eigen::Matrix3d::Zero();
  for (const Eigen::Matrix3d& c : covariances) sum_of_inverses += KartoInverse(c);
  const Eigen::Matrix3d inverse_of_sum = KartoInverse(sum_of_inverses);
  double x = 0.0, y = 0.0, sum_cos = 0.0, sum_sin = 0.0;
  for (std::size_t k = 0; k < means.size(); ++k) {
    const Pose2& p = means[k];
    sum_cos += std::cos(p.theta);
    sum_sin += std::sin(p.theta);
    const Eigen::Matrix3d w = inverse_of_sum * KartoInverse(covariances[k]);
    x += w(0, 0) * p.x + w(0, 1) * p.y + w(0, 2) * p.theta;
    y += w(1, 0) * p.x + w(1, 1) * p.y + w(1, 2) * p.theta;
  }
  // Karto divides both sums by the number of means before atan2; atan2 of the undivided sums
  // can differ in the last bit.
  const double n = static_cast<double>(means.size());
  return {x, y, std::atan2(sum_sin / n, sum_cos / n)};
}

}  // namespace slamtune::slam
