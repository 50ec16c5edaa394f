// Any ROS recording, read without knowing its format in advance: what a path holds is judged by
// content (DetectRecordingKind), then read by the reader of its format (ReadRosRecording). Both go
// through one table of recording formats (ros_recording.cc), a row per RecordingKind: its name,
// how it is recognised (a folder holding a given file, or the magic bytes a file starts with) and
// how it is read, so that a new container format is its reader (like mcap_reader.h) and one row.
//
// The kinds: MCAP, rosbag2 SQLite3 and ROS 1 bag files; such a file compressed whole with zstd
// (rosbag2 compression_mode "file", docs/recordings.md §1.1: `*.mcap.zstd`, `*.db3.zstd`),
// decompressed into memory and then judged by its own magic; a rosbag2 bag folder, whose split
// files (rosbag2_folder.h) are judged and read one after the other into one ContainerSummary;
// and, for anything else, a CARMEN log, which is read elsewhere (carmen_reader.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

// What a path holds, judged by content (magic bytes), never by its name: a folder with
// metadata.yaml is a rosbag2 bag folder; a file starting with "\x89MCAP0\r\n" is MCAP, with
// "SQLite format 3\0" rosbag2 SQLite3, with "#ROSBAG V2.0\n" a ROS 1 bag, with a zstd frame
// magic a file-compressed rosbag2 split (its inner format judged after decompression);
// anything else is a CARMEN log (text or gzip).
enum class RecordingKind { kCarmenLog, kMcap, kRosbag2Sqlite, kRosbag1, kRosbag2Folder, kZstdFile };
// "CARMEN log", "MCAP", "rosbag2 SQLite3", "ROS 1 bag v2.0", "rosbag2 bag folder",
// "zstd-compressed rosbag2 file".
const char* RecordingKindName(RecordingKind kind);
// The name of the container format's kind: "MCAP", "rosbag2 SQLite3", "ROS 1 bag v2.0".
const char* ContainerFormatName(ContainerFormat format);

// Throws InputError "PATH: cannot open (reason)" for a missing or unreadable path, and
// "PATH: a folder but not a rosbag2 bag (no metadata.yaml)".
RecordingKind DetectRecordingKind(const std::string& path);

// Any ROS recording (kind other than kCarmenLog): a single file of any of the three formats
// (zstd-compressed or not), or a rosbag2 bag folder. Reads it whole and calls `on_message` for
// every message in file order (recording_container.h). InputError for a CARMEN log path.
ContainerSummary ReadRosRecording(const std::string& path, const ContainerReadOptions& options,
                                  const MessageCallback& on_message);

// One container format, told rather than judged: the file `path`, or a file's bytes in memory
// named `name` in messages and locations. Otherwise as ReadRosRecording.
ContainerSummary ReadContainerFile(ContainerFormat format, const std::string& path, const ContainerReadOptions& options,
                                   const MessageCallback& on_message);
ContainerSummary ReadContainerBytes(ContainerFormat format, std::vector<std::uint8_t> bytes, const std::string& name,
                                    const ContainerReadOptions& options, const MessageCallback& on_message);

}  // namespace slamtune::io
