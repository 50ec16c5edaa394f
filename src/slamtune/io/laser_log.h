// In-memory model of a 2D laser log: what the CARMEN reader produces, what the simulator
// writes, and what the SLAM engine consumes. Readings are kept exactly as recorded; how the
// engine treats no-returns follows Karto (docs/engine.md §2, §10 item 1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/io/data_end.h"

namespace slamtune::io {

// kRosLaserScan: a sensor_msgs/LaserScan of a ROS recording (ros/recording_log.h).
enum class RecordKind { kFlaser, kRobotLaser1, kRawLaser, kOdom, kParam, kComment, kUnknown, kRosLaserScan };

const char* RecordKindName(RecordKind kind);

// One laser scan, in file order.
struct LaserScanRecord {
  std::size_t line = 0;  // 1-based line of the record in its file
  RecordKind kind = RecordKind::kFlaser;
  // Beam geometry in the laser frame: beam i is at angle_min + i * angle_increment (rad).
  double angle_min = 0.0;
  double angle_increment = 0.0;
  // The last beam's angle as the record states it (a ROS LaserScan's angle_max, float32 widened):
  // a node's Karto derives the reading count it expects from it (slam/node_laser.h). None for
  // CARMEN records, whose geometry is a convention.
  std::optional<double> angle_max;
  // The value at or above which a reading means "no return" for this scan (m): the record's
  // own maximum range (ROBOTLASER1, RAWLASER) or the log's no-return value (FLASER).
  double max_range = std::numeric_limits<double>::infinity();
  // Readings at or below it are not used (m): a ROS LaserScan's range_min, which both nodes give
  // Karto as the laser's minimum range; 0 for CARMEN records.
  double range_min = 0.0;
  std::vector<double> ranges;  // as recorded, unchanged (no clipping, no NaN replacement)
  // Odometric poses at the scan: the laser's and the robot base's. FLASER gives both
  // (x y theta = laser, odom_x odom_y odom_theta = robot); RAWLASER takes the robot pose
  // interpolated from ODOM records and laser = robot (+) offset.
  Pose2 laser_pose;
  Pose2 robot_pose;
  // Laser mounting offset in the robot frame, Between(robot_pose, laser_pose).
  Pose2 laser_offset;
  double ipc_time = 0.0;     // s, the record's ipc_timestamp (relations refer to it)
  double logger_time = 0.0;  // s
  // A ROS LaserScan's header stamp in nanoseconds, exactly (ipc_time is the same in seconds,
  // rounded); none for a CARMEN record. StampNs() gives one for either.
  std::optional<std::int64_t> header_stamp_ns;
  std::size_t no_returns = 0;  // readings >= max_range, NaN, +-inf or negative
};

// A laser's beams: reading count and angles in the laser frame (beam i at angle_min + i * inc).
struct BeamGeometry {
  std::size_t readings = 0;
  double angle_min = 0.0;        // rad, first beam
  double angle_increment = 0.0;  // rad
  double angle_max() const {
    return angle_min + angle_increment * static_cast<double>(readings > 0 ? readings - 1 : 0);
  }
  // Same count, first and last beam within tolerance_rad (beam_geometry.h).
  bool SameAs(const BeamGeometry& other, double tolerance_rad) const;
  // "181 beams, -90.00 .. 90.00 deg, step 1.0000 deg".
  std::string ToString() const;
};

BeamGeometry GeometryOf(const LaserScanRecord& scan);

// The scan's stamp in nanoseconds as a node sees it: the header stamp of a ROS scan, a CARMEN
// record's ipc_timestamp rounded to the nanosecond (what a bag made from the log would carry).
std::int64_t StampNs(const LaserScanRecord& scan);

// The scan's no-returns as LaserScanRecord::no_returns counts them, against its max_range.
std::size_t CountNoReturns(const LaserScanRecord& scan);

// Readings of the log that are ranges: finite, above the scan's range_min and below its
// max_range (not no-returns).
struct LaserLog;
std::size_t CountRanges(const LaserLog& log);

// How scans whose beam geometry differs from the others' are treated (beam_geometry.h).
enum class BeamPolicy { kNode, kPerGeometry, kNearestBeam };

// The reading count a node's Karto laser expects, and how many scans of the log it drops for
// another count (beam_geometry.h ExpectedReadings), for each node.
struct NodeBeamCount {
  std::size_t expected = 0;  // readings the laser made from the first scan expects
  std::size_t dropped = 0;   // scans whose reading count differs: Karto refuses them
};

// What io::HarmonizeBeams did (beam_geometry.h).
struct BeamReport {
  std::string policy;  // "node", "per-geometry", "nearest-beam"; empty when not applied
  struct Seen {
    BeamGeometry geometry;
    std::size_t scans = 0;
  };
  std::vector<Seen> geometries;      // distinct geometries, most scans first (the first seen on a tie)
  std::size_t scans_resampled = 0;   // nearest-beam: scans put onto the most common geometry
  std::size_t readings_outside = 0;  // nearest-beam: beams with no beam of the scan near them (+inf)
  NodeBeamCount slam_karto;          // before any resampling
  NodeBeamCount slam_toolbox;
  bool varies() const { return geometries.size() > 1; }
};

struct OdomRecord {
  std::size_t line = 0;
  Pose2 pose;
  double tv = 0.0, rv = 0.0, accel = 0.0;
  double ipc_time = 0.0, logger_time = 0.0;
};

// Where the scans of a ROS recording came from and what could not be used (ros/recording_log.h).
// The rule for a LaserScan whose range_max is NaN, infinite, 0 or negative, as every output says it.
inline constexpr const char* kBadRangeMaxRule =
    "read with no upper limit: inf and NaN readings are no-returns, every other reading above range_min is a range, "
    "and the range threshold is the node's own (--no-return M sets a limit)";

struct RecordingInfo {
  std::string format;  // "MCAP", "rosbag2 SQLite3", "ROS 1 bag v2.0"
  std::vector<std::string> files;
  DataEnd data_end;  // how the container's data ended
  struct Topic {
    std::string name, type;
    std::size_t messages = 0;
    double rate_hz = 0.0;  // (messages - 1) / span of their receive times; 0 if undefined
  };
  std::vector<Topic> topics;
  // Each choice and how it was made ("--scan-topic", "the only LaserScan topic", ...).
  std::string scan_topic, scan_topic_rule;
  std::string odometry_source, odometry_rule;  // e.g. "tf odom -> base_footprint"
  std::string odom_frame, base_frame, laser_frame;
  std::string laser_offset_source;             // e.g. "tf base_footprint -> base_link -> laser (static)"
  Pose2 laser_offset;                          // base -> laser, projected to x, y, yaw
  double laser_height_m = 0.0;                 // z of the laser above the base frame
  double laser_tilt_deg = 0.0;                 // angle between the laser's z axis and the base's
  bool upside_down = false;                    // z axis down: beams reversed (slam_toolbox)
  bool odometry_velocities = false;            // log.odometry carries recorded tv, rv
  std::size_t scan_messages = 0;               // on the scan topic
  std::size_t scans_unplaced = 0;              // no odometry or laser pose at their stamp: not used
  std::vector<std::string> unplaced_examples;  // the first few, "scan K at T s: why"
  std::size_t scans_malformed = 0;             // --lenient: undecodable or inconsistent, not used
  std::vector<std::string> malformed_examples;
  std::size_t scans_other_frame = 0;  // frame_id differs from the first scan's (used)
  // Scans whose range_max is NaN, infinite, 0 or negative: read with no upper limit (inf and NaN
  // readings are no-returns, every other reading above range_min is a range); the first, e.g.
  // "scan 0 at 100.000000 s: range_max nan".
  std::size_t scans_bad_range_max = 0;
  std::string bad_range_max_example;
  std::size_t messages_undecodable = 0;  // --lenient: tf / odometry messages skipped
  std::vector<std::string> tf_edges;     // "parent -> child (static)" / "(N samples)"
  std::size_t tf_parent_conflicts = 0;   // transforms giving a frame a second parent, ignored
  std::size_t tf_bad_rotations = 0;      // transforms refused for a bad quaternion
  std::size_t tf_refused_frames = 0;     // refused: a frame its own parent, or an empty frame id
  std::vector<std::string> tf_loops;     // loops of the tree not on the frames used, "a -> b -> a"
};

struct LaserLog {
  std::string path;                    // as given to the reader ("<memory>" for streams)
  std::vector<LaserScanRecord> scans;  // file order
  std::vector<OdomRecord> odometry;    // file order
  // Records seen per type name as written in the file ("FLASER", "ODOM", "PARAM", "#" for
  // comments, and unknown names as they appear), including skipped ones.
  std::map<std::string, std::size_t> record_counts;
  std::map<std::string, std::string> params;  // PARAM name -> value (last wins)
  std::size_t unknown_records = 0;            // lines of unknown type, skipped
  std::size_t skipped_records = 0;            // malformed records skipped under --lenient
  std::vector<std::string> skipped_reasons;   // "LINE: reason" for the first few skipped
  std::size_t skipped_scans = 0;              // of those, laser records (FLASER, ROBOTLASER1, RAWLASER1..4)
  std::string first_skipped_scan;             // "line N: reason" of the first
  // RAWLASER scans outside the time span of the ODOM records: no pose to interpolate, so they
  // are left out of `scans` (never posed by clamping) and counted here; the first one in
  // words, e.g. "line 12 at 130.5 s; ODOM 100 .. 120 s".
  std::size_t scans_without_odometry = 0;
  std::string first_scan_without_odometry;
  // The no-return value assumed for the log (m) and how it was found ("--no-return",
  // "PARAM <name>", "<RECORD> max_range" e.g. "ROBOTLASER1 max_range", "maximum reading
  // cluster", "none"); the precedence is documented in carmen_reader.h.
  double no_return_value = std::numeric_limits<double>::infinity();
  std::string no_return_rule = "none";
  // Consecutive laser scans (file order) whose ipc_timestamp is earlier than the previous one.
  std::size_t time_backward_steps = 0;
  double largest_backward_step_s = 0.0;
  // Reading context.
  std::size_t lines_read = 0;              // lines consumed (all of them unless max_scans stopped early)
  bool compressed = false;                 // the input was gzip
  bool stopped_at_max_scans = false;       // LogReadOptions::max_scans ended the read early
  std::size_t total_readings = 0;          // sum of ranges.size() over scans
  std::size_t total_no_returns = 0;        // sum of no_returns over scans
  BeamReport beams;                        // one geometry for the engine (beam_geometry.h)
  std::optional<RecordingInfo> recording;  // set when the log was read from a ROS recording
};

// Choices made when turning a ROS recording into a log (ros/recording_log.h); empty = automatic.
struct RecordingReadOptions {
  std::string scan_topic;             // sensor_msgs/LaserScan topic; "" = the only one
  std::string odom_topic;             // nav_msgs/Odometry topic for the poses; "" = odom -> base from /tf
  std::string odom_frame;             // "" = "odom"
  std::string base_frame;             // "" = base_footprint, else base_link, as found in the tf tree
  std::optional<Pose2> laser_offset;  // base -> laser (m, m, rad), instead of the tf tree's
  double max_odom_gap_s = 0.5;        // odometry samples farther apart are not interpolated

  void Validate() const;
};

struct LogReadOptions {
  bool lenient = false;                  // skip malformed records (and count them) instead of failing
  double no_return_value = 0;            // > 0 overrides the detected no-return value (m)
  std::size_t max_scans = 0;             // stop after this many laser scans (0 = all); for short slices
  BeamPolicy beams = BeamPolicy::kNode;  // applied by ReadLaserLog (log_reader.h)
  RecordingReadOptions recording;        // for ROS recordings

  // Throws InputError naming the field if no_return_value is negative, NaN or infinite.
  void Validate() const;
};

}  // namespace slamtune::io
