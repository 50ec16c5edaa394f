// Simulated 2D laser range finder (a SICK LMS-like scanner by default).
//
// Beam i of n points at angle_min + i * increment in the laser frame, with the field of view
// centred on the laser's heading: angle_min = -fov/2, increment = fov/(n-1), so the defaults
// (180 deg, 181 beams) give beams at -90, -89, ..., +90 deg, 1 deg apart. Each reading is the
// exact distance to the nearest wall plus Gaussian noise, quantised to the range resolution.
// A beam that hits nothing within max range, or whose noisy reading reaches it, reads exactly
// max_range: the "no return" convention of CARMEN logs (docs/engine.md §2.2, §10 item 1).
#pragma once

#include <cstddef>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/sim/random.h"
#include "slamtune/sim/ray_caster.h"

namespace slamtune::sim {

struct LaserOptions {
  double fov_deg = 180.0;             // field of view (deg), in (0, 360]
  int beams = 181;                    // readings per scan, >= 2
  double max_range_m = 30.0;          // no-return value and farthest wall seen (m), > 0
  double range_noise_m = 0.01;        // standard deviation of the range noise (m), >= 0
  double range_resolution_m = 0.001;  // readings are multiples of this (m), in (0, 0.1], 1/res
                                      // whole; 1 mm keeps the written log (3 decimals) exact
  // Beam angles, max range and readings as float32 values (widened to double), as a ROS
  // sensor_msgs/LaserScan carries them, so a bag made from the log holds the same numbers.
  bool float32_values = false;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;

  double angle_min() const;        // rad, -fov/2
  double angle_increment() const;  // rad, fov/(beams-1)
  double max_range() const;        // m, max_range_m (as float32 when float32_values)
};

struct SimulatedScan {
  std::vector<double> ranges;  // m, beams values
  std::size_t no_returns = 0;  // readings equal to max_range_m
};

// One scan from `laser_pose` (world frame). Draws one Gaussian per beam from `random`.
SimulatedScan SimulateScan(const RayCaster& caster, const Pose2& laser_pose, const LaserOptions& options,
                           Random& random);

}  // namespace slamtune::sim
