// How a recording's data ended (MCAP, rosbag2, ROS 1 bag): whether the format's end marker was
// found and, when a tail was cut off inside a record (or corrupt, --lenient), how much was not
// read and why. The container reader fills it (io/ros/recording_container.h); the log carries it
// (RecordingInfo in laser_log.h) to the log summary, the log check and the scan losses.
#pragma once

#include <cstdint>
#include <string>

namespace slamtune::io {

struct DataEnd {
  bool complete = true;  // the format's end marker was found
  // In words: "data end record and footer", "no data end record: the file ends after a complete
  // record (recording cut off?)", "index", "cut off inside a record: ...", ...
  std::string how;
  std::uint64_t dropped_bytes = 0;  // from the record cut off (or corrupt, --lenient) on, not read
  std::string dropped_reason;       // what was wrong there
};

}  // namespace slamtune::io
