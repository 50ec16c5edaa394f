// What a ROS recording holds for 2D laser SLAM, decoded in one pass over its container
// (recording_container.h, ros_messages.h): every sensor_msgs/LaserScan on every topic, the
// transform tree of all tf2_msgs/TFMessage topics (/tf_static, and any topic whose name ends
// in "tf_static" or that is latched, as static transforms; the rest dynamic), and every
// nav_msgs/Odometry. Other message types are counted by topic, not decoded.
//
// Undecodable messages of these types are InputError "FILE: WHERE: TOPIC: what"; with
// --lenient they are skipped and counted (scans apart from the rest).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/ros/recording_container.h"
#include "slamtune/io/ros/ros_messages.h"
#include "slamtune/io/ros/tf_buffer.h"

namespace slamtune::io {

struct RecordedScan {
  LaserScanMessage message;
  std::int64_t log_time_ns = 0;
  std::string location;  // "FILE: byte N" for messages
};

struct OdometrySample {
  std::int64_t stamp_ns = 0;
  std::int64_t log_time_ns = 0;
  std::string frame_id, child_frame_id;
  RigidTransform3 pose;
  double linear_x = 0.0, angular_z = 0.0;  // twist (m/s, rad/s)
};

struct RecordingContents {
  std::string path;
  ContainerSummary container;
  std::map<std::string, std::vector<RecordedScan>> scans;          // LaserScan topic -> messages
  std::map<std::string, std::vector<OdometrySample>> odometry;     // Odometry topic -> messages
  std::map<std::string, std::vector<std::int64_t>> receive_times;  // every topic's log times
  TfBuffer tf;
  std::size_t tf_messages = 0;
  std::size_t static_tf_messages = 0;
  std::size_t scans_undecodable = 0;     // --lenient
  std::size_t messages_undecodable = 0;  // --lenient, tf / odometry
  std::vector<std::string> undecodable_examples;
};

// Reads `path` (a ROS recording, see DetectRecordingKind). `max_scan_messages` > 0 stops
// keeping LaserScans after that many on any one topic (for short slices; the rest is still
// read for tf).
RecordingContents ReadRecordingContents(const std::string& path, bool lenient, std::size_t max_scan_messages = 0);

}  // namespace slamtune::io
