#include "slamtune/io/ros/rosbag1_records.h"

#include <algorithm>
#include <optional>

namespace slamtune::io::rosbag1 {
namespace {

constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

std::uint64_t LittleEndian(std::span<const std::uint8_t> bytes) {
  std::uint64_t value = 0;
  for (std::size_t i = bytes.size(); i-- > 0;) value = (value << 8) | bytes[i];
  return value;
}

// The fields of a header block that starts at absolute offset `offset`.
Header ParseHeader(std::span<const std::uint8_t> bytes, const ByteCursor& outer, std::uint64_t offset) {
  Header header;
  ByteCursor cursor(bytes, outer.file(), offset, outer.frame());
  while (!cursor.empty()) {
    const std::uint64_t field_offset = cursor.offset();
    const auto field = cursor.BytesU32("header field");
    const auto equals = std::find(field.begin(), field.end(), std::uint8_t{'='});
    if (equals == field.end()) cursor.Fail(field_offset, "header field", "no '=' between the name and the value");
    const auto name_size = static_cast<std::size_t>(equals - field.begin());
    header.fields.emplace_back(std::string_view(reinterpret_cast<const char*>(field.data()), name_size),
                               field.subspan(name_size + 1));
  }
  return header;
}

// An item of `kind` with the connection id that Connection and Message data records both carry.
Item ConnectionItem(Item::Kind kind, const FieldReader& fields) {
  Item item;
  item.kind = kind;
  item.conn = fields.U32("conn");
  return item;
}

Item ParseConnection(const Record& record, const ByteCursor& cursor) {
  const FieldReader fields(record, cursor);
  Item item = ConnectionItem(Item::Kind::kConnection, fields);
  item.topic.name = std::string(fields.String("topic"));
  item.topic.serialization = MessageSerialization::kRos1;
  // The data is a second header: topic, type, md5sum, message_definition, [callerid, latching].
  Record details = record;
  details.header = ParseHeader(record.data, cursor, record.data_offset);
  const FieldReader detail_fields(details, cursor);
  item.topic.type = std::string(detail_fields.String("type"));
  const auto latching = details.header.Find("latching");
  item.topic.latched = latching && latching->size() == 1 && (*latching)[0] == '1';
  return item;
}

Item ParseMessageData(const Record& record, const ByteCursor& cursor) {
  const FieldReader fields(record, cursor);
  Item item = ConnectionItem(Item::Kind::kMessage, fields);
  const std::uint64_t time = fields.U64("time");  // u32 sec, then u32 nsec
  const auto sec = static_cast<std::int64_t>(time & 0xFFFFFFFFu), nsec = static_cast<std::int64_t>(time >> 32);
  item.time_ns = sec * kNanosecondsPerSecond + nsec;
  item.data = record.data;
  return item;
}

}  // namespace

const char* OpName(std::uint8_t op) {
  switch (op) {
    case kMessageData: return "message data record";
    case kBagHeader: return "bag header record";
    case kIndexData: return "index data record";
    case kChunk: return "chunk record";
    case kChunkInfo: return "chunk info record";
    case kConnection: return "connection record";
    default: return "record";
  }
}

std::optional<std::span<const std::uint8_t>> Header::Find(std::string_view name) const {
  for (const auto& [field, value] : fields) {
    if (field == name) return value;
  }
  return std::nullopt;
}

std::span<const std::uint8_t> FieldReader::Bytes(std::string_view name, std::size_t size) const {
  const auto value = record_.header.Find(name);
  if (!value) Fail("no field " + std::string(name));
  if (size != 0 && value->size() != size) {
    Fail("field " + std::string(name) + " has " + std::to_string(value->size()) + " bytes, expected " +
         std::to_string(size));
  }
  return *value;
}

std::string_view FieldReader::String(std::string_view name) const {
  const auto value = Bytes(name);
  return {reinterpret_cast<const char*>(value.data()), value.size()};
}

std::uint32_t FieldReader::U32(std::string_view name) const {
  return static_cast<std::uint32_t>(LittleEndian(Bytes(name, 4)));
}

std::uint64_t FieldReader::U64(std::string_view name) const { return LittleEndian(Bytes(name, 8)); }

void FieldReader::Fail(const std::string& problem) const { cursor_.Fail(record_.offset, OpName(record_.op), problem); }

Record NextRecord(ByteCursor& cursor) {
  Record record;
  record.offset = cursor.offset();
  const auto header = cursor.BytesU32("record header");
  record.header = ParseHeader(header, cursor, record.offset + 4);
  const auto op = record.header.Find("op");
  if (!op || op->size() != 1) cursor.Fail(record.offset, "record", "no one-byte op field in the record header");
  record.op = (*op)[0];
  const std::uint32_t data_length = cursor.U32(OpName(record.op));
  if (data_length > cursor.remaining()) {
    cursor.Fail(record.offset, OpName(record.op),
                "data length " + std::to_string(data_length) + " runs past the end (" +
                    std::to_string(cursor.remaining()) + " bytes left)");
  }
  record.data_offset = cursor.offset();
  record.data = cursor.Bytes(data_length, OpName(record.op));
  return record;
}

bool EndsInsideRecord(std::span<const std::uint8_t> bytes, std::uint64_t offset) {
  const auto u32_at = [&](std::uint64_t at) -> std::optional<std::uint64_t> {
    if (at > bytes.size() || bytes.size() - at < 4) return std::nullopt;
    return std::uint64_t{bytes[at]} | std::uint64_t{bytes[at + 1]} << 8 | std::uint64_t{bytes[at + 2]} << 16 |
           std::uint64_t{bytes[at + 3]} << 24;
  };
  const std::optional<std::uint64_t> header_length = u32_at(offset);
  if (!header_length) return true;
  const std::uint64_t data_length_at = offset + 4 + *header_length;
  const std::optional<std::uint64_t> data_length = u32_at(data_length_at);
  return !data_length || *data_length > bytes.size() - data_length_at - 4;
}

Item ParseItem(const Record& record, const ByteCursor& cursor) {
  Item item;
  switch (record.op) {
    case kConnection: item = ParseConnection(record, cursor); break;
    case kMessageData: item = ParseMessageData(record, cursor); break;
    case kBagHeader:
    case kIndexData:
    case kChunk:
    case kChunkInfo: item.kind = Item::Kind::kSkipped; break;
    default: item.kind = Item::Kind::kUnknown;
  }
  item.offset = record.offset;
  return item;
}

}  // namespace slamtune::io::rosbag1
