#include "slamtune/slam/laser_scan.h"

#include <bit>
#include <cmath>
#include <cstdint>

#include "slamtune/common/error.h"
#include "slamtune/common/key_words.h"

namespace slamtune::slam {

LaserScan::LaserScan(std::shared_ptr<const LaserGeometry> geometry, std::shared_ptr<const std::vector<double>> ranges,
                     const Pose2& odometric_pose, double time)
    : geometry_(std::move(geometry)), ranges_(std::move(ranges)), time_(time), odometric_pose_(odometric_pose) {
  SLAMTUNE_CHECK(geometry_ != nullptr && ranges_ != nullptr);
  SLAMTUNE_CHECK(static_cast<int>(ranges_->size()) == geometry_->num_readings);
  SetCorrectedPose(odometric_pose);
}

void LaserScan::SetCorrectedPose(const Pose2& pose) {
  corrected_pose_ = pose;
  readout_valid_ = false;
  barycenter_valid_ = false;
}

void LaserScan::SetCorrectedPoseWithBarycenter(const Pose2& corrected_pose, const Pose2& barycenter) {
  SetCorrectedPose(corrected_pose);
  SetBarycenter(barycenter);
}

void LaserScan::SetSensorPoseWithBarycenter(const Pose2& sensor_pose, const Pose2& barycenter) {
  SetSensorPose(sensor_pose);
  SetBarycenter(barycenter);
}

Pose2 LaserScan::SensorPose() const { return Compose(corrected_pose_, geometry_->offset); }

void LaserScan::SetSensorPose(const Pose2& sensor_pose) {
  SetCorrectedPose(RobotPoseFromSensor(sensor_pose, geometry_->offset));
}

Pose2 LaserScan::OdometricSensorPose() const { return Compose(odometric_pose_, geometry_->offset); }

std::array<std::uint64_t, kGeometryKeyWords> GeometryKeyWords(const LaserGeometry& g) {
  return {KeyBits(g.min_angle), KeyBits(g.angular_resolution), KeyInt(g.num_readings),
          KeyBits(g.min_range), KeyBits(g.max_range),          KeyBits(g.range_threshold),
          KeyBits(g.offset.x),  KeyBits(g.offset.y),           KeyBits(g.offset.theta)};
}

void AppendGeometryKey(const LaserGeometry& g, std::vector<std::uint64_t>* key) {
  const auto words = GeometryKeyWords(g);
  key->insert(key->end(), words.begin(), words.end());
}

Pose2 RobotPoseFromSensor(const Pose2& sensor_pose, const Pose2& offset) {
  const double theta = NormalizeAngle(sensor_pose.theta - offset.theta);
  const double c = std::cos(theta), s = std::sin(theta);
  return {sensor_pose.x - (c * offset.x - s * offset.y), sensor_pose.y - (s * offset.x + c * offset.y), theta};
}

// §2.2: beam i at world angle (theta_s + minAngle) + i * res; the filtered list keeps
// min_range <= r <= range_threshold (NaN fails both comparisons).
void LaserScan::UpdatePoints() const {
  // A barycentre given with the pose must be the one computed here, bit for bit.
  const bool given = barycenter_valid_;
  const Pose2 given_barycenter = barycenter_;
  const LaserGeometry& g = *geometry_;
  const std::vector<double>& r = *ranges_;
  const Pose2 sensor = SensorPose();
  const double start = sensor.theta + g.min_angle;
  unfiltered_.resize(r.size());
  filtered_.clear();
  filtered_.reserve(r.size());
  double sum_x = 0.0, sum_y = 0.0;
  BoundingBox2 box{{sensor.x, sensor.y}, {sensor.x, sensor.y}};
  for (std::size_t i = 0; i < r.size(); ++i) {
    const double angle = start + static_cast<double>(i) * g.angular_resolution;
    const Eigen::Vector2d p(sensor.x + r[i] * std::cos(angle), sensor.y + r[i] * std::sin(angle));
    unfiltered_[i] = p;
    if (g.min_range <= r[i] && r[i] <= g.range_threshold) {
      filtered_.push_back(p);
      sum_x += p.x();
      sum_y += p.y();
      box.min = box.min.cwiseMin(p);
      box.max = box.max.cwiseMax(p);
    }
  }
  if (filtered_.empty()) {
    barycenter_ = sensor;
  } else {
    const double n = static_cast<double>(filtered_.size());
    barycenter_ = {sum_x / n, sum_y / n, 0.0};
  }
  bounding_box_ = box;
  SLAMTUNE_CHECK(!given || (KeyBits(given_barycenter.x) == KeyBits(barycenter_.x) &&
                            KeyBits(given_barycenter.y) == KeyBits(barycenter_.y)));
  readout_valid_ = true;
  barycenter_valid_ = true;
}

}  // namespace slamtune::slam
