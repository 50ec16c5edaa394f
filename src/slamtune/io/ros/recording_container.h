// The container level of a ROS recording: which topics it holds and their time-stamped,
// still serialized messages, whatever the file format. Three formats, read without any ROS
// installation:
//   * MCAP (mcap.dev/spec, ros2 profile): read linearly record by record, chunks uncompressed,
//     zstd or lz4 (LZ4 frame format), so that a file without summary, index or footer (a
//     recording cut off by a crash) still reads;
//   * rosbag2 SQLite3 (`.db3`), schema variants from Eloquent/Foxy/Humble to Jazzy (only the
//     columns every variant has are selected);
//   * ROS 1 bag format 2.0 (wiki.ros.org/Bags/Format/2.0), chunks none, bz2 or lz4 (roslz4 =
//     LZ4 frame format), read linearly, so that a bag without index reads.
// plus a rosbag2 bag folder (metadata.yaml and its split files, in order; file-level zstd
// compression `*.mcap.zstd` / `*.db3.zstd` and message-level zstd compression as
// metadata.yaml's compression_mode / compression_format say).
//
// Messages are handed to a callback one at a time in file order (rosbag2 SQLite3: ORDER BY
// timestamp, id), so a recording of any size is read in one pass without holding it whole. The
// readers are reached through ros_recording.h: ReadRosRecording judges the format by content,
// ReadContainerFile and ReadContainerBytes are told it.
//
// Errors: malformed data (bad CRC, unknown compression, a message on an undeclared channel /
// connection, a Channel whose schema is missing, an unreadable or corrupt database) throw
// InputError "FILE: WHERE: what (--lenient reads the recording up to this record)", WHERE naming
// the byte offset (or the database row), e.g. "drive.mcap: byte 18213 (chunk): zstd: Data
// corruption detected". A file that ends inside a record (cut off by a crash or a power loss: the
// record's length runs past the end) is read up to its last whole record, lenient or not; with
// ContainerReadOptions::lenient a corrupt record ends the read there too. Either way everything
// before it is delivered and the summary says what was not read (ContainerSummary::
// data_end). Never a crash, whatever the bytes.
//
// The readers of ROS recordings sit in io/ros/, this file at their base: they are part of the io
// library and, like the rest of it, of namespace slamtune::io.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "slamtune/io/data_end.h"

namespace slamtune::io {

// Named by ContainerFormatName (ros_recording.h).
enum class ContainerFormat { kMcap, kRosbag2Sqlite, kRosbag1 };

// How message payloads are serialized: ROS 2 CDR (XCDR1, with its 4-byte encapsulation
// header) or ROS 1 serialization.
enum class MessageSerialization { kCdr, kRos1 };

struct RecordedTopic {
  std::string name;  // e.g. "/scan"
  std::string type;  // as written: "sensor_msgs/msg/LaserScan" (ROS 2) or "sensor_msgs/LaserScan" (ROS 1)
  MessageSerialization serialization = MessageSerialization::kCdr;
  // Latched / transient_local (ROS 1 `latching=1`; ROS 2 offered QoS durability transient_local,
  // given as 1 or "transient_local" in offered_qos_profiles). E.g. /tf_static.
  bool latched = false;
  std::size_t messages = 0;  // messages delivered on this topic
};

// Where a message is in its file, for messages: a byte offset (MCAP: of the Message record,
// or of its Chunk record for chunked messages; ROS 1: of the Message data record or of its
// Chunk) or a database row id (rosbag2 SQLite3).
struct MessageLocation {
  enum class Kind { kByte, kRow } kind = Kind::kByte;
  std::uint64_t value = 0;
  std::string file;  // the file it is in (one of a bag folder's split files)
  // "byte 18213" / "row 17".
  std::string ToString() const;
};

struct RecordedMessage {
  std::size_t topic = 0;               // index into ContainerSummary::topics (also passed to the callback)
  std::int64_t log_time_ns = 0;        // receive time: MCAP log_time, rosbag2 timestamp, ROS 1 `time`
  std::span<const std::uint8_t> data;  // serialized payload, valid only during the callback
  MessageLocation location;
};

struct ContainerSummary {
  ContainerFormat format = ContainerFormat::kMcap;
  std::vector<std::string> files;                        // files read, in order (one, or a bag folder's splits)
  std::vector<RecordedTopic> topics;                     // in order of first appearance
  std::size_t messages = 0;                              // messages delivered
  std::size_t chunks = 0;                                // chunk records read (MCAP, ROS 1)
  std::map<std::string, std::size_t> chunk_compression;  // "none", "zstd", "lz4", "bz2" -> chunks
  std::string message_compression;                       // rosbag2 per-message compression ("" or "zstd")
  std::string file_compression;                          // rosbag2 per-file compression ("" or "zstd")
  std::size_t skipped_records = 0;                       // records a linear reader skips (indexes, attachments, ...)
  std::size_t unknown_records = 0;                       // records of unknown opcode / op, skipped
  DataEnd data_end;                                      // how the data ended, and the tail not read
  std::string profile;                                   // MCAP header profile ("ros2"), ROS 1: "ros1"
  std::string ros_distro;                                // when the file says (MCAP metadata, db3 schema table)
};

struct ContainerReadOptions {
  bool lenient = false;    // a corrupt record ends the read (counted) instead of failing
  bool verify_crc = true;  // check MCAP chunk CRCs that are non-zero
};

using MessageCallback = std::function<void(const RecordedTopic& topic, const RecordedMessage& message)>;

}  // namespace slamtune::io
