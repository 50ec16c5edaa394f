#include "slamtune/io/testing/recording_bytes.h"

#include <bzlib.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <lz4frame.h>
#include <unistd.h>
#include <zlib.h>
#include <zstd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io::testing {
namespace {

namespace fs = std::filesystem;

void Append(Bytes* out, std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  const std::size_t old_size = out->size();
  out->resize(old_size + bytes.size());
  std::memcpy(out->data() + old_size, bytes.data(), bytes.size());
}

Bytes U32Bytes(std::uint32_t v) { return ByteWriter().U32(v).Take(); }
Bytes U64Bytes(std::uint64_t v) { return ByteWriter().U64(v).Take(); }

}  // namespace

Bytes ToBytes(std::string_view text) { return Bytes(text.begin(), text.end()); }

Bytes Concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const Bytes& part : parts) Append(&out, part);
  return out;
}

ByteWriter& ByteWriter::U8(std::uint8_t v) {
  bytes_.push_back(v);
  return *this;
}

ByteWriter& ByteWriter::Int(std::uint64_t v, int size) {
  for (int i = 0; i < size; ++i) bytes_.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
  return *this;
}

ByteWriter& ByteWriter::Raw(std::span<const std::uint8_t> bytes) {
  Append(&bytes_, bytes);
  return *this;
}

ByteWriter& ByteWriter::Raw(std::string_view text) {
  bytes_.insert(bytes_.end(), text.begin(), text.end());
  return *this;
}

Bytes ZstdCompress(std::span<const std::uint8_t> data) {
  Bytes out(ZSTD_compressBound(data.size()));
  const std::size_t n = ZSTD_compress(out.data(), out.size(), data.data(), data.size(), 3);
  if (ZSTD_isError(n)) throw std::runtime_error(ZSTD_getErrorName(n));
  out.resize(n);
  return out;
}

Bytes Lz4FrameCompress(std::span<const std::uint8_t> data) {
  Bytes out(LZ4F_compressFrameBound(data.size(), nullptr));
  const std::size_t n = LZ4F_compressFrame(out.data(), out.size(), data.data(), data.size(), nullptr);
  if (LZ4F_isError(n)) throw std::runtime_error(LZ4F_getErrorName(n));
  out.resize(n);
  return out;
}

Bytes Bz2Compress(std::span<const std::uint8_t> data) {
  Bytes out(data.size() + data.size() / 100 + 600);
  auto size = static_cast<unsigned int>(out.size());
  const int rc = BZ2_bzBuffToBuffCompress(reinterpret_cast<char*>(out.data()), &size,
                                          const_cast<char*>(reinterpret_cast<const char*>(data.data())),
                                          static_cast<unsigned int>(data.size()), 9, 0, 0);
  if (rc != BZ_OK) throw std::runtime_error("bz2 compression failed");
  out.resize(size);
  return out;
}

// --- MCAP ---

Bytes McapMagic() { return {0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'}; }

Bytes McapRecord(std::uint8_t opcode, std::span<const std::uint8_t> content) {
  return ByteWriter().U8(opcode).U64(content.size()).Raw(content).Take();
}

Bytes McapHeader(std::string_view profile) {
  return McapRecord(0x01, ByteWriter().StringU32(profile).StringU32("slamtune test").Take());
}

Bytes McapSchema(std::uint16_t id, std::string_view name, std::string_view encoding) {
  return McapRecord(0x03, ByteWriter().U16(id).StringU32(name).StringU32(encoding).StringU32("float32 x\n").Take());
}

namespace {

Bytes EncodeMap(const StringMap& map) {
  ByteWriter pairs;
  for (const auto& [key, value] : map) pairs.StringU32(key).StringU32(value);
  return ByteWriter().BytesU32(pairs.Take()).Take();
}

}  // namespace

Bytes McapChannel(std::uint16_t id, std::uint16_t schema_id, std::string_view topic, std::string_view encoding,
                  const StringMap& metadata) {
  return McapRecord(
      0x04, ByteWriter().U16(id).U16(schema_id).StringU32(topic).StringU32(encoding).Raw(EncodeMap(metadata)).Take());
}

Bytes McapMessage(std::uint16_t channel_id, std::uint64_t log_time, std::string_view data) {
  return McapRecord(0x05, ByteWriter().U16(channel_id).U32(7).U64(log_time).U64(log_time + 1).Raw(data).Take());
}

Bytes McapChunk(const Bytes& records, std::string_view compression, std::optional<std::uint32_t> crc) {
  Bytes stored = records;
  if (compression == "zstd") stored = ZstdCompress(records);
  if (compression == "lz4") stored = Lz4FrameCompress(records);
  const auto actual_crc = static_cast<std::uint32_t>(crc32_z(0, records.data(), records.size()));
  return McapRecord(0x06, ByteWriter()
                              .U64(100)
                              .U64(300)
                              .U64(records.size())
                              .U32(crc.value_or(actual_crc))
                              .StringU32(compression)
                              .BytesU64(stored)
                              .Take());
}

Bytes McapMetadata(std::string_view name, const StringMap& metadata) {
  return McapRecord(0x0C, ByteWriter().StringU32(name).Raw(EncodeMap(metadata)).Take());
}

Bytes McapMessageIndex(std::uint16_t channel_id) {
  return McapRecord(0x07, ByteWriter().U16(channel_id).U32(16).U64(100).U64(0).Take());
}

Bytes McapDataEnd() { return McapRecord(0x0F, ByteWriter().U32(0).Take()); }

Bytes McapFooter() { return McapRecord(0x02, ByteWriter().U64(0).U64(0).U32(0).Take()); }

std::string HumbleLatchedQos() {
  return "- history: 3\n  depth: 0\n  reliability: 1\n  durability: 1\n  deadline:\n    sec: 2147483647\n"
         "    nsec: 4294967295\n  lifespan:\n    sec: 2147483647\n    nsec: 4294967295\n  liveliness: 1\n"
         "  liveliness_lease_duration:\n    sec: 2147483647\n    nsec: 4294967295\n"
         "  avoid_ros_namespace_conventions: false";
}

namespace {

Bytes SmallMcapPrefix() {
  return Concat({McapMagic(), McapHeader(), McapMetadata("rosbag2", {{"ROS_DISTRO", "jazzy"}})});
}

Bytes SmallMcapChunk1(std::string_view compression) {
  return McapChunk(Concat({McapSchema(1, "sensor_msgs/msg/LaserScan"), McapChannel(0, 1, "/scan"),
                           McapSchema(2, "tf2_msgs/msg/TFMessage"),
                           McapChannel(1, 2, "/tf_static", "cdr", {{"offered_qos_profiles", HumbleLatchedQos()}}),
                           McapMessage(0, 100, "scan-1"), McapMessage(1, 150, "tf-1")}),
                   compression);
}

}  // namespace

Bytes SmallMcap(std::string_view compression) {
  const Bytes chunk2 = McapChunk(Concat({McapMessage(0, 200, "scan-2"), McapMessage(0, 300, "scan-3")}), compression);
  return Concat({SmallMcapPrefix(), SmallMcapChunk1(compression), McapMessageIndex(0), chunk2, McapMessageIndex(0),
                 McapDataEnd(), McapSchema(1, "sensor_msgs/msg/LaserScan"), McapChannel(0, 1, "/scan"), McapFooter(),
                 McapMagic()});
}

std::pair<std::uint64_t, std::uint64_t> SmallMcapChunkOffsets(std::string_view compression) {
  const std::uint64_t first = SmallMcapPrefix().size();
  return {first, first + SmallMcapChunk1(compression).size() + McapMessageIndex(0).size()};
}

// --- ROS 1 ---

Bytes Ros1Magic() { return ToBytes("#ROSBAG V2.0\n"); }

Bytes Ros1HeaderBlock(const Ros1Fields& fields) {
  ByteWriter block;
  for (const auto& [name, value] : fields) {
    block.U32(static_cast<std::uint32_t>(name.size() + 1 + value.size())).Raw(name).Raw("=").Raw(value);
  }
  return block.Take();
}

Bytes Ros1Record(const Ros1Fields& fields, const Bytes& data) {
  return ByteWriter().BytesU32(Ros1HeaderBlock(fields)).BytesU32(data).Take();
}

Bytes Ros1BagHeader(std::uint64_t index_pos, std::uint32_t connections, std::uint32_t chunks) {
  const Ros1Fields fields = {{"op", {0x03}},
                             {"index_pos", U64Bytes(index_pos)},
                             {"conn_count", U32Bytes(connections)},
                             {"chunk_count", U32Bytes(chunks)}};
  const std::size_t header_size = Ros1HeaderBlock(fields).size();
  return Ros1Record(fields, Bytes(4096 - 8 - header_size, ' '));  // padded to 4096 bytes
}

Bytes Ros1Connection(std::uint32_t conn, std::string_view topic, std::string_view type, bool latching) {
  Ros1Fields details = {{"topic", ToBytes(topic)},
                        {"type", ToBytes(type)},
                        {"md5sum", ToBytes("90c7ef2dc6895d81024acba2ac42f369")},
                        {"message_definition", ToBytes("float32 x\n")}};
  if (latching) details.push_back({"latching", ToBytes("1")});
  return Ros1Record({{"op", {0x07}}, {"conn", U32Bytes(conn)}, {"topic", ToBytes(topic)}}, Ros1HeaderBlock(details));
}

Bytes Ros1MessageData(std::uint32_t conn, std::uint32_t sec, std::uint32_t nsec, std::string_view data) {
  return Ros1Record({{"op", {0x02}}, {"conn", U32Bytes(conn)}, {"time", ByteWriter().U32(sec).U32(nsec).Take()}},
                    ToBytes(data));
}

Bytes Ros1Chunk(const Bytes& records, std::string_view compression) {
  Bytes stored = records;
  if (compression == "bz2") stored = Bz2Compress(records);
  if (compression == "lz4") stored = Lz4FrameCompress(records);
  return Ros1Record({{"op", {0x05}},
                     {"compression", ToBytes(compression)},
                     {"size", U32Bytes(static_cast<std::uint32_t>(records.size()))}},
                    stored);
}

Bytes Ros1IndexData(std::uint32_t conn) {
  return Ros1Record({{"op", {0x04}}, {"ver", U32Bytes(1)}, {"conn", U32Bytes(conn)}, {"count", U32Bytes(1)}},
                    ByteWriter().U32(1).U32(500000000).U32(0).Take());
}

Bytes Ros1ChunkInfo(std::uint64_t chunk_pos) {
  return Ros1Record({{"op", {0x06}},
                     {"ver", U32Bytes(1)},
                     {"chunk_pos", U64Bytes(chunk_pos)},
                     {"start_time", U64Bytes(1)},
                     {"end_time", U64Bytes(3)},
                     {"count", U32Bytes(1)}},
                    ByteWriter().U32(0).U32(1).Take());
}

Bytes SmallRos1Bag(std::string_view compression, bool indexed) {
  const Bytes chunk1 = Ros1Chunk(Concat({Ros1Connection(0, "/scan", "sensor_msgs/LaserScan"),
                                         Ros1Connection(1, "/tf_static", "tf2_msgs/TFMessage", true),
                                         Ros1MessageData(0, 1, 500000000, "scan-1"), Ros1MessageData(1, 2, 0, "tf-1")}),
                                 compression);
  const Bytes chunk2 = Ros1Chunk(Ros1MessageData(0, 3, 0, "scan-2"), compression);
  const Bytes data = Concat({chunk1, Ros1IndexData(0), Ros1IndexData(1), chunk2, Ros1IndexData(0)});
  const std::uint64_t first_chunk = Ros1Magic().size() + 4096;
  if (!indexed) return Concat({Ros1Magic(), Ros1BagHeader(0, 0, 0), data});
  const Bytes index = Concat({Ros1Connection(0, "/scan", "sensor_msgs/LaserScan"),
                              Ros1Connection(1, "/tf_static", "tf2_msgs/TFMessage", true), Ros1ChunkInfo(first_chunk),
                              Ros1ChunkInfo(first_chunk + chunk1.size())});
  return Concat({Ros1Magic(), Ros1BagHeader(first_chunk + data.size(), 2, 2), data, index});
}

// --- SQLite ---

TestDatabase::TestDatabase(const std::string& path) {
  if (sqlite3_open(path.c_str(), &db_) != SQLITE_OK) throw std::runtime_error("cannot create " + path);
}

TestDatabase::~TestDatabase() { sqlite3_close(db_); }

void TestDatabase::Exec(const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error != nullptr ? error : "?";
    sqlite3_free(error);
    throw std::runtime_error(message + " in: " + sql);
  }
}

void TestDatabase::InsertMessage(std::int64_t id, std::int64_t topic_id, std::int64_t timestamp,
                                 std::span<const std::uint8_t> data) {
  sqlite3_stmt* statement = nullptr;
  sqlite3_prepare_v2(db_, "INSERT INTO messages (id, topic_id, timestamp, data) VALUES (?, ?, ?, ?)", -1, &statement,
                     nullptr);
  sqlite3_bind_int64(statement, 1, id);
  sqlite3_bind_int64(statement, 2, topic_id);
  sqlite3_bind_int64(statement, 3, timestamp);
  sqlite3_bind_blob(statement, 4, data.data(), static_cast<int>(data.size()), SQLITE_TRANSIENT);
  const int rc = sqlite3_step(statement);
  sqlite3_finalize(statement);
  if (rc != SQLITE_DONE) throw std::runtime_error("insert failed");
}

void WriteHumbleDb3(const std::string& path) {
  std::filesystem::remove(path);
  TestDatabase db(path);
  db.Exec("PRAGMA page_size = 512");
  db.Exec(
      "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
      "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL);"
      "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, "
      "data BLOB NOT NULL);"
      "CREATE INDEX timestamp_idx ON messages (timestamp ASC);");
  db.Exec("INSERT INTO topics VALUES (1, '/scan', 'sensor_msgs/msg/LaserScan', 'cdr', '');");
  db.Exec("INSERT INTO topics VALUES (2, '/tf_static', 'tf2_msgs/msg/TFMessage', 'cdr', '" + HumbleLatchedQos() +
          "');");
  db.InsertMessage(1, 1, 300, ToBytes("scan-3"));
  db.InsertMessage(2, 1, 100, ToBytes("scan-1"));
  db.InsertMessage(3, 2, 200, ToBytes("tf-1"));
  db.InsertMessage(4, 1, 200, ToBytes("scan-2"));
}

// --- files ---

std::string FreshTempDir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("slamtune_containers_" + std::to_string(::getpid())) / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

void WriteFile(const std::string& path, std::span<const std::uint8_t> bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

Bytes ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path);
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::string Byte(std::uint64_t offset) { return "byte " + std::to_string(offset); }

MessageCallback Collect(std::vector<Delivered>* out) {
  return [out](const RecordedTopic& topic, const RecordedMessage& message) {
    std::string data;
    if (!message.data.empty()) data.assign(reinterpret_cast<const char*>(message.data.data()), message.data.size());
    out->push_back({topic.name, message.log_time_ns, data, message.location.ToString(), message.location.file});
  };
}

void ExpectScanTopic(const RecordedTopic& topic, const std::string& type, MessageSerialization serialization,
                     std::size_t messages) {
  EXPECT_EQ(topic.name, "/scan");
  EXPECT_EQ(topic.type, type);
  EXPECT_EQ(topic.serialization, serialization);
  EXPECT_FALSE(topic.latched);
  EXPECT_EQ(topic.messages, messages);
}

FuzzOutcome FuzzReader(const Bytes& bytes, std::size_t corruptions, const std::function<void(const Bytes&)>& read,
                       std::size_t truncation_step) {
  FuzzOutcome outcome;
  const auto attempt = [&](const Bytes& input, const std::string& what) {
    ++outcome.reads;
    try {
      read(input);
      ++outcome.succeeded;
    } catch (const InputError&) {
      ++outcome.input_errors;
    } catch (const std::exception& e) {
      outcome.other_failures.push_back(what + ": " + e.what());
    } catch (...) {
      outcome.other_failures.push_back(what + ": a non-standard exception");
    }
  };
  for (std::size_t n = 0; n < bytes.size(); n += truncation_step) {
    attempt(Bytes(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n)), "truncated to " + std::to_string(n));
  }
  std::mt19937 random(42);
  std::uniform_int_distribution<std::size_t> position(0, bytes.size() - 1);
  std::uniform_int_distribution<int> value(0, 255);
  for (std::size_t i = 0; i < corruptions; ++i) {
    Bytes corrupt = bytes;
    const std::size_t at = position(random);
    corrupt[at] = static_cast<std::uint8_t>(value(random));
    attempt(corrupt, "byte " + std::to_string(at) + " set to " + std::to_string(corrupt[at]));
  }
  return outcome;
}

void ExpectEveryDamageReadOrRefused(ContainerFormat format, const Bytes& bytes, const std::string& name) {
  for (const bool lenient : {false, true}) {
    SCOPED_TRACE(lenient ? "lenient" : "strict");
    const FuzzOutcome outcome = FuzzReader(bytes, 400, [&](const Bytes& damaged) {
      ReadContainerBytes(format, damaged, name, {.lenient = lenient},
                         [](const RecordedTopic&, const RecordedMessage&) {});
    });
    EXPECT_THAT(outcome.other_failures, ::testing::IsEmpty());
    EXPECT_GT(outcome.succeeded, 0u);
    if (!lenient) {
      EXPECT_GT(outcome.input_errors, 0u);
    }
  }
}

ContainerRead ReadBytesAs(ContainerFormat format, const Bytes& bytes, const std::string& name,
                          ContainerReadOptions options) {
  ContainerRead read;
  try {
    read.summary = ReadContainerBytes(format, bytes, name, options, Collect(&read.messages));
  } catch (const InputError& e) {
    read.error = e.what();
  }
  return read;
}

ContainerRead ReadFileAs(ContainerFormat format, const std::string& path, ContainerReadOptions options) {
  ContainerRead read;
  try {
    read.summary = ReadContainerFile(format, path, options, Collect(&read.messages));
  } catch (const InputError& e) {
    read.error = e.what();
  }
  return read;
}

}  // namespace slamtune::io::testing
