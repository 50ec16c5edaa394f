// A laser scan as the Karto engine sees it (karto-algorithm.md §2): fixed beam geometry,
// recorded readings, an odometric and a corrected robot pose, and the point readout that is
// recomputed whenever the pose changes (unfiltered points, filtered points, barycentre,
// bounding box).
//
// Value type: copying a LaserScan copies its poses and point lists; the readings and the
// geometry are shared immutable data, so copies of engine state stay cheap and independent.
#pragma once

#include <Eigen/Core>

#include <memory>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::slam {

// Laser description (§2.1). Angles in the laser frame, radians; ranges in metres.
struct LaserGeometry {
  double min_angle = 0.0;
  double angular_resolution = 0.0;
  int num_readings = 0;           // N = Round((max - min)/res) + 1
  double min_range = 0.0;         // minRange
  double max_range = 80.0;        // maxRange: readings >= this are no-returns in the map (§8.1)
  double range_threshold = 12.0;  // rangeThreshold, already clipped into [min_range, max_range]
  Pose2 offset;                   // laser in the robot frame (zero for CARMEN laser poses, §1.4)

  double max_angle() const { return min_angle + (num_readings - 1) * angular_resolution; }
};

struct BoundingBox2 {
  Eigen::Vector2d min{0, 0};
  Eigen::Vector2d max{0, 0};
};

class LaserScan {
 public:
  LaserScan() = default;
  // `ranges` must hold geometry->num_readings values (checked). `time` in seconds.
  LaserScan(std::shared_ptr<const LaserGeometry> geometry, std::shared_ptr<const std::vector<double>> ranges,
            const Pose2& odometric_pose, double time);

  const LaserGeometry& geometry() const { return *geometry_; }
  const std::shared_ptr<const LaserGeometry>& geometry_ptr() const { return geometry_; }
  const std::vector<double>& ranges() const { return *ranges_; }
  const std::shared_ptr<const std::vector<double>>& ranges_ptr() const { return ranges_; }
  double time() const { return time_; }

  int state_id = -1;   // index among processed scans (set by the mapper)
  int log_index = -1;  // index of the scan in the log (for reports)

  const Pose2& odometric_pose() const { return odometric_pose_; }
  const Pose2& corrected_pose() const { return corrected_pose_; }
  // Sets the corrected robot pose and recomputes the point readout (§2.2).
  void SetCorrectedPose(const Pose2& pose);
  // Sensor pose = corrected (+) offset; setting it sets corrected = inverse (§1.4).
  Pose2 SensorPose() const;
  void SetSensorPose(const Pose2& sensor_pose);
  // Sensor pose computed from the odometric pose (used by HasMovedEnough, §3.2 step 5).
  Pose2 OdometricSensorPose() const;

  // One world point per beam, whatever the reading (NaN/inf propagate). Index = beam.
  const std::vector<Eigen::Vector2d>& unfiltered_points() const { return unfiltered_; }
  // World points of beams with min_range <= r <= range_threshold.
  const std::vector<Eigen::Vector2d>& filtered_points() const { return filtered_; }
  // Mean of the filtered points with heading 0; the sensor pose if there are none.
  const Pose2& barycenter() const { return barycenter_; }
  // Box of the sensor position and all filtered points.
  const BoundingBox2& bounding_box() const { return bounding_box_; }
  // Reference pose for distance tests: barycentre or sensor pose (§2.2).
  Pose2 ReferencePose(bool use_barycenter) const { return use_barycenter ? barycenter_ : SensorPose(); }

 private:
  void UpdatePoints();

  std::shared_ptr<const LaserGeometry> geometry_;
  std::shared_ptr<const std::vector<double>> ranges_;
  double time_ = 0.0;
  Pose2 odometric_pose_;
  Pose2 corrected_pose_;
  std::vector<Eigen::Vector2d> unfiltered_;
  std::vector<Eigen::Vector2d> filtered_;
  Pose2 barycenter_;
  BoundingBox2 bounding_box_;
};

// Robot pose from a sensor pose and the mounting offset (Karto's inverse, §1.4).
Pose2 RobotPoseFromSensor(const Pose2& sensor_pose, const Pose2& offset);

}  // namespace slamtune::slam
