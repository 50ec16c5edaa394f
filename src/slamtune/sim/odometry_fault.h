// Planted odometry failures: stretches of the route where the wheel odometry reports a motion
// that did not happen, the way real logs break Karto's front end (sequential scan matching,
// before any loop closure). Each fault acts on a stretch of the route given by true distance
// travelled, spread evenly over it, on top of the ordinary noise (odometry_model.h):
//
//   spin     the odometry reports `magnitude` rad of extra rotation (positive = left) over the
//            stretch: a wheel slipping while the robot drives on;
//   jump     the odometry reports `magnitude` m of extra forward travel over the stretch: a
//            translation jump when the stretch is short, a strong scale error (magnitude /
//            length) when it is long;
//   reverse  the travel over the stretch is reported with its sign flipped (forward logged as
//            backward), an encoder sign error; takes no magnitude.
//
// Whether Karto's front end absorbs a fault depends on how much of it falls between two
// accepted scans (minimum_travel_distance) against the sequential matcher's window
// (correlation_search_space_dimension, coarse_search_angle_offset).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slamtune::sim {

enum class OdometryFaultKind { kSpin, kJump, kReverse };

// "spin", "jump", "reverse".
std::string_view OdometryFaultKindName(OdometryFaultKind kind);
std::optional<OdometryFaultKind> ParseOdometryFaultKind(std::string_view name);

struct OdometryFault {
  OdometryFaultKind kind = OdometryFaultKind::kSpin;
  double start_m = 0.0;    // m: true distance travelled from the route's start where the fault begins, >= 0
  double length_m = 0.1;   // m: true distance over which it acts, > 0
  double magnitude = 0.0;  // spin: rad, |.| <= 2 pi; jump: m, |.| <= 10; reverse: must be 0

  // Throws InputError naming `field` (e.g. "odometry faults[0]"), the field, its value and the rule.
  void Validate(const std::string& field) const;
  // "spin at 40 m over 0.1 m: 30 deg", for logs and reports.
  std::string Describe() const;
};

// What the faults add to one odometry step.
struct FaultEffect {
  bool active = false;          // some fault overlaps the step
  double extra_distance = 0.0;  // m, added to the reported travel
  double extra_rotation = 0.0;  // rad, added to the reported rotation
};

// The effect of `faults` on a step that covers the true travelled distances
// [from_m, from_m + distance_m]: each fault contributes in proportion to its overlap with the step.
FaultEffect FaultEffectOnStep(const std::vector<OdometryFault>& faults, double from_m, double distance_m);

// Reads "KIND,START_M,LENGTH_M[,MAGNITUDE]" (MAGNITUDE in degrees for spin, metres for jump;
// none for reverse), as `slamtune simulate --fault` takes it. InputError naming `text` otherwise.
OdometryFault ParseOdometryFault(const std::string& text);

}  // namespace slamtune::sim
