#include "slamtune/io/ros/ros_messages.h"

#include <array>

#include "slamtune/io/ros/ros_message_reader.h"

namespace slamtune::io {
namespace {

constexpr const char* kLaserScan = "sensor_msgs/LaserScan";
constexpr const char* kOdometry = "nav_msgs/Odometry";
constexpr const char* kTf = "tf2_msgs/TFMessage";

// Every geometry_msgs/TransformStamped takes at least its stamp (8 bytes), two string lengths
// (8) and seven float64 (56), in either serialization.
constexpr std::size_t kMinTransformBytes = 72;

RosVector3 ReadVector3(RosMessageReader& in, std::string_view field) {
  std::array<double, 3> v{};
  in.ReadFloat64Array(field, v);
  return {v[0], v[1], v[2]};
}

RosQuaternion ReadQuaternion(RosMessageReader& in, std::string_view field) {
  std::array<double, 4> q{};
  in.ReadFloat64Array(field, q);
  return {q[0], q[1], q[2], q[3]};
}

}  // namespace

RosMessageKind KindOfRosType(std::string_view type) {
  if (type == "sensor_msgs/msg/LaserScan" || type == "sensor_msgs/LaserScan") return RosMessageKind::kLaserScan;
  if (type == "nav_msgs/msg/Odometry" || type == "nav_msgs/Odometry") return RosMessageKind::kOdometry;
  if (type == "tf2_msgs/msg/TFMessage" || type == "tf2_msgs/TFMessage" || type == "tf/tfMessage") {
    return RosMessageKind::kTf;
  }
  return RosMessageKind::kOther;
}

const char* RosMessageKindName(RosMessageKind kind) {
  switch (kind) {
    case RosMessageKind::kLaserScan: return kLaserScan;
    case RosMessageKind::kOdometry: return kOdometry;
    case RosMessageKind::kTf: return kTf;
    case RosMessageKind::kOther: return "other";
  }
  return "other";
}

LaserScanMessage DecodeLaserScan(std::span<const std::uint8_t> data, MessageSerialization serialization) {
  RosMessageReader in(data, serialization, kLaserScan);
  LaserScanMessage scan;
  scan.header = in.ReadHeader();
  scan.angle_min = in.ReadFloat32("angle_min");
  scan.angle_max = in.ReadFloat32("angle_max");
  scan.angle_increment = in.ReadFloat32("angle_increment");
  scan.time_increment = in.ReadFloat32("time_increment");
  scan.scan_time = in.ReadFloat32("scan_time");
  scan.range_min = in.ReadFloat32("range_min");
  scan.range_max = in.ReadFloat32("range_max");
  scan.ranges = in.ReadFloat32Sequence("ranges");
  scan.intensities = in.ReadFloat32Sequence("intensities");
  return scan;
}

OdometryMessage DecodeOdometry(std::span<const std::uint8_t> data, MessageSerialization serialization) {
  RosMessageReader in(data, serialization, kOdometry);
  OdometryMessage odom;
  odom.header = in.ReadHeader();
  odom.child_frame_id = in.ReadString("child_frame_id");
  odom.position = ReadVector3(in, "pose.pose.position");
  odom.orientation = ReadQuaternion(in, "pose.pose.orientation");
  in.ReadFloat64Array("pose.covariance", odom.pose_covariance);
  odom.linear = ReadVector3(in, "twist.twist.linear");
  odom.angular = ReadVector3(in, "twist.twist.angular");
  in.ReadFloat64Array("twist.covariance", odom.twist_covariance);
  return odom;
}

TfMessage DecodeTfMessage(std::span<const std::uint8_t> data, MessageSerialization serialization) {
  RosMessageReader in(data, serialization, kTf);
  TfMessage tf;
  const std::uint32_t count = in.ReadSequenceCount("transforms", kMinTransformBytes);
  tf.transforms.reserve(count);
  for (std::uint32_t i = 0; i < count; ++i) {
    in.set_context("transforms[" + std::to_string(i) + "]");
    TransformStampedMessage& t = tf.transforms.emplace_back();
    t.header = in.ReadHeader();
    t.child_frame_id = in.ReadString("child_frame_id");
    t.translation = ReadVector3(in, "transform.translation");
    t.rotation = ReadQuaternion(in, "transform.rotation");
  }
  return tf;
}

}  // namespace slamtune::io
