// The odometry checks of `slamtune check` (log_check.h): jumps, stalls, heading wraps away from
// +-pi and poses that disagree with the velocities recorded beside them, on the log's ODOM /
// Odometry records or, without them, on the scans' robot poses. Each problem lists the scans at or
// just before the odometry samples concerned.
#pragma once

#include "slamtune/io/check/log_check.h"
#include "slamtune/io/laser_log.h"

namespace slamtune::io {

// Adds the odometry's fact line ("odometry: N SOURCE, median period ...", and the headings not
// wrapped into [-pi, pi] when there are any) and its problems to `report`. Fewer than two
// odometric poses: nothing.
void CheckOdometry(const LaserLog& log, const CheckOptions& options, CheckReport* report);

}  // namespace slamtune::io
