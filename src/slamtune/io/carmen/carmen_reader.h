// Reader of CARMEN log files (the format of the Freiburg SLAM benchmark, Kümmerle et al.
// 2009; message layouts as in the CARMEN logger's header comments, see
// /work/shared/datasets/MANIFEST.md) into an io::LaserLog.
//
// Input: plain text or gzip, detected by content (magic 1f 8b), never by file name. One record
// per line: `NAME fields... ipc_timestamp ipc_hostname logger_timestamp`.
//
//   FLASER n r1..rn x y theta odom_x odom_y odom_theta ipc host logger
//       x y theta is the laser pose, odom_* the robot pose. No angle fields, so the beam
//       geometry follows the CARMEN convention of a 180° field of view starting at -90°:
//         * n even: increment = 180°/n   (180 -> 1° steps, -90..+89°; 360 -> 0.5°, -90..+89.5°)
//         * n odd:  increment = 180°/(n-1) (181 -> 1°, -90..+90°; 361 -> 0.5°, -90..+90°)
//         * n = 1:  a single beam at -90°, increment 0.
//   ROBOTLASER1 laser_type start_angle fov angular_res max_range accuracy remission_mode
//       n r1..rn m rem1..remm laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv
//       forward_safety_dist side_safety_dist turn_axis ipc host logger
//       Beam i at start_angle + i * angular_res; per-scan max_range from the record.
//       Angles are radians: a start_angle or fov beyond a full turn, beams spanning more, or a
//       fov that contradicts n readings at angular_res (it must be (n - 1) or n steps, within
//       beam_geometry.h's tolerance) is a malformed record, e.g. degrees written as radians.
//   RAWLASER1..4 as ROBOTLASER1 up to the remissions, then ipc host logger: no pose. The robot
//       pose is interpolated linearly in ipc time between the ODOM records that bracket the
//       scan (heading along the shorter arc). Scans before the first or after the last ODOM
//       have no pose: they are left out and counted (LaserLog::scans_without_odometry, printed
//       with the log's input description), never clamped; laser pose = robot (+) offset, the offset taken from the
//       PARAMs robot_<L>_offset, robot_<L>_side_offset, robot_<L>_angular_offset (m, m, rad; zero when absent) with L =
//       frontlaser, rearlaser, laser3, laser4 for RAWLASER1..4. A log with RAWLASER scans and no ODOM record is an
//       error.
//   ODOM x y theta tv rv accel ipc host logger
//   PARAM name value host time   (value may hold spaces; stored in LaserLog::params, last wins)
//   `#` comment lines and empty lines. Any other record name (RLASER, TRUEPOS, SYNC, NMEA-GGA,
//   ROBOTLASER0/2, ...) is skipped and counted in unknown_records and record_counts.
//
// Scans stay in file order (intel's FLASER times step backwards 631 times; they are counted in
// time_backward_steps, not sorted away). Readings are kept exactly as recorded.
//
// No-return value of the log (LaserLog::no_return_value / no_return_rule), first that applies:
//   1. LogReadOptions::no_return_value > 0 ("--no-return"); it then also replaces the per-scan
//      max_range of every scan;
//   2. a PARAM naming the front laser's maximum range ("PARAM <name>"): a name ending in
//      `laser_max_range` (e.g. laser_front_laser_max_range, laser_max_range) or equal to
//      `robot_front_laser_max`, and not containing `rear`; its value must be a positive number;
//   3. the largest max_range field of the ROBOTLASER1/RAWLASER records ("<RECORD> max_range");
//   4. for FLASER logs, the largest finite reading M of the log if at least 0.05 % of all FLASER
//      readings lie within 1 % below it, in [0.99 M, M] ("maximum reading cluster"): the value a
//      driver writes for "no echo" (aces 50.00, intel 81.83, mit-csail 81.91, mit-killian 51.22).
//      The band tolerates logs whose max-range readings jitter: mit-killian has a single 51.22
//      and about 40 000 readings between 51.05 and 51.12, which, being below M, are *not*
//      counted as no-returns; use --no-return 51.0 to count them;
//   5. otherwise +inf ("none").
// FLASER scans take the log's value as max_range; ROBOTLASER1/RAWLASER keep their own. A reading
// is a no-return when it is >= the scan's max_range, NaN, +-inf or negative; no-returns are
// counted per scan and per log, never rejected.
//
// Errors: a malformed record (wrong reading count, non-number, missing or extra fields,
// truncated last line, NaN/inf in a pose or time field) throws InputError "FILE:LINE: what",
// e.g. "intel.clf:812: FLASER declares 180 readings but has 179 numbers before the pose".
// With LogReadOptions::lenient such records are skipped and counted (skipped_records, the first
// reasons in skipped_reasons). Always fatal: unreadable path, truncated or corrupt gzip data,
// an empty file, a file without laser scans, RAWLASER scans without ODOM or none within its span.
// A UTF-8 byte-order mark at the start of the file is ignored (line_reader.h).
#pragma once

#include <istream>
#include <string>

#include "slamtune/io/laser_log.h"

namespace slamtune::io {

// Reads the log at `path` (plain or gzip).
LaserLog ReadCarmenLog(const std::string& path, const LogReadOptions& options = {});

// Reads a log from `in` (plain or gzip); `name` stands for the file name in messages and
// LaserLog::path.
LaserLog ReadCarmenLog(std::istream& in, const std::string& name, const LogReadOptions& options = {});

}  // namespace slamtune::io
