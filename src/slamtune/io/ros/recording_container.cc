#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

const char* ContainerFormatName(ContainerFormat format) {
  switch (format) {
    case ContainerFormat::kMcap: return "MCAP";
    case ContainerFormat::kRosbag2Sqlite: return "rosbag2 SQLite3";
    case ContainerFormat::kRosbag1: return "ROS 1 bag v2.0";
  }
  return "?";
}

const char* RecordingKindName(RecordingKind kind) {
  switch (kind) {
    case RecordingKind::kCarmenLog: return "CARMEN log";
    case RecordingKind::kMcap: return "MCAP";
    case RecordingKind::kRosbag2Sqlite: return "rosbag2 SQLite3";
    case RecordingKind::kRosbag1: return "ROS 1 bag v2.0";
    case RecordingKind::kRosbag2Folder: return "rosbag2 bag folder";
    case RecordingKind::kZstdFile: return "zstd-compressed rosbag2 file";
  }
  return "?";
}

std::string MessageLocation::ToString() const {
  return (kind == Kind::kRow ? "row " : "byte ") + std::to_string(value);
}

}  // namespace slamtune::io
