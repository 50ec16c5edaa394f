// A bounds-checked cursor over one serialized ROS message payload, in either serialization a
// recording may hold (CDR: XCDR1 of the OMG DDS-XTypes spec as ROS 2 rmw writes it; ROS 1:
// wiki.ros.org/roscpp/Overview/MessagesSerializationAndAdaptingTypes). The
// decoders of ros_messages.h read their fields with it, in declaration order.
//
//   * ROS 2 CDR (XCDR1, "plain CDR"): the payload starts with a 4-byte encapsulation header,
//     bytes 0-1 the representation kind (00 01 = CDR_LE, 00 00 = CDR_BE), bytes 2-3 options
//     (ignored). Every other kind, among them the XCDR2 kinds 00 07 / 00 09 / 00 0B, is refused.
//     A primitive of size n in {4, 8} is aligned to n *relative to the end of that header*
//     (offset - 4), never to the buffer start. Strings are a u32 length that counts the NUL, the
//     bytes, then the NUL. A sequence is a u32 count then the elements, the first aligned to the
//     element size (nothing to align when the count is 0).
//   * ROS 1: little-endian, no header, no alignment or padding; strings are a u32 length then the
//     bytes, no NUL.
//
// Every read checks that its bytes are there before touching them, and a count read from the
// payload is checked against the bytes left before anything is allocated (a count of 4e9 costs
// nothing). Failures throw InputError (no file: the caller adds file and message location)
//   "TYPE: FIELD: WHAT at byte OFFSET, the message has SIZE"
// e.g. "sensor_msgs/LaserScan: ranges: 1000 float32 values need 4000 bytes at byte 52, the
// message has 100". OFFSET counts from the start of the payload (the encapsulation header
// included), so it matches a hex dump of the message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

// std_msgs/Header, as RosMessageReader::ReadHeader reads it.
struct RosHeader {
  std::uint32_t seq = 0;      // ROS 1 only (0 for CDR)
  std::int64_t stamp_ns = 0;  // sec * 1e9 + nanosec, exact (int64 end to end)
  std::string frame_id;
};

enum class RosWireFormat { kCdrLittleEndian, kCdrBigEndian, kRos1 };
// "CDR little-endian", "CDR big-endian", "ROS 1".
const char* RosWireFormatName(RosWireFormat format);

class RosMessageReader {
 public:
  // `type` names the message in errors (e.g. "sensor_msgs/LaserScan"); `data` and `type` must
  // outlive the reader. For CDR the encapsulation header is read and checked here: a payload shorter than 4
  // bytes or of an unsupported kind throws InputError naming the kind.
  RosMessageReader(std::span<const std::uint8_t> data, MessageSerialization serialization, std::string_view type);

  RosWireFormat format() const { return format_; }
  std::size_t offset() const { return offset_; }  // next byte to read, from the payload start
  std::size_t size() const { return data_.size(); }

  // Field names in errors are "CONTEXT.FIELD" while a context is set (e.g. "transforms[2]"),
  // else "FIELD".
  void set_context(std::string context) { context_ = std::move(context); }

  std::uint32_t ReadUint32(std::string_view field);
  std::int32_t ReadInt32(std::string_view field);
  float ReadFloat32(std::string_view field);
  double ReadFloat64(std::string_view field);
  std::string ReadString(std::string_view field);
  // Unbounded sequences (u32 count, then the values).
  std::vector<float> ReadFloat32Sequence(std::string_view field);
  std::vector<double> ReadFloat64Sequence(std::string_view field);
  // Fixed arrays (no count): fills all of `out`.
  void ReadFloat64Array(std::string_view field, std::span<double> out);
  // The count of a sequence of messages whose every element takes at least `min_element_bytes`
  // (> 0): throws when that many elements cannot fit in the bytes left, so that the caller may
  // reserve `count` elements safely.
  std::uint32_t ReadSequenceCount(std::string_view field, std::size_t min_element_bytes);
  // std_msgs/Header: CDR {int32 sec, uint32 nanosec, string frame_id}; ROS 1 {uint32 seq,
  // uint32 sec, uint32 nsec, string frame_id}. stamp_ns = sec * 1e9 + nsec, exact in int64.
  RosHeader ReadHeader();

  // Throws InputError "TYPE: FIELD: WHAT at byte OFFSET, the message has SIZE".
  [[noreturn]] void Fail(std::string_view field, const std::string& what, std::size_t offset) const;

 private:
  void ReadEncapsulation();
  // Where an element of `element_size` bytes read next starts: offset_ rounded up to a multiple
  // of element_size from the end of the encapsulation header (CDR), offset_ itself (ROS 1). May
  // lie past the end of the data.
  std::size_t Aligned(std::size_t element_size) const;
  bool Fits(std::size_t at, std::uint64_t bytes) const { return at <= data_.size() && bytes <= data_.size() - at; }
  // Claims one primitive of `element_size` bytes, aligned: returns its offset, or throws
  // "FIELD: a NAME needs N bytes at byte OFFSET".
  std::size_t ClaimPrimitive(std::string_view field, std::size_t element_size, const char* name);
  // Claims `count` consecutive primitives of `element_size` bytes for a sequence or an array
  // (aligned unless count is 0), or throws "FIELD: COUNT NAME values need N bytes at byte OFFSET".
  std::size_t ClaimElements(std::string_view field, std::size_t element_size, std::uint64_t count, const char* name);
  std::uint32_t LoadUint32(std::size_t at) const;
  std::uint64_t LoadUint64(std::size_t at) const;
  // The float32 (`Float` float) or float64 (double) at `at`, in the payload's byte order.
  template <typename Float>
  Float LoadFloat(std::size_t at) const;
  // An unbounded sequence of float32 or float64 values: its u32 count, then the values, all
  // claimed before anything is allocated.
  template <typename Float>
  std::vector<Float> ReadFloatSequence(std::string_view field);

  std::span<const std::uint8_t> data_;
  RosWireFormat format_ = RosWireFormat::kRos1;
  std::string_view type_;
  std::string context_;
  std::size_t offset_ = 0;
};

}  // namespace slamtune::io
