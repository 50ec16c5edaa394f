// The one way commands read a laser log: a CARMEN log (carmen_reader.h) or a ROS recording —
// MCAP, rosbag2 SQLite3, a rosbag2 bag folder, a ROS 1 bag (recording_log.h) — told apart by
// content (DetectRecordingKind), then given one beam geometry (beam_geometry.h, policy
// LogReadOptions::beams). Every command that takes a log takes any of these.
#pragma once

#include <string>

#include "slamtune/io/laser_log.h"

namespace slamtune::io {

LaserLog ReadLaserLog(const std::string& path, const LogReadOptions& options = {});

}  // namespace slamtune::io
