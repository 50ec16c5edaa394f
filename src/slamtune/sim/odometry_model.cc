#include "slamtune/sim/odometry_model.h"

#include <fmt/format.h>

#include <cmath>

#include "slamtune/common/error.h"

namespace slamtune::sim {
namespace {

void RequireNonNegative(const char* field, double value) {
  if (!(value >= 0.0 && std::isfinite(value))) {
    throw InputError(fmt::format("odometry {} = {}: must be finite and >= 0", field, value));
  }
}

void RequireBelow(const char* field, double value, double bound) {
  if (!(std::fabs(value) < bound))
    throw InputError(fmt::format("odometry {} = {}: must be in (-{}, {})", field, value, bound, bound));
}

}  // namespace

void OdometryNoiseOptions::Validate() const {
  RequireNonNegative("translation_noise", translation_noise);
  RequireNonNegative("rotation_noise_per_m", rotation_noise_per_m);
  RequireNonNegative("rotation_noise_per_rad", rotation_noise_per_rad);
  RequireBelow("translation_scale_bias", translation_scale_bias, 0.5);
  RequireBelow("rotation_scale_bias", rotation_scale_bias, 0.5);
  if (!(std::fabs(heading_drift_per_m) <= 0.1)) {
    throw InputError(fmt::format("odometry heading_drift_per_m = {}: must be in [-0.1, 0.1]", heading_drift_per_m));
  }
  for (std::size_t i = 0; i < faults.size(); ++i) faults[i].Validate(fmt::format("odometry faults[{}]", i));
}

OdometryModel::OdometryModel(const Pose2& start, const OdometryNoiseOptions& options, uint64_t seed)
    : options_(options), random_(seed), pose_(start) {}

const Pose2& OdometryModel::Advance(const Pose2& true_delta) {
  const double distance = std::hypot(true_delta.x, true_delta.y);
  const double direction = distance > 0.0 ? std::atan2(true_delta.y, true_delta.x) : 0.0;
  const double rotation = true_delta.theta;
  const double distance_noise = random_.Gaussian(options_.translation_noise * std::sqrt(distance));
  const double rotation_sigma =
      std::sqrt(options_.rotation_noise_per_m * options_.rotation_noise_per_m * distance +
                options_.rotation_noise_per_rad * options_.rotation_noise_per_rad * std::fabs(rotation));
  const double rotation_noise = random_.Gaussian(rotation_sigma);
  double reported_distance = distance * (1.0 + options_.translation_scale_bias) + distance_noise;
  double reported_rotation =
      rotation * (1.0 + options_.rotation_scale_bias) + options_.heading_drift_per_m * distance + rotation_noise;
  const FaultEffect fault = FaultEffectOnStep(options_.faults, travelled_m_, distance);
  if (fault.active) {
    reported_distance += fault.extra_distance;
    reported_rotation += fault.extra_rotation;
  }
  travelled_m_ += distance;
  pose_ = Compose(pose_, Pose2{reported_distance * std::cos(direction), reported_distance * std::sin(direction),
                               NormalizeAngle(reported_rotation)});
  return pose_;
}

}  // namespace slamtune::sim
