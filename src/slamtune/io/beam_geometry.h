// One beam geometry for a whole log.
//
// Karto describes a laser once (docs/engine.md §2.1): every scan must have the first
// scan's reading count, or Process rejects it, and scans of the same count are read with the
// first scan's angles whatever their own. Real recordings break that: a CARMEN log whose scans
// alternate between 180 and 181 readings with four start angles, cheap lidars whose count
// varies from turn to turn (slam_toolbox#540, "contains 268 range readings, expected 274").
//
// Both nodes make one Karto laser per frame from the first scan they receive, and Karto's
// LaserRangeFinder::Validate refuses every scan whose reading count differs from the count that
// laser expects (ExpectedReadings), with no more than a line on the console.
//
// Policy (BeamPolicy):
//   * kNode (default): nothing is changed; the engine does what the node does (drops the scans of
//     another count, counted as the run's scans_wrong_reading_count), and the counts of
//     NodeBeamCount say how many, for each node, wherever the log is described.
//   * kPerGeometry: nothing is changed; the engine gives each beam geometry a Karto laser of its
//     own, as Karto does for several lasers (exact angles, no reading changed; slam/log_runner.h
//     LasersOf, docs/engine.md §3.5). For logs where the driver cannot be made to publish one
//     count; neither node runs this way on such a log.
//   * kNearestBeam: an approximation: the geometry most scans have (the first seen on a tie) is
//     the reference; every scan with another one is resampled onto it, each reference beam taking
//     the reading of the nearest beam of the scan's own geometry, and +inf (no return) where the
//     scan has no beam within half of its own increment. The engine then maps scans the node
//     never sees.
// Geometries are "the same" when they have the same reading count and their first and last
// beam angles agree within kSameAngleTolerance (1e-6 rad: float32 rounding of a ROS message
// is 1e-7).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/common/karto_math.h"
#include "slamtune/io/laser_log.h"

namespace slamtune::io {

inline constexpr double kSameAngleTolerance = 1e-6;  // rad

// The beam angles a laser can mean (rad): every beam within +-kMaxBeamAngle and a field of view
// of at most kMaxBeamAngle, a full turn plus kFullTurnTolerance (6-decimal and float32 rounding,
// a driver's extra step closing the circle). Beyond that the values are degrees written where
// radians belong, or corrupt: the CARMEN and recording readers refuse them, naming the record,
// rather than draw a starburst map.
inline constexpr double kFullTurnTolerance = 0.01;
inline constexpr double kMaxBeamAngle = kTwoPi + kFullTurnTolerance;
// A CARMEN fov may be (n - 1) or n angular steps; beyond kFovTolerance plus 1 % of the beams'
// span on either side it contradicts the steps (carmen_records.cc).
inline constexpr double kFovTolerance = 0.01;  // rad

// Empty when beams first, first + increment, ..., first + (n - 1) * increment are angles a laser
// can mean (above); otherwise what is wrong, e.g. "first beam at -90 rad is beyond +-2pi".
std::string BeamAnglesProblem(double first, double increment, std::size_t n);

const char* BeamPolicyName(BeamPolicy policy);  // "node", "per-geometry", "nearest-beam"
// Those names ("strict" and "resample", their names in older run folders, read as "node" and
// "nearest-beam"); InputError naming the option otherwise.
BeamPolicy ParseBeamPolicy(const std::string& text);

// Whose rule counts the readings a laser expects: open_karto's (slam_karto) or slam_toolbox's.
enum class KartoLaserRule { kSlamKarto, kSlamToolbox };

// The reading count a node's Karto laser made from `first` expects of every scan
// (LaserRangeFinder::Update, in double on the message's float32 values): round((angle_max -
// angle_min) / angle_increment) + 1. slam_toolbox (laser_utils.cpp) makes a laser whose angles
// span a full turn within one increment a 360-degree one, which expects one reading fewer, unless
// its span is over 350 deg and round(span / increment) + 1 is the scan's count. Without
// angle_max (CARMEN records, whose geometry is a convention) the first scan's own count.
std::size_t ExpectedReadings(KartoLaserRule rule, const LaserScanRecord& first);

// Records the log's geometries and the nodes' counts in log->beams and, with kNearestBeam, makes
// the scans share one geometry. Idempotent.
void HarmonizeBeams(BeamPolicy policy, LaserLog* log);

// `scan`'s readings on `target` beams as described above; no_returns recounted against the
// scan's max_range. Returns the target beams that no beam of the scan is near (set to +inf).
std::size_t ResampleScan(const BeamGeometry& target, LaserScanRecord* scan);

}  // namespace slamtune::io
