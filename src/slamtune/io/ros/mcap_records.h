// MCAP records as a linear reader sees them (mcap.dev/spec "Records"): the framing of every
// record (opcode:u8, content_length:u64, content; unknown trailing fields of a known record are
// ignored), and the content of the three records that carry messages, Schema, Channel and
// Message, as views into the bytes. Used by mcap_reader.cc for top-level records and for the
// records inside a chunk alike.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "slamtune/io/byte_cursor.h"

namespace slamtune::io::mcap {

// Spec "Records": the opcodes a reader acts on.
enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMetadata = 0x0C,
  kDataEnd = 0x0F,
  kFirstUserOpcode = 0x80,  // 0x80-0xFF: user extensions
};
constexpr std::size_t kRecordFraming = 1 + 8;  // opcode:u8, content_length:u64

// "Chunk record", or "record of opcode 0x42" for one the spec does not define.
std::string RecordName(std::uint8_t opcode);
// Opcodes the spec defines (0x01-0x0F) and user extensions: skipped when not used, not unknown.
bool IsKnownOrUserOpcode(std::uint8_t opcode);

// One record: its opcode, where it starts (in the file or in a chunk's records) and its content.
struct Record {
  std::uint8_t opcode = 0;
  std::uint64_t offset = 0;
  std::span<const std::uint8_t> content;
};

// The record at the cursor; InputError when its framing or content runs past the end.
Record NextRecord(ByteCursor& cursor);

// Whether the data ends inside the record at `offset` (its opcode and length, or the content
// they declare, run past the end): the file was cut off there.
bool EndsInsideRecord(std::span<const std::uint8_t> bytes, std::uint64_t offset);

// A Schema, Channel or Message record as read, before it is checked against what is declared;
// any other record is kSkipped or kUnknown.
struct Item {
  enum class Kind { kSchema, kChannel, kMessage, kSkipped, kUnknown } kind = Kind::kSkipped;
  std::uint64_t offset = 0;            // of the record
  std::uint16_t id = 0;                // Schema id, Channel id, Message channel_id
  std::uint16_t schema_id = 0;         // Channel
  std::string_view name;               // Schema name, Channel topic
  std::string_view encoding;           // Schema encoding, Channel message_encoding
  bool latched = false;                // Channel: offered_qos_profiles transient_local, or latching=1
  std::uint64_t log_time = 0;          // Message
  std::span<const std::uint8_t> data;  // Message
};

// Parses `record`; errors name `file`, `frame` (ByteCursor) and the field.
Item ParseItem(const Record& record, std::string_view file, std::string_view frame);

}  // namespace slamtune::io::mcap
