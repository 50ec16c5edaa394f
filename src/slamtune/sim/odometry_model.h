// Wheel odometry with random and systematic errors, integrated step by step.
//
// Each step's true motion (the robot-frame increment between two poses on the route) is
// reported as a travelled distance along the true chord direction and a rotation:
//   distance' = distance (1 + translation_scale_bias) + N(0, translation_noise^2 distance)
//   rotation' = rotation (1 + rotation_scale_bias) + heading_drift_per_m distance
//               + N(0, rotation_noise_per_m^2 distance + rotation_noise_per_rad^2 |rotation|)
// and composed onto the odometric pose. Variances grow linearly with distance and angle (a
// random walk), so the accumulated noise does not depend on the step length; the systematic
// terms (miscalibrated wheel base and wheel diameters, Borenstein & Feng 1996, "Measurement
// and correction of systematic odometry errors in mobile robots", IEEE T-RA 12(6)) make the
// heading drift steadily, so revisited walls appear doubled until a loop is closed. Planted
// faults (odometry_fault.h) add their share of the step to distance' and rotation'; they draw
// no random numbers, and without faults the odometry is bit for bit what it is without them.
#pragma once

#include <cstdint>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/sim/odometry_fault.h"
#include "slamtune/sim/random.h"

namespace slamtune::sim {

struct OdometryNoiseOptions {
  double translation_noise = 0.02;       // m/sqrt(m): std of the distance error over 1 m, >= 0
  double rotation_noise_per_m = 0.005;   // rad/sqrt(m): heading noise per metre driven, >= 0
  double rotation_noise_per_rad = 0.03;  // rad/sqrt(rad): heading noise per radian turned, >= 0
  double translation_scale_bias = 0.0;   // fraction: reported distance = (1 + b) x true, in (-0.5, 0.5)
  double rotation_scale_bias = 0.01;     // fraction: reported rotation = (1 + b) x true, in (-0.5, 0.5)
  double heading_drift_per_m = 0.001;    // rad/m: systematic heading drift per metre driven, |.| <= 0.1
  std::vector<OdometryFault> faults;     // planted failures located by true distance travelled; none by default

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

class OdometryModel {
 public:
  // Odometry starts at `start` (the odometry frame coincides with the world frame at the start).
  OdometryModel(const Pose2& start, const OdometryNoiseOptions& options, uint64_t seed);

  // Reports the true robot-frame motion `true_delta` with noise and returns the new odometric pose.
  // Draws exactly two Gaussians per call, faults or not.
  const Pose2& Advance(const Pose2& true_delta);

  const Pose2& pose() const { return pose_; }
  // True distance travelled so far (m): the sum of the steps' chord lengths; faults are located by it.
  double travelled_m() const { return travelled_m_; }

 private:
  OdometryNoiseOptions options_;
  Random random_;
  Pose2 pose_;
  double travelled_m_ = 0.0;
};

}  // namespace slamtune::sim
