#include "slamtune/io/ros/mcap_reader.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_recording.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using ::testing::ElementsAre;
using ::testing::EndsWith;
using ::testing::HasSubstr;
using ::testing::StartsWith;
using namespace testing;  // NOLINT: the record builders

// The reading of `bytes` as "m.mcap", and the error it gave ("" when none).
ContainerRead ReadAsMcap(const Bytes& bytes, ContainerReadOptions options = {}) {
  return ReadBytesAs(ContainerFormat::kMcap, bytes, "m.mcap", options);
}

// The offset just past the record that starts at `offset`.
std::uint64_t RecordEnd(const Bytes& bytes, std::uint64_t offset) {
  std::uint64_t length = 0;
  for (int i = 7; i >= 0; --i) length = (length << 8) | bytes[offset + 1 + i];
  return offset + 9 + length;
}

Bytes Prefix(const Bytes& bytes, std::uint64_t size) { return Bytes(bytes.begin(), bytes.begin() + size); }

Bytes Closing() { return Concat({McapDataEnd(), McapFooter(), McapMagic()}); }
Bytes McapOpening() { return Concat({McapMagic(), McapHeader()}); }

std::string Names(const std::vector<Delivered>& messages) {
  std::string names;
  for (const Delivered& m : messages) names += m.data + "@" + std::to_string(m.log_time_ns) + "/" + m.location + " ";
  return names;
}

TEST(McapReaderTest, ReadsChunksOfEachCompressionWithSchemasAndChannelsKeptAcrossChunks) {
  for (const std::string compression : {"", "zstd", "lz4"}) {
    SCOPED_TRACE(compression);
    const ContainerRead read = ReadAsMcap(SmallMcap(compression));
    ASSERT_EQ(read.error, "");
    const auto [chunk1, chunk2] = SmallMcapChunkOffsets(compression);
    // Chunk 2 holds only messages: its channel 0 (/scan) was declared in chunk 1.
    EXPECT_EQ(Names(read.messages), "scan-1@100/" + Byte(chunk1) + " tf-1@150/" + Byte(chunk1) + " scan-2@200/" +
                                        Byte(chunk2) + " scan-3@300/" + Byte(chunk2) + " ");
    EXPECT_EQ(read.messages[1].topic, "/tf_static");
    EXPECT_EQ(read.messages[0].file, "m.mcap");
    const ContainerSummary& s = read.summary;
    ASSERT_EQ(s.topics.size(), 2u);
    ExpectScanTopic(s.topics[0], "sensor_msgs/msg/LaserScan", MessageSerialization::kCdr, 3);
    EXPECT_EQ(s.topics[1].type, "tf2_msgs/msg/TFMessage");
    EXPECT_TRUE(s.topics[1].latched);
    EXPECT_EQ(s.messages, 4u);
    EXPECT_EQ(s.chunks, 2u);
    EXPECT_EQ(s.chunk_compression.at(compression.empty() ? "none" : compression), 2u);
    EXPECT_EQ(s.skipped_records, 5u);  // Metadata, 2 MessageIndex, the summary's Schema and Channel
    EXPECT_EQ(s.unknown_records, 0u);
    EXPECT_EQ(s.profile, "ros2");
    EXPECT_EQ(s.ros_distro, "jazzy");
    EXPECT_TRUE(s.data_end.complete);
    EXPECT_EQ(s.data_end.how, "data end record and footer");
    EXPECT_THAT(s.files, ElementsAre("m.mcap"));
  }
}

TEST(McapReaderTest, UnchunkedRecordsChannelIdZeroAndUnknownOrUserOpcodes) {
  const Bytes head = Concat({McapOpening(), McapSchema(1, "nav_msgs/msg/Odometry"), McapChannel(0, 1, "/odom")});
  const Bytes bytes = Concat({head, McapMessage(0, 5, "odom-1"), McapRecord(0x42, ToBytes("future")),
                              McapRecord(0x90, ToBytes("user")), McapRecord(0x00, {}), Closing()});
  const ContainerRead read = ReadAsMcap(bytes);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(Names(read.messages), "odom-1@5/" + Byte(head.size()) + " ");
  EXPECT_EQ(read.summary.unknown_records, 2u);  // 0x42 and 0x00
  EXPECT_EQ(read.summary.skipped_records, 1u);  // 0x90, a user extension
  EXPECT_EQ(read.summary.chunks, 0u);
}

TEST(McapReaderTest, AFileCutAfterACompleteChunkReadsAsIncomplete) {
  const Bytes full = SmallMcap("zstd");
  const std::uint64_t chunk2 = SmallMcapChunkOffsets("zstd").second;
  const ContainerRead read = ReadAsMcap(Prefix(full, RecordEnd(full, chunk2)));
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.messages.size(), 4u);
  EXPECT_FALSE(read.summary.data_end.complete);
  EXPECT_EQ(read.summary.data_end.how,
            "no data end record: the file ends after a complete record (recording cut off?)");
  EXPECT_EQ(read.summary.data_end.dropped_bytes, 0u);
}

// A file that ends inside a record (a power loss while recording) reads up to its last whole
// record, lenient or not, and says how many bytes were not read.
TEST(McapReaderTest, AFileCutInsideAChunkReadsUpToItsLastWholeRecord) {
  const Bytes full = SmallMcap("zstd");
  const std::uint64_t chunk2 = SmallMcapChunkOffsets("zstd").second;
  const Bytes cut = Prefix(full, RecordEnd(full, chunk2) - 5);
  for (const bool lenient : {false, true}) {
    const ContainerRead read = ReadAsMcap(cut, {.lenient = lenient});
    ASSERT_EQ(read.error, "");
    EXPECT_EQ(read.messages.size(), 2u);  // chunk 1's
    EXPECT_EQ(read.summary.data_end.dropped_bytes, cut.size() - chunk2);
    EXPECT_THAT(read.summary.data_end.dropped_reason,
                StartsWith("m.mcap: " + Byte(chunk2) + " (Chunk record): content "));
    EXPECT_FALSE(read.summary.data_end.complete);
    EXPECT_THAT(read.summary.data_end.how, StartsWith(fmt::format("cut off inside a record: read up to its last whole "
                                                                  "record, the last {} bytes (",
                                                                  cut.size() - chunk2)));
  }
  // Cut inside the opcode and length of a record: the same.
  EXPECT_EQ(ReadAsMcap(Prefix(full, chunk2 + 4)).summary.data_end.dropped_bytes, 4u);
}

// A corrupt record inside the file is an error that says what --lenient does.
TEST(McapReaderTest, ACorruptRecordIsAnErrorNamingLenient) {
  Bytes bad = SmallMcap("zstd");
  const std::uint64_t chunk2 = SmallMcapChunkOffsets("zstd").second;
  const std::string zstd = "zstd";
  const auto name = std::search(bad.begin() + static_cast<std::ptrdiff_t>(chunk2), bad.end(), zstd.begin(), zstd.end());
  ASSERT_NE(name, bad.end());
  name[3] = 'x';  // the chunk's compression: "zstx"
  const ContainerRead strict = ReadAsMcap(bad);
  EXPECT_THAT(strict.error, StartsWith("m.mcap: " + Byte(chunk2)));
  EXPECT_THAT(strict.error, EndsWith(" (--lenient reads the recording up to this record)"));
  const ContainerRead lenient = ReadAsMcap(bad, {.lenient = true});
  ASSERT_EQ(lenient.error, "");
  EXPECT_THAT(lenient.summary.data_end.how, StartsWith("a corrupt record: read up to it (--lenient)"));
}

TEST(McapReaderTest, ABadChunkCrcIsAnErrorUnlessCrcsAreNotVerified) {
  const Bytes records = Concat({McapSchema(1, "S"), McapChannel(1, 1, "/a"), McapMessage(1, 9, "a")});
  const Bytes bad = Concat({McapOpening(), McapChunk(records, "lz4", 0x12345678), Closing()});
  EXPECT_THAT(ReadAsMcap(bad).error, StartsWith("m.mcap: " + Byte(McapOpening().size()) + " (chunk): CRC mismatch: "));
  EXPECT_THAT(ReadAsMcap(bad).error, HasSubstr("the chunk says 12345678"));
  EXPECT_EQ(ReadAsMcap(bad, {.verify_crc = false}).messages.size(), 1u);
  const Bytes unchecked = Concat({McapOpening(), McapChunk(records, "zstd", 0), Closing()});  // CRC 0: not checked
  EXPECT_EQ(ReadAsMcap(unchecked).messages.size(), 1u);
}

TEST(McapReaderTest, UnknownCompressionAndCorruptZstdAreErrorsAtTheChunk) {
  const Bytes records = Concat({McapSchema(1, "S"), McapChannel(1, 1, "/a"), McapMessage(1, 9, "payload")});
  Bytes chunk = McapChunk(records, "zstd");
  const Bytes brotli = Concat({McapOpening(), McapChunk(records, "brotli"), Closing()});
  EXPECT_EQ(ReadAsMcap(brotli).error,
            "m.mcap: " + Byte(McapOpening().size()) + " (chunk): unknown compression \"brotli\"" + kLenientHint);
  chunk[chunk.size() - ZstdCompress(records).size()] ^= 0xFF;  // the zstd frame's magic
  const ContainerRead corrupt = ReadAsMcap(Concat({McapOpening(), chunk, Closing()}));
  EXPECT_EQ(corrupt.error,
            "m.mcap: " + Byte(McapOpening().size()) + " (chunk): zstd: Unknown frame descriptor" + kLenientHint);
}

TEST(McapReaderTest, AMessageOnAnUndeclaredChannelRefusesItsWholeChunk) {
  const Bytes declarations = Concat({McapSchema(1, "S"), McapChannel(1, 1, "/a")});
  const Bytes first = Concat({McapOpening(), declarations, McapMessage(1, 1, "before")});
  const Bytes records = Concat({McapMessage(1, 2, "in chunk"), McapMessage(5, 3, "orphan")});
  const Bytes bytes = Concat({first, McapChunk(records, "zstd"), Closing()});
  EXPECT_EQ(ReadAsMcap(bytes).error, "m.mcap: " + Byte(first.size()) + " (chunk), uncompressed " +
                                         Byte(McapMessage(1, 2, "in chunk").size()) +
                                         " (Message): message on channel 5, which was never declared" + kLenientHint);
  const ContainerRead lenient = ReadAsMcap(bytes, {.lenient = true});
  EXPECT_EQ(Names(lenient.messages), "before@1/" + Byte(McapOpening().size() + declarations.size()) + " ");
  EXPECT_EQ(lenient.summary.chunks, 0u);
}

TEST(McapReaderTest, AChannelWhoseSchemaIsMissingIsAnError) {
  const Bytes bytes = Concat({McapOpening(), McapSchema(1, "S"), McapChannel(3, 9, "/odom"), Closing()});
  EXPECT_EQ(ReadAsMcap(bytes).error, "m.mcap: " + Byte(McapOpening().size() + McapSchema(1, "S").size()) +
                                         " (Channel): channel 3 (/odom) names schema 9, which was never declared" +
                                         kLenientHint);
  // Schema id 0 means "no schema".
  EXPECT_EQ(ReadAsMcap(Concat({McapOpening(), McapChannel(3, 0, "/odom"), Closing()})).error, "");
}

TEST(McapReaderTest, RepeatedSchemaAndChannelIdsKeepTheFirstDeclaration) {
  const Bytes bytes =
      Concat({McapOpening(), McapSchema(1, "First"), McapChannel(2, 1, "/first"), McapSchema(1, "Second"),
              McapChunk(Concat({McapChannel(2, 1, "/second"), McapMessage(2, 1, "m")}), "lz4"), Closing()});
  const ContainerRead read = ReadAsMcap(bytes);
  ASSERT_EQ(read.error, "");
  ASSERT_EQ(read.summary.topics.size(), 1u);
  EXPECT_EQ(read.summary.topics[0].name, "/first");
  EXPECT_EQ(read.summary.topics[0].type, "First");
  EXPECT_EQ(read.summary.topics[0].messages, 1u);
}

TEST(McapReaderTest, ChannelsOfOneTopicMergeAndOtherEncodingsAreMarkedInTheType) {
  const Bytes bytes = Concat({McapOpening(), McapSchema(1, "tf2_msgs/msg/TFMessage"), McapChannel(0, 1, "/tf"),
                              McapChannel(1, 1, "/tf"), McapSchema(2, "sensor_msgs/LaserScan", "ros1msg"),
                              McapChannel(2, 2, "/scan", "ros1", {{"latching", "1"}}),
                              McapSchema(3, "foo.Bar", "jsonschema"), McapChannel(3, 3, "/json", "json"),
                              McapChannel(4, 0, "/raw", "protobuf"), McapMessage(0, 1, "a"), McapMessage(1, 2, "b"),
                              McapMessage(2, 3, "c"), McapMessage(3, 4, "{}"), McapMessage(4, 5, "p"), Closing()});
  const ContainerRead read = ReadAsMcap(bytes);
  ASSERT_EQ(read.error, "");
  const auto& topics = read.summary.topics;
  ASSERT_EQ(topics.size(), 4u);
  EXPECT_EQ(topics[0].name, "/tf");
  EXPECT_EQ(topics[0].messages, 2u);  // two publishers, one topic
  EXPECT_EQ(topics[1].serialization, MessageSerialization::kRos1);
  EXPECT_EQ(topics[1].type, "sensor_msgs/LaserScan");
  EXPECT_TRUE(topics[1].latched);
  EXPECT_EQ(topics[2].type, "foo.Bar (json encoding)");
  EXPECT_EQ(topics[3].type, "(protobuf encoding)");
  EXPECT_EQ(read.messages.size(), 5u);
}

TEST(McapReaderTest, CallbackExceptionsPassThroughUnchangedEvenWhenLenient) {
  const MessageCallback stop = [](const RecordedTopic&, const RecordedMessage&) { throw InputError("stop here"); };
  try {
    ReadContainerBytes(ContainerFormat::kMcap, SmallMcap("zstd"), "m.mcap", {.lenient = true}, stop);
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "stop here");
  }
  const MessageCallback other = [](const RecordedTopic&, const RecordedMessage&) { throw std::out_of_range("x"); };
  EXPECT_THROW(ReadContainerBytes(ContainerFormat::kMcap, SmallMcap(""), "m.mcap", {}, other), std::out_of_range);
}

TEST(McapReaderTest, NotMcapAndAHeaderThatIsNotFirstAreErrors) {
  EXPECT_EQ(ReadAsMcap(ToBytes("#ROSBAG V2.0\n")).error,
            "m.mcap: byte 0 (magic): not an MCAP file (no \\x89MCAP0\\r\\n magic)");
  EXPECT_EQ(ReadAsMcap(Concat({McapMagic(), McapDataEnd()})).error,
            "m.mcap: byte 8 (DataEnd record): the first record is not the Header");
  const ContainerRead magic_only = ReadAsMcap(McapMagic());
  EXPECT_EQ(magic_only.error, "");
  EXPECT_FALSE(magic_only.summary.data_end.complete);
}

TEST(McapReaderTest, ReadsAFileByPathAndNamesAMissingOne) {
  const std::string path = FreshTempDir("mcap_file") + "/drive.mcap";
  WriteFile(path, SmallMcap("lz4"));
  std::vector<Delivered> messages;
  const ContainerSummary summary = ReadContainerFile(ContainerFormat::kMcap, path, {}, Collect(&messages));
  EXPECT_THAT(summary.files, ElementsAre(path));
  ASSERT_EQ(messages.size(), 4u);
  EXPECT_EQ(messages[3].file, path);
  try {
    ReadContainerFile(ContainerFormat::kMcap, path + ".missing", {}, Collect(&messages));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ".missing: cannot open (No such file or directory)");
  }
}

TEST(McapReaderTest, EveryTruncationAndRandomCorruptionSucceedsOrThrowsInputError) {
  for (const std::string compression : {"", "zstd", "lz4"}) {
    SCOPED_TRACE(compression);
    ExpectEveryDamageReadOrRefused(ContainerFormat::kMcap, SmallMcap(compression), "fuzz.mcap");
  }
}

}  // namespace
}  // namespace slamtune::io
