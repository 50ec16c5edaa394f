#include "slamtune/io/ros/rosbag1_reader.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/byte_cursor.h"
#include "slamtune/io/ros/decompression.h"
#include "slamtune/io/ros/rosbag1_records.h"

namespace slamtune::io {
// The reader is in namespace rosbag1 with the records and ops it reads (rosbag1_records.h).
namespace rosbag1 {
namespace {

constexpr std::string_view kMagic = "#ROSBAG V2.0\n";  // Bags/Format/2.0 "Version"

class Rosbag1Reader : public ContainerBytesReader {
 public:
  using ContainerBytesReader::ContainerBytesReader;

  void Read();

 private:
  void HandleTopLevel(const Record& record, const ByteCursor& cursor);
  void ReadBagHeader(const Record& record, const ByteCursor& cursor);
  void ReadChunk(const Record& record, const ByteCursor& cursor);
  // Checks that every message's connection is declared, by an earlier record or by one before
  // it in `items`, then remembers the connections and delivers the messages at `location`.
  void Apply(const std::vector<Item>& items, const ByteCursor& cursor, std::uint64_t location);
  void SetEnding();

  std::unordered_map<std::uint32_t, std::size_t> connection_topics_;  // conn -> topic index
  bool bag_header_seen_ = false;
  std::uint64_t index_pos_ = 0;
  bool index_reached_ = false;
};

void Rosbag1Reader::Read() {
  sink_->summary().files.push_back(name_);
  if (sink_->summary().profile.empty()) sink_->summary().profile = "ros1";
  ByteCursor cursor(bytes_, name_);
  if (!HasRosbag1Magic(bytes_)) cursor.Fail(0, "version line", "not a ROS 1 bag v2.0 (no #ROSBAG V2.0 line)");
  cursor.Skip(kMagic.size(), "version line");
  while (!cursor.empty()) {
    const std::uint64_t record_offset = cursor.offset();
    try {
      const Record record = NextRecord(cursor);
      HandleTopLevel(record, cursor);
    } catch (const InputError& e) {
      sink_->EndAtBadRecord(e, {record_offset, bytes_.size(), EndsInsideRecord(bytes_, record_offset), bag_header_seen_,
                                options_.lenient});
      return;
    }
  }
  SetEnding();
}

void Rosbag1Reader::HandleTopLevel(const Record& record, const ByteCursor& cursor) {
  if (!bag_header_seen_) {
    if (record.op != kBagHeader)
      cursor.Fail(record.offset, OpName(record.op), "the first record is not the bag header");
    ReadBagHeader(record, cursor);
    return;
  }
  if (index_pos_ != 0 && record.offset == index_pos_) index_reached_ = true;
  if (record.op == kChunk) {
    ReadChunk(record, cursor);
  } else {
    Apply({ParseItem(record, cursor)}, cursor, record.offset);
  }
}

void Rosbag1Reader::ReadBagHeader(const Record& record, const ByteCursor& cursor) {
  const FieldReader fields(record, cursor);
  index_pos_ = fields.U64("index_pos");
  fields.U32("conn_count");
  fields.U32("chunk_count");
  bag_header_seen_ = true;
}

void Rosbag1Reader::ReadChunk(const Record& record, const ByteCursor& cursor) {
  const FieldReader fields(record, cursor);
  const std::string_view compression = fields.String("compression");
  const std::uint32_t size = fields.U32("size");
  std::vector<std::uint8_t> decompressed;
  std::span<const std::uint8_t> records = record.data;
  if (compression != "none") {
    if (compression != "bz2" && compression != "lz4") {
      fields.Fail("unknown compression \"" + std::string(compression) + "\"");
    }
    try {
      decompressed = DecompressExact(compression == "bz2" ? Codec::kBz2 : Codec::kLz4Frame, record.data, size);
    } catch (const InputError& e) {
      fields.Fail(e.message());
    }
    records = decompressed;
  }
  const std::string frame = "byte " + std::to_string(record.offset) + " (chunk), uncompressed ";
  ByteCursor inner(records, name_, 0, frame);
  std::vector<Item> items;
  while (!inner.empty()) items.push_back(ParseItem(NextRecord(inner), inner));
  Apply(items, inner, record.offset);
  ContainerSummary& summary = sink_->summary();
  ++summary.chunks;
  ++summary.chunk_compression[std::string(compression)];
}

void Rosbag1Reader::Apply(const std::vector<Item>& items, const ByteCursor& cursor, std::uint64_t location) {
  std::unordered_set<std::uint32_t> new_connections;
  for (const Item& item : items) {
    if (item.kind == Item::Kind::kConnection) new_connections.insert(item.conn);
    if (item.kind == Item::Kind::kMessage && !connection_topics_.contains(item.conn) &&
        !new_connections.contains(item.conn)) {
      cursor.Fail(item.offset, OpName(kMessageData),
                  "message on connection " + std::to_string(item.conn) + ", which was never declared");
    }
  }
  ContainerSummary& summary = sink_->summary();
  for (const Item& item : items) {
    switch (item.kind) {
      case Item::Kind::kConnection:
        if (!connection_topics_.contains(item.conn)) connection_topics_[item.conn] = sink_->AddTopic(item.topic);
        break;
      case Item::Kind::kMessage: Deliver(connection_topics_.at(item.conn), item.time_ns, item.data, location); break;
      case Item::Kind::kSkipped: ++summary.skipped_records; break;
      case Item::Kind::kUnknown: ++summary.unknown_records; break;
    }
  }
}

void Rosbag1Reader::SetEnding() {
  ContainerSummary& summary = sink_->summary();
  if (index_reached_) {
    summary.data_end.how = "index (connection and chunk info records at index_pos)";
    return;
  }
  summary.data_end.complete = false;
  summary.data_end.how = index_pos_ == 0
                             ? "no index (the bag header's index_pos is 0): the file ends after a complete record "
                               "(recording cut off?)"
                             : "no index at index_pos " + std::to_string(index_pos_) +
                                   ": the file ends after a complete record (recording cut off?)";
}

}  // namespace
}  // namespace rosbag1

bool HasRosbag1Magic(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= rosbag1::kMagic.size() &&
         std::equal(rosbag1::kMagic.begin(), rosbag1::kMagic.end(), bytes.begin());
}

void ReadRosbag1Into(std::span<const std::uint8_t> bytes, const std::string& name, const ContainerReadOptions& options,
                     ContainerSink* sink) {
  rosbag1::Rosbag1Reader(bytes, name, options, sink).Read();
}

}  // namespace slamtune::io
