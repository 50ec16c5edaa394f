// Test helpers: ROS recordings built byte by byte, so that the container readers are tested on
// exactly the layouts the specifications describe (MCAP: mcap.dev/spec; ROS 1:
// wiki.ros.org/Bags/Format/2.0; rosbag2 SQLite3: docs/recordings.md §1.3), compressed with the
// libraries' own compressors, plus small file and database utilities.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io::testing {

using Bytes = std::vector<std::uint8_t>;

Bytes ToBytes(std::string_view text);
Bytes Concat(std::initializer_list<Bytes> parts);

// Little-endian writer, the counterpart of ByteCursor.
class ByteWriter {
 public:
  ByteWriter& U8(std::uint8_t v);
  ByteWriter& U16(std::uint16_t v) { return Int(v, 2); }
  ByteWriter& U32(std::uint32_t v) { return Int(v, 4); }
  ByteWriter& U64(std::uint64_t v) { return Int(v, 8); }
  ByteWriter& Raw(std::span<const std::uint8_t> bytes);
  ByteWriter& Raw(std::string_view text);
  ByteWriter& StringU32(std::string_view text) { return U32(static_cast<std::uint32_t>(text.size())).Raw(text); }
  ByteWriter& BytesU32(std::span<const std::uint8_t> b) { return U32(static_cast<std::uint32_t>(b.size())).Raw(b); }
  ByteWriter& BytesU64(std::span<const std::uint8_t> b) { return U64(b.size()).Raw(b); }
  Bytes Take() { return std::move(bytes_); }

 private:
  ByteWriter& Int(std::uint64_t v, int size);
  Bytes bytes_;
};

Bytes ZstdCompress(std::span<const std::uint8_t> data);
Bytes Lz4FrameCompress(std::span<const std::uint8_t> data);
Bytes Bz2Compress(std::span<const std::uint8_t> data);

// --- MCAP records (spec "Records") ---
using StringMap = std::map<std::string, std::string>;
Bytes McapMagic();
Bytes McapRecord(std::uint8_t opcode, std::span<const std::uint8_t> content);
Bytes McapHeader(std::string_view profile = "ros2");
Bytes McapSchema(std::uint16_t id, std::string_view name, std::string_view encoding = "ros2msg");
Bytes McapChannel(std::uint16_t id, std::uint16_t schema_id, std::string_view topic, std::string_view encoding = "cdr",
                  const StringMap& metadata = {});
Bytes McapMessage(std::uint16_t channel_id, std::uint64_t log_time, std::string_view data);
// compression "", "zstd" or "lz4"; the CRC of the records is written unless `crc` says otherwise.
Bytes McapChunk(const Bytes& records, std::string_view compression, std::optional<std::uint32_t> crc = std::nullopt);
Bytes McapMetadata(std::string_view name, const StringMap& metadata);
Bytes McapMessageIndex(std::uint16_t channel_id);
Bytes McapDataEnd();
Bytes McapFooter();
// offered_qos_profiles as Humble writes it for a transient_local publisher (durability: 1).
std::string HumbleLatchedQos();

// A small complete MCAP: Header, Metadata rosbag2 (ROS_DISTRO jazzy), chunk 1 with Schema 1
// (sensor_msgs/msg/LaserScan), Channel 0 /scan, Schema 2 (tf2_msgs/msg/TFMessage), Channel 1
// /tf_static (latched) and messages scan@100 "scan-1", tf@150 "tf-1"; a MessageIndex; chunk 2
// with only messages scan@200 "scan-2", scan@300 "scan-3"; DataEnd; a summary repeating the
// Schemas and Channels; Footer; magic.
Bytes SmallMcap(std::string_view compression);
// Offsets of SmallMcap's two chunk records.
std::pair<std::uint64_t, std::uint64_t> SmallMcapChunkOffsets(std::string_view compression);

// --- ROS 1 bag records (Bags/Format/2.0) ---
using Ros1Fields = std::vector<std::pair<std::string, Bytes>>;
Bytes Ros1Magic();
Bytes Ros1HeaderBlock(const Ros1Fields& fields);
Bytes Ros1Record(const Ros1Fields& fields, const Bytes& data);
Bytes Ros1BagHeader(std::uint64_t index_pos, std::uint32_t connections, std::uint32_t chunks);
Bytes Ros1Connection(std::uint32_t conn, std::string_view topic, std::string_view type, bool latching = false);
Bytes Ros1MessageData(std::uint32_t conn, std::uint32_t sec, std::uint32_t nsec, std::string_view data);
// compression "none", "bz2" or "lz4".
Bytes Ros1Chunk(const Bytes& records, std::string_view compression);
Bytes Ros1IndexData(std::uint32_t conn);
Bytes Ros1ChunkInfo(std::uint64_t chunk_pos);

// A small ROS 1 bag: bag header, chunk 1 with connection 0 /scan (sensor_msgs/LaserScan) and
// connection 1 /tf_static (tf2_msgs/TFMessage, latching) and messages scan@1.5 s "scan-1",
// tf@2 s "tf-1"; index data; chunk 2 with messages scan@3 s "scan-2"; then (indexed) the index
// section: both connections again and two chunk infos, the bag header's index_pos pointing there.
Bytes SmallRos1Bag(std::string_view compression, bool indexed = true);

// --- SQLite ---
// A database file for writing test bags with plain SQL.
class TestDatabase {
 public:
  explicit TestDatabase(const std::string& path);
  ~TestDatabase();
  TestDatabase(const TestDatabase&) = delete;
  TestDatabase& operator=(const TestDatabase&) = delete;
  void Exec(const std::string& sql);
  void InsertMessage(std::int64_t id, std::int64_t topic_id, std::int64_t timestamp,
                     std::span<const std::uint8_t> data);

 private:
  sqlite3* db_ = nullptr;
};

// Writes a Humble-like db3 (topics with offered_qos_profiles; /scan id 1, /tf_static id 2
// latched) with four messages given out of timestamp order, tying at one timestamp.
void WriteHumbleDb3(const std::string& path);

// --- files ---
// A fresh empty folder under the temporary directory, unique to this process and `name`.
std::string FreshTempDir(const std::string& name);
void WriteFile(const std::string& path, std::span<const std::uint8_t> bytes);
Bytes ReadFile(const std::string& path);

// --- reading ---
// "byte N": where a reader's error says the record it stopped at starts.
std::string Byte(std::uint64_t offset);
// What a reader's error says after the record that is not read.
inline const std::string kLenientHint = " (--lenient reads the recording up to this record)";

struct Delivered {
  std::string topic;
  std::int64_t log_time_ns = 0;
  std::string data;
  std::string location;  // MessageLocation::ToString()
  std::string file;
};
MessageCallback Collect(std::vector<Delivered>* out);

// Expects `topic` to be the first topic of the small recordings (SmallMcap, WriteHumbleDb3,
// SmallRos1Bag): /scan, of `type` in `serialization`, not latched, with `messages` messages.
void ExpectScanTopic(const RecordedTopic& topic, const std::string& type, MessageSerialization serialization,
                     std::size_t messages);

// Robustness: `read` is called on every truncation of `bytes` (lengths 0, step, 2 step, ...) and
// on `corruptions` copies with one byte replaced (positions and values from a fixed seed).
struct FuzzOutcome {
  std::size_t reads = 0;
  std::size_t succeeded = 0;
  std::size_t input_errors = 0;
  std::vector<std::string> other_failures;  // anything thrown that is not an InputError
};
FuzzOutcome FuzzReader(const Bytes& bytes, std::size_t corruptions, const std::function<void(const Bytes&)>& read,
                       std::size_t truncation_step = 1);
// Expects the reader of `format`, strict and lenient, to read or refuse with an InputError every
// truncation of `bytes` and 400 corrupted copies, never anything else; strict, to refuse some.
void ExpectEveryDamageReadOrRefused(ContainerFormat format, const Bytes& bytes, const std::string& name);

// A container's reading in a test, and the error it gave ("" when none).
struct ContainerRead {
  ContainerSummary summary;
  std::vector<Delivered> messages;
  std::string error;
};
// `bytes` read as the file `name` of `format`.
ContainerRead ReadBytesAs(ContainerFormat format, const Bytes& bytes, const std::string& name,
                          ContainerReadOptions options = {});
// The file at `path` read as `format`.
ContainerRead ReadFileAs(ContainerFormat format, const std::string& path, ContainerReadOptions options = {});

}  // namespace slamtune::io::testing
