// Writes a LaserLog (laser_log.h) as a CARMEN text log that ReadCarmenLog (carmen_reader.h)
// reads back: the standard header comment, PARAM lines, then ODOM and laser lines merged in
// time order (ODOM first at equal times; each list keeps its own order).
//
//   PARAM name value hostname 0            (as in the Freiburg datasets' logs)
//   ODOM x y theta tv rv accel ipc_timestamp hostname logger_timestamp
//   FLASER n r_1 .. r_n x y theta odom_x odom_y odom_theta ipc_timestamp hostname logger_timestamp
//   ROBOTLASER1 0 start_angle fov angular_res max_range 0 0 n r_1 .. r_n 0 laser_x laser_y
//       laser_theta robot_x robot_y robot_theta 0 0 0 0 0 ipc_timestamp hostname logger_timestamp
//
// Scans of kind kFlaser become FLASER lines (first pose = laser pose, second = robot pose).
// FLASER has no angle fields: readers infer the beams from n (FlaserBeamGeometry), so such a
// scan must have exactly that geometry, or the writer refuses it. Scans of the other kinds
// become ROBOTLASER1 lines, which carry their geometry and max range (tv, rv, safety distances
// and remissions are not in the model and are written as 0). Precision: ranges with 3 decimals
// (1 mm), poses and timestamps with 6 by default, beam angles exactly (shortest round trip):
// the simulator's millimetre readings and microsecond timestamps read back unchanged.
#pragma once

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"

namespace slamtune::io {

struct CarmenWriteOptions {
  std::vector<std::string> comments;  // extra header lines, each written as "# <text>"
  std::string hostname = "slamtune";  // ipc_hostname column; non-empty, no whitespace
  int range_decimals = 3;             // digits after the point for ranges, in [0, 9]
  // Ranges as the shortest text that reads back to the same double (range_decimals unused):
  // for readings that are not whole millimetres, e.g. float32 values as a ROS LaserScan holds.
  bool exact_ranges = false;
  int pose_decimals = 6;  // for x, y, theta, tv, rv, accel, in [0, 12]
  int time_decimals = 6;  // for timestamps, in [0, 9]

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

struct CarmenWriteSummary {
  std::size_t lines = 0;
  std::size_t comments = 0;
  std::size_t params = 0;
  std::size_t odometry = 0;
  std::size_t scans = 0;        // laser lines, FLASER and ROBOTLASER1
  std::size_t robotlaser1 = 0;  // of which ROBOTLASER1
};

// Writes `log` to `out`. Throws InputError (before writing anything) when a value cannot be
// written as CARMEN text: a non-finite reading, pose or timestamp, a FLASER scan whose beam
// geometry is not the FLASER convention, a ROBOTLASER1 scan with a non-finite max range, or a
// PARAM name or value that is empty or contains whitespace.
CarmenWriteSummary WriteCarmenLog(std::ostream& out, const LaserLog& log, const CarmenWriteOptions& options = {});

// Makes a log read from any recording writable as CARMEN, as `slamtune convert` and `slamtune
// fault` write it: scans become ROBOTLASER1 (FLASER scans stay FLASER when `keep_flaser`), a scan
// without a finite max range takes its largest finite reading + 1 m (at least 1 m), non-finite
// readings become the scan's max range (the CARMEN convention for a no-return), and the PARAMs
// robot_frontlaser_offset, _side_offset, _angular_offset and laser_front_laser_max_range are set
// from the first scan, so the log reads back with the same laser offset and no-return value.
// Returns how many readings were replaced.
std::size_t PrepareForCarmen(LaserLog* log, bool keep_flaser = false);

// Writes `log` to the file `path` (replaced if it exists) whole or not at all, through
// PATH.partial (common/atomic_file.h). Throws InputError as above, or "PATH: cannot write ..."
// when the file cannot be written.
CarmenWriteSummary WriteCarmenLog(const std::string& path, const LaserLog& log, const CarmenWriteOptions& options = {});

}  // namespace slamtune::io
