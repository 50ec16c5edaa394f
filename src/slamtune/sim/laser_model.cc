#include "slamtune/sim/laser_model.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"

namespace slamtune::sim {

void LaserOptions::Validate() const {
  if (!(fov_deg > 0.0 && fov_deg <= 360.0)) {
    throw InputError(fmt::format("laser fov_deg = {}: must be in (0, 360]", fov_deg));
  }
  if (beams < 2 || beams > 100000) throw InputError(fmt::format("laser beams = {}: must be in [2, 100000]", beams));
  if (!(max_range_m > 0.0 && std::isfinite(max_range_m))) {
    throw InputError(fmt::format("laser max_range_m = {}: must be positive and finite", max_range_m));
  }
  if (!(range_noise_m >= 0.0 && range_noise_m < max_range_m)) {
    throw InputError(
        fmt::format("laser range_noise_m = {}: must be in [0, max_range_m = {})", range_noise_m, max_range_m));
  }
  const double per_metre = 1.0 / range_resolution_m;
  if (!(range_resolution_m > 0.0 && range_resolution_m <= 0.1) || std::fabs(per_metre - std::round(per_metre)) > 1e-6) {
    throw InputError(
        fmt::format("laser range_resolution_m = {}: must be in (0, 0.1] and divide 1 m evenly", range_resolution_m));
  }
}

namespace {
double AsFloat32(double v) { return static_cast<double>(static_cast<float>(v)); }
}  // namespace

double LaserOptions::angle_min() const {
  const double v = -DegToRad(fov_deg) / 2.0;
  return float32_values ? AsFloat32(v) : v;
}
double LaserOptions::angle_increment() const {
  const double v = DegToRad(fov_deg) / (beams - 1);
  return float32_values ? AsFloat32(v) : v;
}
double LaserOptions::max_range() const { return float32_values ? AsFloat32(max_range_m) : max_range_m; }

SimulatedScan SimulateScan(const RayCaster& caster, const Pose2& laser_pose, const LaserOptions& options,
                           Random& random) {
  SimulatedScan scan;
  scan.ranges.resize(options.beams);
  const Eigen::Vector2d origin(laser_pose.x, laser_pose.y);
  // World angle of beam i as Karto evaluates it: (theta + angle_min) + i * increment (§2.1).
  const double first = laser_pose.theta + options.angle_min();
  const double increment = options.angle_increment();
  const double max_range = options.max_range();
  // k / steps (not k * resolution): the nearest double to the decimal k/steps, so a reading
  // printed with enough decimals parses back to exactly this value.
  const double steps = std::round(1.0 / options.range_resolution_m);
  for (int i = 0; i < options.beams; ++i) {
    const auto hit = caster.Cast(origin, first + i * increment, max_range);
    const double noise = random.Gaussian(options.range_noise_m);  // drawn for every beam: fixed stream
    double reading = max_range;
    if (hit) {
      const double quantised = std::round((*hit + noise) * steps) / steps;
      reading = std::clamp(quantised, 0.0, max_range);
      if (options.float32_values) reading = AsFloat32(reading);
    }
    if (reading >= max_range) {
      reading = max_range;
      ++scan.no_returns;
    }
    scan.ranges[i] = reading;
  }
  return scan;
}

}  // namespace slamtune::sim
