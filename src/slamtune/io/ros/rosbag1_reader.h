// ROS 1 bag format 2.0 (wiki.ros.org/Bags/Format/2.0; docs/recordings.md §1.6), read linearly:
// the line "#ROSBAG V2.0\n", then records, each header_len:u32, header (fields field_len:u32 +
// "name=value", the value binary), data_len:u32, data. Every header has `op`:
//   0x03 bag header (index_pos, conn_count, chunk_count; must come first; index_pos 0 = the bag
//        was never closed), 0x05 chunk (compression none / bz2 / lz4 = LZ4 frame format, size =
//        uncompressed size; its data holds Connection and Message data records), 0x07 connection
//        (conn, topic; its data a second header with type, md5sum, message_definition, optional
//        callerid and latching), 0x02 message data (conn, time = u32 sec + u32 nsec), 0x04 index
//        data and 0x06 chunk info (skipped_records).
// Connections are remembered by id wherever they appear (inside chunks, and again in the index
// section after them; a repeated id is ignored). No index is needed: a bag whose recording was
// cut off reads up to its last complete record (ContainerSummary::complete false). A chunk is
// read whole before any of its messages is delivered. Messages are MessageSerialization::kRos1,
// the type as written (e.g. sensor_msgs/LaserScan), latched when `latching=1`.
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

// True when `bytes` start with "#ROSBAG V2.0\n".
bool HasRosbag1Magic(std::span<const std::uint8_t> bytes);

// Reads the ROS 1 bag `bytes` (named `name` in messages and locations) into `sink`.
void ReadRosbag1Into(std::span<const std::uint8_t> bytes, const std::string& name, const ContainerReadOptions& options,
                     ContainerSink* sink);

}  // namespace slamtune::io
