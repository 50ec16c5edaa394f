// A ROS recording turned into the laser log the engine consumes, as slam_toolbox and slam_karto
// feed Karto (docs/recordings.md §1.5):
//
//   * scans: the sensor_msgs/LaserScan topic (--scan-topic, or the only one; several without a
//     choice is an error listing them), in message order, each at its header stamp (not the
//     receive time); beams from the message (angle_min, angle_increment, one per range),
//     max_range = range_max, readings as recorded (+inf, NaN and readings >= range_max are
//     no-returns, REP 117). A scan whose range count disagrees with its angles
//     (Round((angle_max - angle_min) / angle_increment) + 1, or one less for a 360 deg laser
//     whose angle_max closes the circle) is an error (--lenient: skipped, counted).
//   * odometry: the pose of the base frame in the odometry frame at each scan stamp, from the
//     tf tree (tf_buffer.h: interpolated, never extrapolated, not across gaps longer than
//     --max-odom-gap), or from a nav_msgs/Odometry topic (--odom-topic) interpolated the same
//     way. Frames: --odom-frame (default odom) and --base-frame (default base_footprint, as
//     slam_toolbox, else base_link, as slam_karto, whichever the tree has). Without tf
//     odometry, the only Odometry topic is used, and said so. A scan that cannot be placed is
//     not used and is counted, with the reason of the first few.
//   * laser mounting offset: base -> laser frame (the scans' frame_id) composed over the tf
//     tree at the first scan (/tf_static, usually a chain such as base_footprint -> base_link
//     -> laser), projected to x, y, yaw; --laser-offset states it instead. A laser whose z axis
//     points down (upside down) has its readings reversed, as slam_karto and slam_toolbox do,
//     and its beams described exactly: first beam at -angle_max.
//   * each scan keeps its robot pose and the offset, and laser pose = robot pose (+) offset, the
//     sensor pose Karto computes from the odometric pose and the range finder's offset pose
//     (docs/engine.md §1.4); the engine is given the robot poses and the offset
//     (slam/log_runner.h OdometryFrameOf).
//
//   * a loop in the tf tree on the frames the odometry or the laser offset is composed over is an
//     error naming the loop (tf2 refuses every lookup through it): TfLoopError.
//
// Every choice is recorded in LaserLog::recording with the rule that made it.
#pragma once

#include <string>

#include "slamtune/common/error.h"
#include "slamtune/io/laser_log.h"
#include "slamtune/io/ros/recording_contents.h"

namespace slamtune::io {

// The tf tree has a loop where the odometry or the laser offset would be looked up.
class TfLoopError : public InputError {
 public:
  using InputError::InputError;
};

// Throws InputError for a choice that cannot be made (named topic missing, several scan topics,
// no odometry, no laser offset) and for malformed scans unless options.lenient.
LaserLog RecordingToLog(const RecordingContents& contents, const LogReadOptions& options);

// ReadRecordingContents + RecordingToLog.
LaserLog ReadRecordingLog(const std::string& path, const LogReadOptions& options);

}  // namespace slamtune::io
