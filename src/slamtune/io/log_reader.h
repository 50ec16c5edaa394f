// The one way commands read a laser log: a CARMEN log (carmen_reader.h) or a ROS recording —
// MCAP, rosbag2 SQLite3, a rosbag2 bag folder, a ROS 1 bag (ros/recording_log.h) — told apart by
// content (DetectRecordingKind), then given one beam geometry (beam_geometry.h, policy
// LogReadOptions::beams). Every command that takes a log takes any of these.
#pragma once

#include <string>

#include "slamtune/io/laser_log.h"

namespace slamtune::io {

LaserLog ReadLaserLog(const std::string& path, const LogReadOptions& options = {});

// InputError "FILE: not one of the N readings of the M scans is a range ..." when no reading of
// `log` is a range (CountRanges): a map made from it would be empty. What `run`, `optimize` and
// `sweep` ask of their log; `check` reports it (no_valid_reading).
void RequireRanges(const LaserLog& log);

}  // namespace slamtune::io
