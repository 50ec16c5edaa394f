#include "slamtune/io/ros/recording_log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kMaxScanExamples = 5;  // of each kind of scan not used

std::string Join(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string TopicList(const RecordingContents& contents) {
  std::vector<std::string> items;
  for (const RecordedTopic& t : contents.container.topics) items.push_back(fmt::format("{} ({})", t.name, t.type));
  return items.empty() ? "none" : Join(items);
}

// --scan-topic, or the only LaserScan topic.
void ChooseScanTopic(const RecordingContents& contents, const RecordingReadOptions& options, RecordingInfo* info) {
  std::vector<std::string> candidates;
  for (const auto& [name, scans] : contents.scans)
    candidates.push_back(fmt::format("{} ({} messages)", name, scans.size()));
  if (!options.scan_topic.empty()) {
    if (contents.scans.count(options.scan_topic) == 0) {
      throw InputError(contents.path, 0,
                       fmt::format("--scan-topic {}: no sensor_msgs/LaserScan messages on it; LaserScan topics: {}",
                                   options.scan_topic, candidates.empty() ? "none" : Join(candidates)));
    }
    info->scan_topic = options.scan_topic;
    info->scan_topic_rule = "--scan-topic";
    return;
  }
  if (candidates.empty() && contents.scans_undecodable > 0) {
    throw InputError(contents.path, 0,
                     fmt::format("none of the {} sensor_msgs/LaserScan messages in the recording could be decoded "
                                 "(first: {}); its topics: {}",
                                 contents.scans_undecodable,
                                 contents.undecodable_examples.empty() ? "-" : contents.undecodable_examples.front(),
                                 TopicList(contents)));
  }
  if (candidates.empty()) {
    throw InputError(contents.path, 0,
                     "no sensor_msgs/LaserScan messages in the recording; its topics: " + TopicList(contents));
  }
  if (candidates.size() > 1) {
    throw InputError(
        contents.path, 0,
        fmt::format("{} LaserScan topics: {}; choose one with --scan-topic", candidates.size(), Join(candidates)));
  }
  info->scan_topic = contents.scans.begin()->first;
  info->scan_topic_rule = "the only LaserScan topic";
}

// Where the robot's odometric poses come from: a dynamic tf chain, or an Odometry topic's
// samples put into a TfBuffer of their own (same interpolation and gap rule).
struct OdometrySource {
  const TfBuffer* tf = nullptr;
  TfBuffer topic_samples;
  const std::vector<OdometrySample>* samples = nullptr;  // when from a topic
};

void UseOdometryTopic(const RecordingContents& contents, const std::string& topic, const RecordingReadOptions& options,
                      const std::string& rule, RecordingInfo* info, OdometrySource* source) {
  const std::vector<OdometrySample>& samples = contents.odometry.at(topic);
  info->odom_frame = options.odom_frame.empty() ? samples.front().frame_id : options.odom_frame;
  info->base_frame = options.base_frame.empty() ? samples.front().child_frame_id : options.base_frame;
  for (const OdometrySample& s : samples) {
    source->topic_samples.Add(info->odom_frame, info->base_frame, s.stamp_ns, s.pose, false, s.log_time_ns);
  }
  source->tf = &source->topic_samples;
  source->samples = &samples;
  info->odometry_source =
      fmt::format("topic {} (nav_msgs/Odometry, {} -> {})", topic, info->odom_frame, info->base_frame);
  info->odometry_rule = rule;
}

std::string LoopText(const std::vector<std::string>& loop) {
  std::string out;
  for (const std::string& frame : loop) out += (out.empty() ? "" : " -> ") + frame;
  return out;
}

// tf2 refuses every lookup through a loop of the tree: so does the reader, for the frames whose
// transforms it would compose (the odometry's or the laser offset's), naming the loop.
void RequireNoLoop(const RecordingContents& contents, std::initializer_list<const std::string*> frames,
                   const std::string& what) {
  for (const std::string* frame : frames) {
    const std::vector<std::string> loop = contents.tf.LoopAbove(*frame);
    if (loop.empty()) continue;
    std::string edges;
    for (std::size_t k = 1; k < loop.size(); ++k) {
      edges += fmt::format("{}{} -> {} ({})", edges.empty() ? "" : ", ", loop[k - 1], loop[k],
                           contents.tf.IsStatic(loop[k]) ? "static" : "dynamic");
    }
    throw TfLoopError(contents.path, 0,
                      fmt::format("the tf tree has a loop, {}: {} is its own ancestor ({}), so {} cannot be found "
                                  "(tf2 refuses every lookup through a loop); one of these transforms was published "
                                  "the wrong way round",
                                  LoopText(loop), loop.front(), edges, what));
  }
}

bool Connected(const TfBuffer& tf, const std::string& ancestor, const std::string& frame) {
  const std::vector<std::string> path = tf.PathToRoot(frame);
  return std::find(path.begin(), path.end(), ancestor) != path.end();
}

void ChooseOdometry(const RecordingContents& contents, const RecordingReadOptions& options, RecordingInfo* info,
                    OdometrySource* source) {
  if (!options.odom_topic.empty()) {
    if (contents.odometry.count(options.odom_topic) == 0) {
      std::vector<std::string> names;
      for (const auto& [name, samples] : contents.odometry) names.push_back(name);
      throw InputError(contents.path, 0,
                       fmt::format("--odom-topic {}: no nav_msgs/Odometry messages on it; Odometry topics: {}",
                                   options.odom_topic, names.empty() ? "none" : Join(names)));
    }
    UseOdometryTopic(contents, options.odom_topic, options, "--odom-topic", info, source);
    return;
  }
  const std::string odom = options.odom_frame.empty() ? "odom" : options.odom_frame;
  std::string base = options.base_frame;
  if (base.empty()) {
    for (const char* candidate : {"base_footprint", "base_link"}) {
      if (contents.tf.HasFrame(candidate) && Connected(contents.tf, odom, candidate)) {
        base = candidate;
        break;
      }
    }
  }
  if (!base.empty() && contents.tf.HasFrame(odom) && Connected(contents.tf, odom, base)) {
    RequireNoLoop(contents, {&odom, &base}, fmt::format("the odometry {} -> {}", odom, base));
    info->odom_frame = odom;
    info->base_frame = base;
    source->tf = &contents.tf;
    info->odometry_source = fmt::format("tf {} -> {}", odom, base);
    info->odometry_rule = fmt::format("odometry frame {} ({}), base frame {} ({})", odom,
                                      options.odom_frame.empty() ? "default" : "--odom-frame", base,
                                      options.base_frame.empty() ? "found in the tf tree" : "--base-frame");
    return;
  }
  const std::string why =
      fmt::format("no {} -> {} transform in /tf", odom, base.empty() ? "base_footprint/base_link" : base);
  if (contents.odometry.size() == 1) {
    UseOdometryTopic(contents, contents.odometry.begin()->first, options, why + "; the only Odometry topic", info,
                     source);
    return;
  }
  throw InputError(contents.path, 0,
                   fmt::format("no odometry: {} and {} nav_msgs/Odometry topics; name them with --odom-frame / "
                               "--base-frame or --odom-topic (tf: {})",
                               why, contents.odometry.size(),
                               contents.tf.Describe().empty() ? "empty" : Join(contents.tf.Describe())));
}

// base -> laser, from --laser-offset or the tf tree at the first scan.
RigidTransform3 ChooseLaserOffset(const RecordingContents& contents, const RecordingReadOptions& options,
                                  std::int64_t first_stamp, RecordingInfo* info) {
  RigidTransform3 offset;
  if (options.laser_offset) {
    const Pose2& o = *options.laser_offset;
    offset.translation = {o.x, o.y, 0.0};
    offset.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(o.theta, Eigen::Vector3d::UnitZ()));
    info->laser_offset_source = "--laser-offset";
    info->laser_offset = o;
    return offset;
  }
  if (info->laser_frame == info->base_frame) {
    info->laser_offset_source = "the scans are in the base frame";
    return offset;
  }
  RequireNoLoop(contents, {&info->base_frame, &info->laser_frame},
                fmt::format("the laser offset {} -> {}", info->base_frame, info->laser_frame));
  const TfLookup lookup = contents.tf.Lookup(info->base_frame, info->laser_frame, first_stamp);
  if (!lookup.transform) {
    throw InputError(
        contents.path, 0,
        fmt::format("no laser offset: {} -> {} not in the tf tree ({}); was /tf_static recorded? State the "
                    "mounting pose with --laser-offset X,Y,YAW",
                    info->base_frame, info->laser_frame, lookup.failure));
  }
  std::vector<std::string> chain = contents.tf.PathToRoot(info->laser_frame);
  const auto base = std::find(chain.begin(), chain.end(), info->base_frame);
  if (base != chain.end()) {
    chain.erase(base + 1, chain.end());  // laser ... base: the base is its ancestor (the usual tree)
  } else {
    chain.push_back(info->base_frame);  // through a common ancestor; named as a pair below
    chain.erase(chain.begin() + 1, chain.end() - 1);
  }
  std::reverse(chain.begin(), chain.end());
  bool all_static = true;
  for (std::size_t k = 1; k < chain.size(); ++k) all_static = all_static && contents.tf.IsStatic(chain[k]);
  std::string names;
  for (const std::string& frame : chain) names += (names.empty() ? "" : " -> ") + frame;
  info->laser_offset_source = fmt::format("tf {} ({})", names, all_static ? "static" : "at the first scan");
  return *lookup.transform;
}

// The planar mounting pose and how the laser sits (height, tilt, upside down).
void DescribeMounting(const RigidTransform3& offset, RecordingInfo* info) {
  const Eigen::Vector3d z = offset.rotation * Eigen::Vector3d::UnitZ();
  info->upside_down = z.z() < 0.0;
  const double tilt = RadToDeg(std::acos(std::clamp(std::fabs(z.z()), 0.0, 1.0)));
  info->laser_tilt_deg = tilt;
  info->laser_height_m = offset.translation.z();
  if (info->laser_offset_source != "--laser-offset") info->laser_offset = ToPose2(offset);
}

// Beams the message's angles describe, or 0 when they describe none.
std::size_t BeamsOfAngles(const LaserScanMessage& m, bool* closes_circle) {
  const double span = static_cast<double>(m.angle_max) - static_cast<double>(m.angle_min);
  const double inc = m.angle_increment;
  *closes_circle = false;
  if (!std::isfinite(span) || !std::isfinite(inc)) return 0;
  if (inc == 0.0) return span == 0.0 ? 1 : 0;
  const double steps = std::round(span / inc);
  if (!(steps >= 0.0 && steps < 1e7)) return 0;
  *closes_circle = std::fabs(std::fabs(span) - kTwoPi) < std::fabs(inc);
  return static_cast<std::size_t>(steps) + 1;
}

// Empty when the scan's ranges agree with its angles; otherwise what is wrong.
std::string GeometryProblem(const LaserScanMessage& m) {
  bool closes_circle = false;
  const std::size_t n = m.ranges.size();
  const std::size_t beams = BeamsOfAngles(m, &closes_circle);
  if (n == 0) return "LaserScan has no ranges";
  const double first = m.angle_min, last = m.angle_max;
  if (std::fabs(first) > kMaxBeamAngle || std::fabs(last) > kMaxBeamAngle || std::fabs(last - first) > kMaxBeamAngle) {
    return fmt::format(
        "LaserScan angles {} .. {} rad (step {}) go beyond a full turn: angles must be radians "
        "(written in degrees?)",
        m.angle_min, m.angle_max, m.angle_increment);
  }
  if (beams == 0) {
    return fmt::format("LaserScan angles {} .. {} step {} rad describe no beams", m.angle_min, m.angle_max,
                       m.angle_increment);
  }
  if (std::isfinite(m.range_max) && m.range_max > 0.0f && std::isfinite(m.range_min) && m.range_min > m.range_max) {
    return fmt::format("LaserScan range_min {} m exceeds range_max {} m: no reading can be a range", m.range_min,
                       m.range_max);
  }
  if (n == beams || (closes_circle && n + 1 == beams)) return "";
  return fmt::format("LaserScan has {} ranges but its angles ({} .. {} rad, step {}) give {} beams", n, m.angle_min,
                     m.angle_max, m.angle_increment, beams);
}

void Example(std::vector<std::string>* examples, const std::string& text) {
  if (examples->size() < kMaxScanExamples) examples->push_back(text);
}

LaserScanRecord ToRecord(const RecordedScan& scan, std::size_t index, const RecordingInfo& info) {
  const LaserScanMessage& m = scan.message;
  LaserScanRecord r;
  r.line = index + 1;
  r.kind = RecordKind::kRosLaserScan;
  // The message's float32 values widened to double, as both nodes hand them to Karto.
  r.angle_min = m.angle_min;
  r.angle_increment = m.angle_increment;
  r.angle_max = static_cast<double>(m.angle_max);
  r.ranges.assign(m.ranges.begin(), m.ranges.end());
  if (info.upside_down) {
    // As both nodes do: the readings reversed, the angles as the message gives them (right for a
    // scan symmetric about the laser's x axis, as upside-down mounts are used).
    std::reverse(r.ranges.begin(), r.ranges.end());
  }
  r.max_range = (m.range_max > 0.0f && std::isfinite(m.range_max)) ? static_cast<double>(m.range_max)
                                                                   : std::numeric_limits<double>::infinity();
  r.range_min = std::isfinite(m.range_min) && m.range_min > 0.0f ? static_cast<double>(m.range_min) : 0.0;
  r.ipc_time = static_cast<double>(m.header.stamp_ns) / 1e9;
  r.header_stamp_ns = static_cast<std::int64_t>(m.header.stamp_ns);
  r.logger_time = static_cast<double>(scan.log_time_ns) / 1e9;
  return r;
}

void FillTopics(const RecordingContents& contents, RecordingInfo* info) {
  for (const RecordedTopic& t : contents.container.topics) {
    RecordingInfo::Topic topic{t.name, t.type, t.messages, 0.0};
    auto it = contents.receive_times.find(t.name);
    if (it != contents.receive_times.end() && it->second.size() > 1) {
      const auto [lo, hi] = std::minmax_element(it->second.begin(), it->second.end());
      if (*hi > *lo)
        topic.rate_hz = static_cast<double>(it->second.size() - 1) / (static_cast<double>(*hi - *lo) / 1e9);
    }
    info->topics.push_back(topic);
  }
}

// log.odometry: the Odometry topic's samples (with their velocities) when there is one for the
// base frame, else the tf samples of the odometry chain.
void FillOdometry(const RecordingContents& contents, const OdometrySource& source, LaserLog* log) {
  RecordingInfo& info = *log->recording;
  const std::vector<OdometrySample>* samples = source.samples;
  if (samples == nullptr) {
    for (const auto& [name, topic_samples] : contents.odometry) {
      if (!topic_samples.empty() && topic_samples.front().child_frame_id == info.base_frame) samples = &topic_samples;
    }
  }
  if (samples != nullptr) {
    info.odometry_velocities = true;
    for (std::size_t k = 0; k < samples->size(); ++k) {
      const OdometrySample& s = (*samples)[k];
      OdomRecord r;
      r.line = k + 1;
      r.pose = ToPose2(s.pose);
      r.tv = s.linear_x;
      r.rv = s.angular_z;
      r.ipc_time = static_cast<double>(s.stamp_ns) / 1e9;
      r.logger_time = static_cast<double>(s.log_time_ns) / 1e9;
      log->odometry.push_back(r);
    }
    return;
  }
  const std::vector<std::int64_t> stamps = source.tf->SampleStamps(info.base_frame);
  for (std::size_t k = 0; k < stamps.size(); ++k) {
    const TfLookup pose = source.tf->Lookup(info.odom_frame, info.base_frame, stamps[k]);
    if (!pose.transform) continue;
    OdomRecord r;
    r.line = k + 1;
    r.pose = ToPose2(*pose.transform);
    r.ipc_time = r.logger_time = static_cast<double>(stamps[k]) / 1e9;
    log->odometry.push_back(r);
  }
}

// What the recording holds before any choice is made: its container, what could not be read,
// the tf tree and the topics.
void DescribeRecording(const RecordingContents& contents, LaserLog* log) {
  RecordingInfo& info = *log->recording;
  const ContainerSummary& c = contents.container;
  info.format = ContainerFormatName(c.format);
  info.files = c.files;
  info.data_end = c.data_end;
  info.messages_undecodable = contents.messages_undecodable;
  info.scans_malformed = contents.scans_undecodable;
  for (const std::string& e : contents.undecodable_examples) Example(&info.malformed_examples, e);
  info.tf_edges = contents.tf.Describe();
  info.tf_parent_conflicts = contents.tf.parent_conflicts();
  info.tf_bad_rotations = contents.tf.bad_rotations();
  info.tf_refused_frames = contents.tf.refused_frames();
  for (const std::vector<std::string>& loop : contents.tf.Loops()) info.tf_loops.push_back(LoopText(loop));
  FillTopics(contents, &info);
  for (const RecordingInfo::Topic& t : info.topics) log->record_counts[t.name] = t.messages;
}

// Scan message k as a record posed by the odometry at its stamp, or none when it is malformed
// (an InputError unless lenient) or has no odometry there; either is counted in `info`.
std::optional<LaserScanRecord> PosedScan(const RecordingContents& contents, const RecordedScan& scan, std::size_t k,
                                         const LogReadOptions& options, const OdometrySource& source,
                                         RecordingInfo* info) {
  const LaserScanMessage& m = scan.message;
  if (const std::string problem = GeometryProblem(m); !problem.empty()) {
    const std::string where = fmt::format("{}: {}: {}", scan.location, info->scan_topic, problem);
    if (!options.lenient) throw InputError(contents.path, 0, where + " (--lenient skips such scans and counts them)");
    ++info->scans_malformed;
    Example(&info->malformed_examples, where);
    return std::nullopt;
  }
  if (NormalizeFrameId(m.header.frame_id) != info->laser_frame) ++info->scans_other_frame;
  if (!(std::isfinite(m.range_max) && m.range_max > 0.0f) && info->scans_bad_range_max++ == 0) {
    info->bad_range_max_example =
        fmt::format("scan {} at {}: range_max {}", k, StampText(m.header.stamp_ns), m.range_max);
  }
  const TfLookup pose =
      source.tf->Lookup(info->odom_frame, info->base_frame, m.header.stamp_ns, options.recording.max_odom_gap_s);
  if (!pose.transform) {
    ++info->scans_unplaced;
    Example(&info->unplaced_examples, fmt::format("scan {} at {}: {}", k, StampText(m.header.stamp_ns), pose.failure));
    return std::nullopt;
  }
  const Pose2 offset = info->laser_offset;
  LaserScanRecord record = ToRecord(scan, k, *info);
  record.robot_pose = ToPose2(*pose.transform);
  record.laser_offset = offset;
  record.laser_pose = offset == Pose2{} ? record.robot_pose : Compose(record.robot_pose, offset);
  if (options.no_return_value > 0) record.max_range = options.no_return_value;
  record.no_returns = CountNoReturns(record);
  return record;
}

// log.scans: every scan of the chosen topic that can be posed, up to max_scans. Throws when none can.
void AddPosedScans(const RecordingContents& contents, const std::vector<RecordedScan>& scans,
                   const LogReadOptions& options, const OdometrySource& source, LaserLog* log) {
  RecordingInfo& info = *log->recording;
  for (std::size_t k = 0; k < scans.size(); ++k) {
    if (options.max_scans > 0 && log->scans.size() >= options.max_scans) {
      log->stopped_at_max_scans = true;
      break;
    }
    std::optional<LaserScanRecord> record = PosedScan(contents, scans[k], k, options, source, &info);
    if (!record) continue;
    if (!log->scans.empty() && record->ipc_time < log->scans.back().ipc_time) {
      ++log->time_backward_steps;
      log->largest_backward_step_s =
          std::max(log->largest_backward_step_s, log->scans.back().ipc_time - record->ipc_time);
    }
    log->total_readings += record->ranges.size();
    log->total_no_returns += record->no_returns;
    log->scans.push_back(std::move(*record));
  }
  if (log->scans.empty()) {
    throw InputError(
        contents.path, 0,
        fmt::format("none of the {} scans on {} could be used: {} without odometry ({}), {} malformed", scans.size(),
                    info.scan_topic, info.scans_unplaced,
                    info.unplaced_examples.empty() ? "-" : info.unplaced_examples.front(), info.scans_malformed));
  }
}

// --no-return, else the first scan's range_max.
void ChooseNoReturnValue(const LogReadOptions& options, LaserLog* log) {
  if (options.no_return_value > 0) {
    log->no_return_value = options.no_return_value;
    log->no_return_rule = "--no-return";
  } else {
    log->no_return_value = log->scans.front().max_range;
    log->no_return_rule = std::isfinite(log->no_return_value)
                              ? "LaserScan range_max"
                              : "none: LaserScan range_max is NaN, infinite, 0 or negative";
  }
}

}  // namespace

LaserLog RecordingToLog(const RecordingContents& contents, const LogReadOptions& options) {
  options.Validate();
  const RecordingReadOptions& choice = options.recording;
  LaserLog log;
  log.path = contents.path;
  log.recording.emplace();
  RecordingInfo& info = *log.recording;
  DescribeRecording(contents, &log);

  ChooseScanTopic(contents, choice, &info);
  const std::vector<RecordedScan>& scans = contents.scans.at(info.scan_topic);
  SLAMTUNE_CHECK(!scans.empty());  // a scan topic has an entry only once a scan of it decoded
  info.scan_messages = scans.size();
  info.laser_frame = NormalizeFrameId(scans.front().message.header.frame_id);
  OdometrySource source;
  ChooseOdometry(contents, choice, &info, &source);
  const RigidTransform3 mount = ChooseLaserOffset(contents, choice, scans.front().message.header.stamp_ns, &info);
  DescribeMounting(mount, &info);

  AddPosedScans(contents, scans, options, source, &log);
  ChooseNoReturnValue(options, &log);
  FillOdometry(contents, source, &log);
  return log;
}

LaserLog ReadRecordingLog(const std::string& path, const LogReadOptions& options) {
  options.Validate();
  // Scans beyond max_scans are not kept; a few more than asked cover scans that cannot be placed.
  const std::size_t keep = options.max_scans > 0 ? options.max_scans * 2 + 100 : 0;
  const RecordingContents contents = ReadRecordingContents(path, options.lenient, keep);
  return RecordingToLog(contents, options);
}

}  // namespace slamtune::io
