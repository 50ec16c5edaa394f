// `slamtune check`: what to know about a recording before tuning on it, in the spirit of
// cartographer_rosbag_validate. It reads the log as the other commands do (log_reader.h) but
// with the beams left as recorded, and for a ROS recording also looks at the raw messages, so
// that it can say what the reading would otherwise have had to repair or drop.
//
// Problems found (ProblemKind), each with how many, the first scans (log scan indices; for a
// recording, message indices on the scan topic) and their times:
//   scan stamps: gaps longer than gap_factor x the median period, stamps going back,
//     duplicated stamps;
//   beams: the reading count or angles change between scans;
//   range_max: readings above the scan's range_max (range_max too low), or the largest reading
//     far below it (too high: less than range_max_use_fraction of it), and a majority of
//     no-returns;
//   odometry: jumps (faster than max_speed_mps or max_turn_rate_rad_s between samples), stalls
//     (no sample for longer than stall_s while scans go on, or the pose frozen while the
//     recorded speed says moving), heading wraps away from +-pi, and poses that disagree
//     with the velocities recorded beside them — moving forward while the speed is negative,
//     or the other way round (a logger that integrated |tv|: the map breaks and no SLAM
//     parameter is to blame);
//   tf: scans without odometry at their stamp (missing), odometry received more than late_s
//     after the scan it places (late), no laser offset in the tf tree (/tf_static missing), a
//     loop in the tree (on the frames used, nothing further can be checked: the report ends
//     there, as every other command refuses such a recording);
//   the recording: several LaserScan topics, malformed messages, a truncated tail.
// Facts (no problem): topics with types and rates, the choices made, the laser offset found.
// The odometry checks are odometry_check.h; check_problems.h is how every check records a problem.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/ros/recording_contents.h"
#include "slamtune/io/scan_losses.h"

namespace slamtune::io {

struct CheckOptions {
  double gap_factor = 3.0;                // a scan gap is longer than this x the median period
  double range_max_use_fraction = 0.5;    // largest reading below this fraction of range_max: too high
  double no_return_majority = 0.5;        // share of no-returns counted as a problem
  double max_speed_mps = 3.0;             // odometry faster than this between samples: a jump
  double max_turn_rate_rad_s = 6.0;       // or turning faster than this (and by > 0.2 rad)
  double stall_s = 1.0;                   // no odometry sample for this long while scanning: a stall
  double moving_speed_mps = 0.05;         // |tv| above this means the robot is moving
  double late_s = 0.5;                    // odometry received this long after its scan: late
  double velocity_mismatch_share = 0.05;  // share of moving steps that disagree, to report

  void Validate() const;
};

enum class ProblemKind {
  kScanGap,
  kScanStampBackward,
  kScanStampDuplicate,
  kBeamGeometryChange,
  kLaserCountMismatch,  // a node's Karto laser expects another reading count than the first scan has
  kRangeMaxTooLow,
  kRangeMaxTooHigh,
  kBadRangeMax,     // range_max NaN, infinite, 0 or negative: read with no upper limit
  kNoValidReading,  // not one reading of the log is a range: nothing can be mapped
  kMostlyNoReturns,
  kOdometryJump,
  kOdometryStall,
  kHeadingWrap,
  kOdometryVelocityMismatch,
  kTfMissing,
  kTfLate,
  kNoLaserOffset,
  kTfLoop,
  kSeveralScanTopics,
  kMalformedMessages,
  kTruncatedRecording,
};
// Stable snake_case name, e.g. "scan_gap", for JSON and tests.
const char* ProblemKindName(ProblemKind kind);

struct CheckProblem {
  ProblemKind kind;
  std::string what;                // one line, with the numbers
  std::size_t count = 0;           // occurrences
  std::vector<std::size_t> scans;  // the first few scans concerned
  std::vector<double> times_s;     // their times (stamps)
};

struct CheckReport {
  std::string path;
  std::vector<std::string> facts;  // "NAME: value" lines
  std::vector<CheckProblem> problems;
  ScanLosses scans_not_used;  // the kinds the recording decides, for either node (io/scan_losses.h)
  bool ok() const { return problems.empty(); }
  bool Has(ProblemKind kind) const;
};

// Reads `path` with `read` (beams kept as recorded) and checks it. InputError only for what
// makes the file unreadable (format errors); choices that cannot be made are problems.
CheckReport CheckRecording(const std::string& path, const LogReadOptions& read, const CheckOptions& options = {});

// CheckRecording on a ROS recording's contents already read.
CheckReport CheckRecordingContents(const RecordingContents& contents, const LogReadOptions& read,
                                   const CheckOptions& options = {});

// The checks on a log already read (beams as recorded); no raw-message checks.
CheckReport CheckLog(const LaserLog& log, const CheckOptions& options = {});

// A human-readable report: facts, then each problem with its scans, then the verdict.
std::string FormatCheckReport(const CheckReport& report);

}  // namespace slamtune::io
