#include "slamtune/io/ros/mcap_reader.h"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/byte_cursor.h"
#include "slamtune/io/ros/decompression.h"
#include "slamtune/io/ros/mcap_records.h"

namespace slamtune::io {
// The reader is in namespace mcap with the records and opcodes it reads (mcap_records.h).
namespace mcap {
namespace {

constexpr std::uint8_t kMagic[] = {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};  // spec "Magic"

class McapReader : public ContainerBytesReader {
 public:
  using ContainerBytesReader::ContainerBytesReader;

  void Read();

 private:
  // Handles one top-level record; returns false at the Footer.
  bool HandleTopLevel(const Record& record);
  void ReadHeader(const Record& record);
  void ReadMetadata(const Record& record);
  void ReadChunk(const Record& record);
  std::vector<std::uint8_t> ChunkRecords(const Record& record, std::span<const std::uint8_t>* records,
                                         std::string* compression_name);
  // Checks that every Channel's schema and every Message's channel is declared, by an earlier
  // record or by one before it in `items`, so that a chunk is refused before any of it is used.
  void CheckDeclarations(const std::vector<Item>& items, std::string_view frame) const;
  // Checks the declarations, then remembers the Schemas and Channels and delivers the Messages,
  // located at `location` (the record's offset, or its chunk's).
  void Apply(const std::vector<Item>& items, std::string_view frame, std::uint64_t location);
  void CheckClosingMagic(ByteCursor& cursor) const;
  void SetEnding();

  std::unordered_map<std::uint16_t, std::string> schema_names_;    // Schema id -> name
  std::unordered_map<std::uint16_t, std::size_t> channel_topics_;  // Channel id -> topic index
  bool header_seen_ = false;
  bool data_end_seen_ = false;
  bool footer_seen_ = false;
};

void McapReader::Read() {
  ContainerSummary& summary = sink_->summary();
  summary.files.push_back(name_);
  ByteCursor cursor(bytes_, name_);
  if (!HasMcapMagic(bytes_)) cursor.Fail(0, "magic", "not an MCAP file (no \\x89MCAP0\\r\\n magic)");
  cursor.Skip(sizeof(kMagic), "magic");
  while (!cursor.empty()) {
    const std::uint64_t record_offset = cursor.offset();
    try {
      if (!HandleTopLevel(NextRecord(cursor))) {
        CheckClosingMagic(cursor);
        break;
      }
    } catch (const InputError& e) {
      sink_->EndAtBadRecord(
          e, {record_offset, bytes_.size(), EndsInsideRecord(bytes_, record_offset), header_seen_, options_.lenient});
      return;
    }
  }
  SetEnding();
}

bool McapReader::HandleTopLevel(const Record& record) {
  ContainerSummary& summary = sink_->summary();
  if (!header_seen_) {
    if (record.opcode != kHeader) {
      ThrowAtByte(name_, "", record.offset, RecordName(record.opcode), "the first record is not the Header");
    }
    ReadHeader(record);
    return true;
  }
  switch (record.opcode) {
    case kFooter: footer_seen_ = true; return false;
    case kDataEnd: data_end_seen_ = true; return true;
    case kChunk:
      if (data_end_seen_) break;  // not in a summary section
      ReadChunk(record);
      return true;
    case kMetadata: ReadMetadata(record); break;
    case kSchema:
    case kChannel:
    case kMessage:
      if (data_end_seen_) break;  // the summary repeats Schemas and Channels: skipped
      Apply({ParseItem(record, name_, "")}, "", record.offset);
      return true;
    default: break;
  }
  ++(IsKnownOrUserOpcode(record.opcode) ? summary.skipped_records : summary.unknown_records);
  return true;
}

void McapReader::ReadHeader(const Record& record) {
  ByteCursor cursor(record.content, name_, record.offset + kRecordFraming);
  const std::string_view profile = cursor.StringU32("Header profile");
  cursor.StringU32("Header library");
  header_seen_ = true;
  if (sink_->summary().profile.empty()) sink_->summary().profile = std::string(profile);
}

// Spec "Metadata": name, then Map<string, string>; rosbag2 writes "rosbag2" with ROS_DISTRO.
void McapReader::ReadMetadata(const Record& record) {
  ByteCursor cursor(record.content, name_, record.offset + kRecordFraming);
  const std::string_view name = cursor.StringU32("Metadata name");
  ByteCursor map(cursor.BytesU32("Metadata metadata"), name_, cursor.offset());
  while (!map.empty()) {
    const std::string_view key = map.StringU32("Metadata key");
    const std::string_view value = map.StringU32("Metadata value");
    if (name == "rosbag2" && key == "ROS_DISTRO" && sink_->summary().ros_distro.empty()) {
      sink_->summary().ros_distro = std::string(value);
    }
  }
}

// Spec "Chunk": message_start_time, message_end_time, uncompressed_size, uncompressed_crc,
// compression, records (u64-prefixed). Returns the decompressed bytes (empty when the records
// are stored as they are), points `records` at the records and names the compression ("none"
// for "").
std::vector<std::uint8_t> McapReader::ChunkRecords(const Record& record, std::span<const std::uint8_t>* records,
                                                   std::string* compression_name) {
  ByteCursor cursor(record.content, name_, record.offset + kRecordFraming);
  cursor.U64("Chunk message_start_time");
  cursor.U64("Chunk message_end_time");
  const std::uint64_t uncompressed_size = cursor.U64("Chunk uncompressed_size");
  const std::uint32_t crc = cursor.U32("Chunk uncompressed_crc");
  const std::string_view compression = cursor.StringU32("Chunk compression");
  const std::span<const std::uint8_t> stored = cursor.BytesU64("Chunk records");
  std::vector<std::uint8_t> decompressed;
  *records = stored;
  if (!compression.empty()) {
    if (compression != "zstd" && compression != "lz4") {
      ThrowAtByte(name_, "", record.offset, "chunk", "unknown compression \"" + std::string(compression) + "\"");
    }
    try {
      decompressed =
          DecompressExact(compression == "zstd" ? Codec::kZstd : Codec::kLz4Frame, stored, uncompressed_size);
    } catch (const InputError& e) {
      ThrowAtByte(name_, "", record.offset, "chunk", e.message());
    }
    *records = decompressed;
  }
  if (crc != 0 && options_.verify_crc) {
    const std::uint32_t actual = static_cast<std::uint32_t>(crc32_z(0, records->data(), records->size()));
    if (actual != crc) {
      char text[96];
      std::snprintf(text, sizeof(text), "CRC mismatch: the records' CRC-32 is %08x, the chunk says %08x", actual, crc);
      ThrowAtByte(name_, "", record.offset, "chunk", text);
    }
  }
  *compression_name = compression.empty() ? "none" : std::string(compression);
  return decompressed;
}

void McapReader::ReadChunk(const Record& record) {
  std::span<const std::uint8_t> records;
  std::string compression;
  const std::vector<std::uint8_t> decompressed = ChunkRecords(record, &records, &compression);
  const std::string frame = "byte " + std::to_string(record.offset) + " (chunk), uncompressed ";
  ByteCursor cursor(records, name_, 0, frame);
  std::vector<Item> items;
  while (!cursor.empty()) items.push_back(ParseItem(NextRecord(cursor), name_, frame));
  Apply(items, frame, record.offset);
  ContainerSummary& summary = sink_->summary();
  ++summary.chunks;
  ++summary.chunk_compression[compression];
}

void McapReader::CheckDeclarations(const std::vector<Item>& items, std::string_view frame) const {
  std::unordered_set<std::uint16_t> new_schemas, new_channels;
  for (const Item& item : items) {
    if (item.kind == Item::Kind::kSchema) new_schemas.insert(item.id);
    if (item.kind == Item::Kind::kChannel) {
      if (item.schema_id != 0 && !schema_names_.contains(item.schema_id) && !new_schemas.contains(item.schema_id)) {
        ThrowAtByte(name_, frame, item.offset, "Channel",
                    "channel " + std::to_string(item.id) + " (" + std::string(item.name) + ") names schema " +
                        std::to_string(item.schema_id) + ", which was never declared");
      }
      new_channels.insert(item.id);
    }
    if (item.kind == Item::Kind::kMessage && !channel_topics_.contains(item.id) && !new_channels.contains(item.id)) {
      ThrowAtByte(name_, frame, item.offset, "Message",
                  "message on channel " + std::to_string(item.id) + ", which was never declared");
    }
  }
}

RecordedTopic ChannelTopic(const Item& channel, const std::string& schema_name) {
  RecordedTopic topic;
  topic.name = std::string(channel.name);
  topic.type = schema_name;
  topic.latched = channel.latched;
  if (channel.encoding == "cdr") {
    topic.serialization = MessageSerialization::kCdr;
  } else if (channel.encoding == "ros1") {
    topic.serialization = MessageSerialization::kRos1;
  } else {
    topic.type += (topic.type.empty() ? "(" : " (") + std::string(channel.encoding) + " encoding)";
  }
  return topic;
}

void McapReader::Apply(const std::vector<Item>& items, std::string_view frame, std::uint64_t location) {
  CheckDeclarations(items, frame);
  ContainerSummary& summary = sink_->summary();
  for (const Item& item : items) {
    switch (item.kind) {
      case Item::Kind::kSchema: schema_names_.try_emplace(item.id, item.name); break;
      case Item::Kind::kChannel:
        if (!channel_topics_.contains(item.id)) {
          const auto schema = schema_names_.find(item.schema_id);
          const std::string schema_name = schema == schema_names_.end() ? std::string() : schema->second;
          channel_topics_[item.id] = sink_->AddTopic(ChannelTopic(item, schema_name));
        }
        break;
      case Item::Kind::kMessage:
        Deliver(channel_topics_.at(item.id), static_cast<std::int64_t>(item.log_time), item.data, location);
        break;
      case Item::Kind::kSkipped: ++summary.skipped_records; break;
      case Item::Kind::kUnknown: ++summary.unknown_records; break;
    }
  }
}

void McapReader::CheckClosingMagic(ByteCursor& cursor) const {
  const std::uint64_t offset = cursor.offset();
  if (cursor.remaining() < sizeof(kMagic) || !HasMcapMagic(cursor.Bytes(sizeof(kMagic), "closing magic"))) {
    cursor.Fail(offset, "closing magic", "the Footer is not followed by the MCAP magic");
  }
  if (!cursor.empty()) {
    cursor.Fail(cursor.offset(), "closing magic",
                std::to_string(cursor.remaining()) + " bytes after the closing magic");
  }
}

void McapReader::SetEnding() {
  ContainerSummary& summary = sink_->summary();
  if (data_end_seen_ && footer_seen_) {
    summary.data_end.how = "data end record and footer";
  } else if (data_end_seen_) {
    summary.data_end.how = "data end record, no footer (the file ends after the summary section)";
  } else if (footer_seen_) {
    summary.data_end.how = "footer without a data end record";
  } else {
    summary.data_end.how = "no data end record: the file ends after a complete record (recording cut off?)";
    summary.data_end.complete = false;
  }
}

}  // namespace
}  // namespace mcap

bool HasMcapMagic(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= sizeof(mcap::kMagic) &&
         std::equal(std::begin(mcap::kMagic), std::end(mcap::kMagic), bytes.begin());
}

void ReadMcapInto(std::span<const std::uint8_t> bytes, const std::string& name, const ContainerReadOptions& options,
                  ContainerSink* sink) {
  mcap::McapReader(bytes, name, options, sink).Read();
}

}  // namespace slamtune::io
