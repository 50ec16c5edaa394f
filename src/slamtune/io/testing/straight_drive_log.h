// Test helper: the laser log of a robot driving straight along x at a steady speed, the clean
// baseline into which the log checks' tests plant their faults.
#pragma once

#include "slamtune/io/laser_log.h"

namespace slamtune::io::testing {

// How much of the drive a StraightDriveLog holds.
struct StraightDrive {
  double start_s = 0.0;      // time of the first ODOM record and of the first scan
  int odometry_records = 0;  // ODOM records, 0.1 s apart
  int scans = 0;             // scans, 0.2 s apart
};

// A robot driving along x at 0.5 m/s from x = 0: ODOM records at 10 Hz with that speed (tv) and
// scans at 5 Hz, posed on the same line; the scans have no beam geometry and no readings.
LaserLog StraightDriveLog(const StraightDrive& drive);

}  // namespace slamtune::io::testing
