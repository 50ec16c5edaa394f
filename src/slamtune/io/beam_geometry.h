// One beam geometry for a whole log.
//
// Karto describes a laser once (docs/engine.md §2.1): every scan must have the first
// scan's reading count, or Process rejects it, and scans of the same count are read with the
// first scan's angles whatever their own. Real recordings break that: a CARMEN log whose scans
// alternate between 180 and 181 readings with four start angles, cheap lidars whose count
// varies from turn to turn (slam_toolbox#540, "contains 268 range readings, expected 274").
//
// Policy (BeamPolicy):
//   * kResample (default): the reference geometry is the one most scans have (the first seen on
//     a tie); every scan with another geometry is resampled onto it, each reference beam taking
//     the reading of the nearest beam of the scan's own geometry, and +inf (no return) where the
//     scan has no beam within half of its own increment (outside its field of view). Nearest,
//     not interpolated: interpolating across an edge would invent points between two walls.
//     Scans of the reference geometry are untouched, so a log with one geometry is unchanged.
//   * kStrict: nothing is changed; the engine then does what Karto does (drops scans of another
//     reading count, counted in the run's scans_wrong_reading_count).
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

const char* BeamPolicyName(BeamPolicy policy);  // "resample", "strict"
// "resample" / "strict"; InputError naming the option otherwise.
BeamPolicy ParseBeamPolicy(const std::string& text);

// Makes the log's scans share one geometry under `policy` and records what was done in
// log->beams. Idempotent.
void HarmonizeBeams(BeamPolicy policy, LaserLog* log);

// `scan`'s readings on `target` beams as described above; no_returns recounted against the
// scan's max_range. Returns the target beams that no beam of the scan is near (set to +inf).
std::size_t ResampleScan(const BeamGeometry& target, LaserScanRecord* scan);

}  // namespace slamtune::io
