// Decoders of the three ROS message types a 2D laser SLAM run needs, in both serializations a
// recording may hold (recording_container.h):
//   * ROS 2 CDR (XCDR1 / "plain CDR" as rmw writes it): a 4-byte encapsulation header (00 01 =
//     little-endian, 00 00 = big-endian; XCDR2 kinds are refused), then every primitive of size
//     n in {2, 4, 8} aligned to n relative to the end of that header; strings are u32 length
//     *including* the NUL, then the bytes and the NUL; sequences are a u32 count then the
//     elements (no alignment when the count is 0); fixed arrays have no count. std_msgs/Header
//     is {stamp, frame_id} (no seq). Bytes after the last field (padding) are ignored.
//   * ROS 1 serialization: little-endian, no alignment or padding; strings u32 length then the
//     bytes (no NUL); std_msgs/Header is {uint32 seq, time stamp, string frame_id}.
// Layouts (common_interfaces):
//   sensor_msgs/LaserScan : Header, float32 angle_min angle_max angle_increment time_increment
//                           scan_time range_min range_max, float32[] ranges, float32[] intensities
//   nav_msgs/Odometry     : Header, string child_frame_id, PoseWithCovariance {Pose {Point
//                           position; Quaternion orientation}; float64[36]}, TwistWithCovariance
//                           {Twist {Vector3 linear; Vector3 angular}; float64[36]}
//   tf2_msgs/TFMessage (ROS 1 also tf/tfMessage) : geometry_msgs/TransformStamped[]
//   TransformStamped      : Header, string child_frame_id, Transform {Vector3 translation;
//                           Quaternion rotation}
//
// Errors: a payload that ends before a field, a string without its NUL (CDR) or with an
// impossible length, a sequence count that cannot fit in the remaining bytes, an unknown
// encapsulation kind: InputError without file (the caller adds file and message location),
// naming the message type, the field and the byte offset, e.g.
// "sensor_msgs/LaserScan: ranges: 1000 float32 values need 4000 bytes at byte 52, the message
// has 100". Values are returned as decoded (NaN / inf ranges kept); no semantic checks here.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "slamtune/io/ros/recording_container.h"
#include "slamtune/io/ros/ros_message_reader.h"

namespace slamtune::io {

// Each message's std_msgs/Header is a RosHeader (ros_message_reader.h, whose reader reads it).
struct LaserScanMessage {
  RosHeader header;
  float angle_min = 0, angle_max = 0, angle_increment = 0;  // rad
  float time_increment = 0, scan_time = 0;                  // s
  float range_min = 0, range_max = 0;                       // m
  std::vector<float> ranges;                                // m, as recorded
  std::vector<float> intensities;                           // may be empty
};

struct RosVector3 {
  double x = 0, y = 0, z = 0;
};
struct RosQuaternion {
  double x = 0, y = 0, z = 0, w = 1;
};

struct TransformStampedMessage {
  RosHeader header;  // header.frame_id = parent frame
  std::string child_frame_id;
  RosVector3 translation;
  RosQuaternion rotation;
};

struct TfMessage {
  std::vector<TransformStampedMessage> transforms;
};

struct OdometryMessage {
  RosHeader header;            // header.frame_id = odometry frame (e.g. "odom")
  std::string child_frame_id;  // base frame (e.g. "base_footprint")
  RosVector3 position;
  RosQuaternion orientation;
  std::array<double, 36> pose_covariance{};
  RosVector3 linear;  // twist, in the child frame
  RosVector3 angular;
  std::array<double, 36> twist_covariance{};
};

enum class RosMessageKind { kLaserScan, kOdometry, kTf, kOther };

// The kind of a type name as recordings write it: "sensor_msgs/msg/LaserScan" and
// "sensor_msgs/LaserScan"; "nav_msgs/msg/Odometry" and "nav_msgs/Odometry";
// "tf2_msgs/msg/TFMessage", "tf2_msgs/TFMessage" and "tf/tfMessage". Anything else kOther.
RosMessageKind KindOfRosType(std::string_view type);
// "sensor_msgs/LaserScan", "nav_msgs/Odometry", "tf2_msgs/TFMessage", "other".
const char* RosMessageKindName(RosMessageKind kind);

LaserScanMessage DecodeLaserScan(std::span<const std::uint8_t> data, MessageSerialization serialization);
OdometryMessage DecodeOdometry(std::span<const std::uint8_t> data, MessageSerialization serialization);
TfMessage DecodeTfMessage(std::span<const std::uint8_t> data, MessageSerialization serialization);

}  // namespace slamtune::io
