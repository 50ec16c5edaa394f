// A laser scan as the Karto engine sees it (docs/engine.md §2): fixed beam geometry,
// recorded readings, an odometric and a corrected robot pose, and the point readout of that
// pose (unfiltered points, filtered points, barycentre, bounding box).
//
// The readout is computed on first use after a pose change, not at the change: a pose is often
// replaced before its points are read (the odometric pose at construction, every node after a
// solve whose barycentres are known), and the readout's sin/cos per beam is most of the time of
// a run whose matches come from the MatchCache. The computation is the same whenever it runs,
// so results are bit-identical. Lazy means a const accessor may write the readout: a scan read
// by several threads at once must have EnsureReadout() called first (the matchers do so on the
// calling thread before they spread work over threads).
//
// Value type: copying a LaserScan copies its poses and point lists; the readings and the
// geometry are shared immutable data, so copies of engine state stay cheap and independent.
#pragma once

#include <Eigen/Core>
#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
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
  int laser = 0;       // which of the mapper's lasers took it (§3.5; 0 with one laser)

  const Pose2& odometric_pose() const { return odometric_pose_; }
  const Pose2& corrected_pose() const { return corrected_pose_; }
  // Sets the corrected robot pose; the point readout (§2.2) follows on first use.
  void SetCorrectedPose(const Pose2& pose);
  // SetSensorPose with the barycentre of that pose already known (bit for bit what the readout
  // would compute, e.g. stored when another run made the same solve); the points follow on use.
  void SetSensorPoseWithBarycenter(const Pose2& sensor_pose, const Pose2& barycenter);
  // The same for a corrected (robot) pose, as a robot-pose graph writes its values back.
  void SetCorrectedPoseWithBarycenter(const Pose2& corrected_pose, const Pose2& barycenter);
  // Gives the barycentre of the current pose, known bit for bit (e.g. from a BarycenterCache);
  // checked against the readout's own when that is computed. The points follow on use.
  void SetBarycenter(const Pose2& barycenter) {
    barycenter_ = barycenter;
    barycenter_valid_ = true;
  }
  // Whether the barycentre of the current pose is known without computing the readout.
  bool barycenter_known() const { return barycenter_valid_; }
  // Computes the readout now if the pose changed since it was last computed.
  void EnsureReadout() const {
    if (!readout_valid_) UpdatePoints();
  }
  // Sensor pose = corrected (+) offset; setting it sets corrected = inverse (§1.4).
  Pose2 SensorPose() const;
  void SetSensorPose(const Pose2& sensor_pose);
  // Sensor pose computed from the odometric pose (used by HasMovedEnough, §3.2 step 5).
  Pose2 OdometricSensorPose() const;

  // One world point per beam, whatever the reading (NaN/inf propagate). Index = beam.
  const std::vector<Eigen::Vector2d>& unfiltered_points() const {
    EnsureReadout();
    return unfiltered_;
  }
  // World points of beams with min_range <= r <= range_threshold.
  const std::vector<Eigen::Vector2d>& filtered_points() const {
    EnsureReadout();
    return filtered_;
  }
  // Mean of the filtered points with heading 0; the sensor pose if there are none.
  const Pose2& barycenter() const {
    if (!barycenter_valid_) EnsureReadout();
    return barycenter_;
  }
  // Box of the sensor position and all filtered points.
  const BoundingBox2& bounding_box() const {
    EnsureReadout();
    return bounding_box_;
  }
  // Reference pose for distance tests: barycentre or sensor pose (§2.2).
  Pose2 ReferencePose(bool use_barycenter) const { return use_barycenter ? barycenter() : SensorPose(); }

  // A hint for MatchCache (sharing/match_cache.h): the id under which the cache last interned this
  // scan's (log index, readings, corrected pose). The cache checks the id against the interned
  // contents before using it, so any value, stale or copied, is safe; it only saves a hash
  // lookup. Relaxed atomic access, so scans shared by threads stay race-free.
  static constexpr std::uint32_t kNoMatchKeyHint = 0xffffffffu;
  std::uint32_t match_key_hint() const {
    return std::atomic_ref<std::uint32_t>(match_key_hint_).load(std::memory_order_relaxed);
  }
  void set_match_key_hint(std::uint32_t id) const {
    std::atomic_ref<std::uint32_t>(match_key_hint_).store(id, std::memory_order_relaxed);
  }

 private:
  void UpdatePoints() const;

  std::shared_ptr<const LaserGeometry> geometry_;
  std::shared_ptr<const std::vector<double>> ranges_;
  double time_ = 0.0;
  Pose2 odometric_pose_;
  Pose2 corrected_pose_;
  // The readout of corrected_pose_, valid when readout_valid_; the barycentre alone may be
  // valid before the rest (SetSensorPoseWithBarycenter).
  mutable bool readout_valid_ = false;
  mutable bool barycenter_valid_ = false;
  mutable std::vector<Eigen::Vector2d> unfiltered_;
  mutable std::vector<Eigen::Vector2d> filtered_;
  mutable Pose2 barycenter_;
  mutable BoundingBox2 bounding_box_;
  alignas(std::atomic_ref<std::uint32_t>::required_alignment) mutable std::uint32_t match_key_hint_ = kNoMatchKeyHint;
};

// The bits of every field of `g`, for exact cache keys (common/key_words.h); AppendGeometryKey
// appends them to a key.
inline constexpr std::size_t kGeometryKeyWords = 9;
std::array<std::uint64_t, kGeometryKeyWords> GeometryKeyWords(const LaserGeometry& g);
void AppendGeometryKey(const LaserGeometry& g, std::vector<std::uint64_t>* key);

// Robot pose from a sensor pose and the mounting offset (Karto's inverse, §1.4).
Pose2 RobotPoseFromSensor(const Pose2& sensor_pose, const Pose2& offset);

}  // namespace slamtune::slam
