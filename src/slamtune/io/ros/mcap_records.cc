#include "slamtune/io/ros/mcap_records.h"

#include <cstdio>

#include "slamtune/io/ros/rosbag2_qos.h"

namespace slamtune::io::mcap {
namespace {

// Spec "Channel": the metadata Map<string, string> (u32 byte length, then key/value strings).
bool ChannelIsLatched(ByteCursor& cursor) {
  ByteCursor map(cursor.BytesU32("Channel metadata"), cursor.file(), cursor.offset(), cursor.frame());
  bool latched = false;
  while (!map.empty()) {
    const std::string_view key = map.StringU32("Channel metadata key");
    const std::string_view value = map.StringU32("Channel metadata value");
    if (key == "offered_qos_profiles" && OfferedQosIsTransientLocal(value)) latched = true;
    if (key == "latching" && value == "1") latched = true;
  }
  return latched;
}

}  // namespace

std::string RecordName(std::uint8_t opcode) {
  static constexpr const char* kNames[] = {"",           "Header",        "Footer",          "Schema",
                                           "Channel",    "Message",       "Chunk",           "MessageIndex",
                                           "ChunkIndex", "Attachment",    "AttachmentIndex", "Statistics",
                                           "Metadata",   "MetadataIndex", "SummaryOffset",   "DataEnd"};
  if (opcode >= kHeader && opcode <= kDataEnd) return std::string(kNames[opcode]) + " record";
  char hex[8];
  std::snprintf(hex, sizeof(hex), "0x%02X", opcode);
  return std::string("record of opcode ") + hex;
}

bool IsKnownOrUserOpcode(std::uint8_t opcode) {
  return (opcode >= kHeader && opcode <= kDataEnd) || opcode >= kFirstUserOpcode;
}

Record NextRecord(ByteCursor& cursor) {
  Record record;
  record.offset = cursor.offset();
  if (cursor.remaining() < kRecordFraming) {
    cursor.Fail(
        record.offset, "record",
        "the data ends inside a record's opcode and length (" + std::to_string(cursor.remaining()) + " of 9 bytes)");
  }
  record.opcode = cursor.U8("record opcode");
  const std::uint64_t length = cursor.U64("record length");
  if (length > cursor.remaining()) {
    cursor.Fail(record.offset, RecordName(record.opcode),
                "content length " + std::to_string(length) + " runs past the end (" +
                    std::to_string(cursor.remaining()) + " bytes left)");
  }
  record.content = cursor.Bytes(length, "record content");
  return record;
}

bool EndsInsideRecord(std::span<const std::uint8_t> bytes, std::uint64_t offset) {
  if (offset > bytes.size()) return true;
  const std::uint64_t remaining = bytes.size() - offset;
  if (remaining < kRecordFraming) return true;
  std::uint64_t length = 0;
  for (int i = 8; i >= 1; --i) length = (length << 8) | bytes[offset + static_cast<std::uint64_t>(i)];
  return length > remaining - kRecordFraming;
}

Item ParseItem(const Record& record, std::string_view file, std::string_view frame) {
  Item item;
  item.offset = record.offset;
  ByteCursor cursor(record.content, file, record.offset + kRecordFraming, frame);
  switch (record.opcode) {
    case kSchema:
      item.kind = Item::Kind::kSchema;
      item.id = cursor.U16("Schema id");
      item.name = cursor.StringU32("Schema name");
      item.encoding = cursor.StringU32("Schema encoding");
      cursor.BytesU32("Schema data");
      break;
    case kChannel:
      item.kind = Item::Kind::kChannel;
      item.id = cursor.U16("Channel id");
      item.schema_id = cursor.U16("Channel schema_id");
      item.name = cursor.StringU32("Channel topic");
      item.encoding = cursor.StringU32("Channel message_encoding");
      item.latched = ChannelIsLatched(cursor);
      break;
    case kMessage:
      item.kind = Item::Kind::kMessage;
      item.id = cursor.U16("Message channel_id");
      cursor.U32("Message sequence");
      item.log_time = cursor.U64("Message log_time");
      cursor.U64("Message publish_time");
      item.data = cursor.Rest();
      break;
    default: item.kind = IsKnownOrUserOpcode(record.opcode) ? Item::Kind::kSkipped : Item::Kind::kUnknown;
  }
  return item;
}

}  // namespace slamtune::io::mcap
