#include "slamtune/io/ros/recording_contents.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kMaxUndecodableExamples = 5;

RigidTransform3 ToRigid(const RosVector3& t, const RosQuaternion& q) {
  RigidTransform3 out;
  out.translation = {t.x, t.y, t.z};
  out.rotation = Eigen::Quaterniond(q.w, q.x, q.y, q.z);
  return out;
}

struct Reader {
  RecordingContents* out;
  bool lenient;
  std::size_t max_scan_messages;

  void Message(const RecordedTopic& topic, const RecordedMessage& message) {
    out->receive_times[topic.name].push_back(message.log_time_ns);
    const RosMessageKind kind = KindOfRosType(topic.type);
    if (kind == RosMessageKind::kOther) return;
    try {
      Decode(kind, topic, message);
    } catch (const InputError& e) {
      const std::string where =
          fmt::format("{}: {}: {}: {}", message.location.file.empty() ? out->path : message.location.file,
                      message.location.ToString(), topic.name, e.what());
      if (!lenient) throw InputError(where);
      (kind == RosMessageKind::kLaserScan ? out->scans_undecodable : out->messages_undecodable) += 1;
      if (out->undecodable_examples.size() < kMaxUndecodableExamples) out->undecodable_examples.push_back(where);
    }
  }

  void Decode(RosMessageKind kind, const RecordedTopic& topic, const RecordedMessage& message) {
    switch (kind) {
      case RosMessageKind::kLaserScan: {
        const auto known = out->scans.find(topic.name);
        if (max_scan_messages > 0 && known != out->scans.end() && known->second.size() >= max_scan_messages) return;
        // Decoded before the topic gets its entry: a topic whose every scan is undecodable
        // (lenient) has none, so it is never offered as a scan topic with no scans.
        RecordedScan scan{DecodeLaserScan(message.data, topic.serialization), message.log_time_ns,
                          message.location.ToString()};
        out->scans[topic.name].push_back(std::move(scan));
        return;
      }
      case RosMessageKind::kOdometry: {
        const OdometryMessage m = DecodeOdometry(message.data, topic.serialization);
        out->odometry[topic.name].push_back({m.header.stamp_ns, message.log_time_ns,
                                             NormalizeFrameId(m.header.frame_id), NormalizeFrameId(m.child_frame_id),
                                             ToRigid(m.position, m.orientation), m.linear.x, m.angular.z});
        return;
      }
      case RosMessageKind::kTf: {
        const TfMessage m = DecodeTfMessage(message.data, topic.serialization);
        const bool is_static = topic.latched || topic.name.ends_with("tf_static");
        ++out->tf_messages;
        if (is_static) ++out->static_tf_messages;
        for (const TransformStampedMessage& t : m.transforms) {
          out->tf.Add(NormalizeFrameId(t.header.frame_id), NormalizeFrameId(t.child_frame_id), t.header.stamp_ns,
                      ToRigid(t.translation, t.rotation), is_static, message.log_time_ns);
        }
        return;
      }
      case RosMessageKind::kOther: return;
    }
  }
};

}  // namespace

RecordingContents ReadRecordingContents(const std::string& path, bool lenient, std::size_t max_scan_messages) {
  RecordingContents contents;
  contents.path = path;
  Reader reader{&contents, lenient, max_scan_messages};
  ContainerReadOptions options;
  options.lenient = lenient;
  contents.container = ReadRosRecording(path, options, [&](const RecordedTopic& topic, const RecordedMessage& message) {
    reader.Message(topic, message);
  });
  return contents;
}

}  // namespace slamtune::io
