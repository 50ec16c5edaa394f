// What kind of recording a path holds, judged by content (DetectRecordingKind,
// recording_container.h), and the reading of one recording file of any kind: MCAP, rosbag2
// SQLite3 or ROS 1 bag, or such a file compressed whole with zstd (rosbag2 compression_mode
// "file", docs/recordings.md §1.1: `*.mcap.zstd`, `*.db3.zstd`), decompressed into memory and
// then judged by its own magic. ReadRosRecording (recording_container.h) dispatches on the
// kind; a rosbag2 bag folder is read by rosbag2_folder.h.
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "slamtune/io/ros/container_sink.h"
#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

// The kind of a file whose first bytes are `head` (16 are enough): kMcap, kRosbag2Sqlite,
// kRosbag1, kZstdFile or, for anything else, kCarmenLog.
RecordingKind RecordingKindOfBytes(std::span<const std::uint8_t> head);

// Reads the single recording file `path` into `sink`, setting the summary's format (and
// file_compression "zstd" for a zstd-compressed file). InputError for a CARMEN log, a folder,
// or a zstd-compressed file that holds none of the three formats.
void ReadRecordingFileInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink);

}  // namespace slamtune::io
