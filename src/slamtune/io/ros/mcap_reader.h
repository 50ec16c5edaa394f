// MCAP (mcap.dev/spec, ros2 profile), read linearly: the magic, the Header record, then record
// after record (opcode:u8, content_length:u64, content) through the data section to DataEnd,
// then the summary section (skipped) to the Footer and the closing magic (spec "File Structure").
// No index, summary or footer is needed, so a recording cut off by a crash reads up to its last
// complete record (ContainerSummary::complete false).
//
// Records (spec "Records"): Schema and Channel are remembered by id for the rest of the file,
// wherever they appear (a chunk's Schema and Channel serve later chunks too; a repeated id is
// ignored); Message records are delivered, top-level or inside a Chunk; a Chunk is decompressed
// ("", "zstd", "lz4" = LZ4 frame format), its uncompressed_crc checked when non-zero, and its
// records walked. A chunk is read whole before any of its messages is delivered, so a corrupt
// chunk under lenient reading drops all of it. MessageIndex, ChunkIndex, Attachment,
// AttachmentIndex, Statistics, Metadata, MetadataIndex and SummaryOffset are skipped (the
// Metadata record "rosbag2" gives ROS_DISTRO), as are the user opcodes 0x80-0xFF
// (skipped_records); other opcodes count as unknown_records.
//
// Channels: message_encoding "cdr" is MessageSerialization::kCdr and "ros1" kRos1, the type is
// the schema name (e.g. sensor_msgs/msg/LaserScan); latched from metadata offered_qos_profiles
// (durability transient_local) or "latching" = "1" (ros1 profile). Any other message encoding
// (json, protobuf, ...) still lists the topic and delivers its messages, but with the type
// written "SCHEMA (ENCODING encoding)", so that no decoder of a ROS type takes them for CDR.
//
// Errors (recording_container.h): "FILE: byte N (WHAT): ...", N the record's offset; inside a
// chunk "FILE: byte N (chunk), uncompressed byte M (WHAT): ...".
#pragma once

#include <cstdint>
#include <span>
#include <string>

#include "slamtune/io/ros/container_sink.h"
#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

// True when `bytes` start with the MCAP magic "\x89MCAP0\r\n".
bool HasMcapMagic(std::span<const std::uint8_t> bytes);

// Reads the MCAP file `bytes` (named `name` in messages and locations) into `sink`.
void ReadMcapInto(std::span<const std::uint8_t> bytes, const std::string& name, const ContainerReadOptions& options,
                  ContainerSink* sink);

}  // namespace slamtune::io
