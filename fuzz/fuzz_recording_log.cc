// The step from a recording's decoded contents to the laser log every command works on
// (io/ros/recording_log.h RecordingToLog), past the containers: the contents are built from the input
// as a program (fuzz_input.h) — LaserScans on one or two topics with any stamps, angles, limits
// and ranges (NaN, infinities, range_max 0 or negative, range_min above range_max), a tf tree of
// static and dynamic transforms between a few frames (loops, gaps, bad rotations), Odometry
// samples — and read with any choice of topic, frames, offset, odometry gap, no-return value,
// strict or lenient. Then the beam geometry (every policy), the check, the description and the
// scans not used. An InputError is the expected answer; besides crashes, the log's promises are
// checked: every scan it keeps has a finite robot and laser pose.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/check/log_check.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/ros/recording_contents.h"
#include "slamtune/io/ros/recording_log.h"
#include "slamtune/io/scan_losses.h"

namespace {

using slamtune::fuzz::FuzzInput;
namespace io = slamtune::io;

const std::vector<std::string> kFrames = {"odom", "base_link", "base_footprint", "laser", "map", "", "/laser"};
const std::vector<std::string> kScanTopics = {"/scan", "/scan2"};
constexpr std::int64_t kTick = 10000000;  // stamps in steps of 10 ms

float Float(FuzzInput& in) { return static_cast<float>(in.Double()); }

io::RigidTransform3 Transform(FuzzInput& in) {
  io::RigidTransform3 t;
  t.translation = {in.Double(), in.Double(), in.Bool() ? 0.0 : in.Double()};
  if (in.Bool()) {
    t.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(in.Double(), Eigen::Vector3d::UnitZ()));
  } else {
    t.rotation = Eigen::Quaterniond(in.Double(), in.Double(), in.Double(), in.Double());  // any norm
  }
  return t;
}

io::LaserScanMessage Scan(FuzzInput& in, std::int64_t stamp_ns) {
  io::LaserScanMessage m;
  m.header.stamp_ns = stamp_ns;
  m.header.frame_id = in.Bool() ? "laser" : in.Name(kFrames);
  const std::size_t n = in.Index(12);
  if (in.Bool()) {  // a sound geometry, so that the rest of the reading is reached
    m.angle_min = -0.5f;
    m.angle_increment = 0.25f;
    m.angle_max = -0.5f + 0.25f * static_cast<float>(n > 0 ? n - 1 : 0);
  } else {
    m.angle_min = Float(in);
    m.angle_max = Float(in);
    m.angle_increment = Float(in);
  }
  m.range_min = in.Bool() ? 0.1f : Float(in);
  m.range_max = in.Bool() ? 10.0f : Float(in);
  for (std::size_t i = 0; i < n; ++i) m.ranges.push_back(in.Bool() ? 1.0f + 0.5f * static_cast<float>(i) : Float(in));
  return m;
}

io::RecordingContents Contents(FuzzInput& in) {
  io::RecordingContents c;
  c.path = "fuzz.mcap";
  c.container.data_end.complete = in.Bool();
  if (!c.container.data_end.complete && in.Bool()) {
    c.container.data_end.dropped_bytes = in.U16();
    c.container.data_end.dropped_reason = "cut";
  }
  c.container.topics = {{"/tf", "tf2_msgs/msg/TFMessage", io::MessageSerialization::kCdr, false, 0},
                        {"/tf_static", "tf2_msgs/msg/TFMessage", io::MessageSerialization::kCdr, true, 0}};
  std::int64_t scan_stamp = 0;
  for (int step = 0; step < 200 && !in.empty(); ++step) {
    switch (in.Byte() % 6) {
      case 0:
      case 1: {  // a scan, mostly later than the last
        const std::string& topic = in.Index(4) == 0 ? kScanTopics[1] : kScanTopics[0];
        scan_stamp += in.Bool() ? 10 * kTick : in.Stamp(kTick);
        auto& scans = c.scans[topic];
        if (scans.empty())
          c.container.topics.push_back({topic, "sensor_msgs/msg/LaserScan", io::MessageSerialization::kCdr, false, 0});
        scans.push_back({Scan(in, scan_stamp), scan_stamp, "byte " + std::to_string(step)});
        c.receive_times[topic].push_back(scan_stamp + in.Stamp(kTick));
        break;
      }
      case 2:
      case 3: {  // the odometry chain, mostly odom -> base_link
        const bool usual = in.Bool();
        const std::string parent = usual ? "odom" : in.Name(kFrames);
        const std::string child = usual ? "base_link" : in.Name(kFrames);
        const std::int64_t stamp = in.Bool() ? scan_stamp + in.Stamp(kTick / 10) : in.Stamp(kTick);
        c.tf.Add(parent, child, stamp, Transform(in), /*is_static=*/false, stamp);
        ++c.tf_messages;
        break;
      }
      case 4: {  // a static transform, mostly base_link -> laser
        const bool usual = in.Bool();
        const std::string parent = usual ? "base_link" : in.Name(kFrames);
        const std::string child = usual ? "laser" : in.Name(kFrames);
        c.tf.Add(parent, child, 0, Transform(in), /*is_static=*/true, 0);
        ++c.static_tf_messages;
        break;
      }
      default: {  // an Odometry sample
        io::OdometrySample s;
        s.stamp_ns = in.Bool() ? scan_stamp : in.Stamp(kTick);
        s.log_time_ns = s.stamp_ns;
        s.frame_id = "odom";
        s.child_frame_id = in.Bool() ? "base_link" : in.Name(kFrames);
        s.pose = Transform(in);
        s.linear_x = in.Double();
        s.angular_z = in.Double();
        auto& samples = c.odometry["/odom"];
        if (samples.empty())
          c.container.topics.push_back({"/odom", "nav_msgs/msg/Odometry", io::MessageSerialization::kCdr, false, 0});
        samples.push_back(s);
        break;
      }
    }
  }
  return c;
}

io::LogReadOptions Options(FuzzInput& in) {
  io::LogReadOptions o;
  o.lenient = in.Bool();
  if (in.Index(4) == 0) o.no_return_value = in.Double();
  if (in.Index(4) == 0) o.max_scans = in.Index(8);
  io::RecordingReadOptions& r = o.recording;
  if (in.Index(4) == 0) r.scan_topic = in.Name(kScanTopics);
  if (in.Index(4) == 0) r.odom_topic = "/odom";
  if (in.Index(4) == 0) r.odom_frame = in.Name(kFrames);
  if (in.Index(4) == 0) r.base_frame = in.Name(kFrames);
  if (in.Index(4) == 0) r.laser_offset = slamtune::Pose2{in.Double(), in.Double(), in.Double()};
  if (in.Index(4) == 0) r.max_odom_gap_s = in.Double();
  return o;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzInput in(data, size);
  const io::LogReadOptions options = Options(in);
  const io::RecordingContents contents = Contents(in);
  try {
    options.Validate();
  } catch (const slamtune::InputError&) {
    return 0;
  }
  try {
    io::CheckRecordingContents(contents, options);
  } catch (const slamtune::InputError&) {
  }
  io::LaserLog log;
  try {
    log = io::RecordingToLog(contents, options);
  } catch (const slamtune::InputError&) {
    return 0;
  }
  for (const io::LaserScanRecord& scan : log.scans) {
    SLAMTUNE_CHECK(std::isfinite(scan.robot_pose.x) && std::isfinite(scan.robot_pose.y) &&
                   std::isfinite(scan.robot_pose.theta));
    SLAMTUNE_CHECK(std::isfinite(scan.laser_pose.x) && std::isfinite(scan.laser_pose.y) &&
                   std::isfinite(scan.laser_pose.theta));
  }
  io::DescribeLogInput(log);
  io::ReadingLosses(log);
  io::CheckLog(log);
  try {
    io::RequireRanges(log);
  } catch (const slamtune::InputError&) {
  }
  for (const io::BeamPolicy policy :
       {io::BeamPolicy::kNode, io::BeamPolicy::kPerGeometry, io::BeamPolicy::kNearestBeam}) {
    io::LaserLog copy = log;
    try {
      io::HarmonizeBeams(policy, &copy);
      io::DescribeLogInput(copy);
      io::ReadingLosses(copy, io::KartoLaserRule::kSlamKarto);
    } catch (const slamtune::InputError&) {
    }
  }
  return 0;
}
