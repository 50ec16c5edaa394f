// ROS 1 bag v2.0 records as a linear reader sees them (wiki.ros.org/Bags/Format/2.0
// "Records"): header_len:u32, header, data_len:u32, data, the header a sequence of
// field_len:u32 + "name=value" fields with binary values (integers little-endian) and always an
// `op`; and the content of the two records that carry messages, Connection and Message data, as
// views into the bytes. Used by rosbag1_reader.cc for top-level records and for the records
// inside a chunk alike.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "slamtune/io/byte_cursor.h"
#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io::rosbag1 {

// Bags/Format/2.0 "Records": the `op` header field.
enum Op : std::uint8_t {
  kMessageData = 0x02,
  kBagHeader = 0x03,
  kIndexData = 0x04,
  kChunk = 0x05,
  kChunkInfo = 0x06,
  kConnection = 0x07,
};

// "chunk record", ..., "record" for an unknown op.
const char* OpName(std::uint8_t op);

// A record header (or a connection's data): its name=value fields, in file order.
struct Header {
  std::vector<std::pair<std::string_view, std::span<const std::uint8_t>>> fields;

  std::optional<std::span<const std::uint8_t>> Find(std::string_view name) const;
};

// One record: its op, header and data.
struct Record {
  std::uint8_t op = 0;
  std::uint64_t offset = 0;  // of the record, in the file or in a chunk's records
  Header header;
  std::uint64_t data_offset = 0;  // of its data, likewise
  std::span<const std::uint8_t> data;
};

// The record at the cursor; InputError when it runs past the end or has no one-byte op.
Record NextRecord(ByteCursor& cursor);

// Whether the data ends inside the record at `offset` (its header length, header, data length
// or data run past the end): the file was cut off there.
bool EndsInsideRecord(std::span<const std::uint8_t> bytes, std::uint64_t offset);

// Reads the header fields of one record; a missing field or one of the wrong size throws
// InputError at the record's offset, as does Fail.
class FieldReader {
 public:
  // Both must outlive the reader.
  FieldReader(const Record& record, const ByteCursor& cursor) : record_(record), cursor_(cursor) {}

  // The value of field `name`, of exactly `size` bytes unless `size` is 0.
  std::span<const std::uint8_t> Bytes(std::string_view name, std::size_t size = 0) const;
  std::string_view String(std::string_view name) const;
  std::uint32_t U32(std::string_view name) const;
  std::uint64_t U64(std::string_view name) const;
  [[noreturn]] void Fail(const std::string& problem) const;

 private:
  const Record& record_;
  const ByteCursor& cursor_;
};

// A Connection or Message data record as read, before it is checked against what is declared;
// any other record is kSkipped (a known op) or kUnknown.
struct Item {
  enum class Kind { kConnection, kMessage, kSkipped, kUnknown } kind = Kind::kSkipped;
  std::uint64_t offset = 0;            // of the record
  std::uint32_t conn = 0;              // connection id
  RecordedTopic topic;                 // kConnection: topic, type, latching
  std::int64_t time_ns = 0;            // kMessage: time (u32 sec, u32 nsec)
  std::span<const std::uint8_t> data;  // kMessage: the serialized message
};

// Parses `record`, read from `cursor` (whose file and frame errors name).
Item ParseItem(const Record& record, const ByteCursor& cursor);

}  // namespace slamtune::io::rosbag1
