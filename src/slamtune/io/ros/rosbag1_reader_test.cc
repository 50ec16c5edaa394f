#include "slamtune/io/ros/rosbag1_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_recording.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using ::testing::StartsWith;
using namespace testing;  // NOLINT: the record builders

constexpr std::uint64_t kFirstChunk = 13 + 4096;  // after the version line and the padded bag header

ContainerRead ReadAsBag(const Bytes& bytes, ContainerReadOptions options = {}) {
  return ReadBytesAs(ContainerFormat::kRosbag1, bytes, "b.bag", options);
}

// The offset of SmallRos1Bag's second chunk.
std::uint64_t SecondChunk(std::string_view compression) {
  const Bytes chunk1 = Ros1Chunk(Concat({Ros1Connection(0, "/scan", "sensor_msgs/LaserScan"),
                                         Ros1Connection(1, "/tf_static", "tf2_msgs/TFMessage", true),
                                         Ros1MessageData(0, 1, 500000000, "scan-1"), Ros1MessageData(1, 2, 0, "tf-1")}),
                                 compression);
  return kFirstChunk + chunk1.size() + Ros1IndexData(0).size() + Ros1IndexData(1).size();
}

Bytes BagOpening() { return Concat({Ros1Magic(), Ros1BagHeader(0, 0, 0)}); }

TEST(Rosbag1ReaderTest, ReadsChunksOfEachCompressionAndIgnoresTheIndexsRepeatedConnections) {
  for (const std::string compression : {"none", "bz2", "lz4"}) {
    SCOPED_TRACE(compression);
    const ContainerRead read = ReadAsBag(SmallRos1Bag(compression));
    ASSERT_EQ(read.error, "");
    const std::uint64_t second = SecondChunk(compression);
    ASSERT_EQ(read.messages.size(), 3u);
    EXPECT_EQ(read.messages[0].data, "scan-1");
    EXPECT_EQ(read.messages[0].log_time_ns, 1'500'000'000);
    EXPECT_EQ(read.messages[0].location, Byte(kFirstChunk));
    EXPECT_EQ(read.messages[1].topic, "/tf_static");
    EXPECT_EQ(read.messages[1].log_time_ns, 2'000'000'000);
    EXPECT_EQ(read.messages[2].data, "scan-2");
    EXPECT_EQ(read.messages[2].location, Byte(second));
    EXPECT_EQ(read.messages[2].file, "b.bag");
    const ContainerSummary& s = read.summary;
    ASSERT_EQ(s.topics.size(), 2u);
    ExpectScanTopic(s.topics[0], "sensor_msgs/LaserScan", MessageSerialization::kRos1, 2);
    EXPECT_TRUE(s.topics[1].latched);
    EXPECT_EQ(s.chunks, 2u);
    EXPECT_EQ(s.chunk_compression.at(compression), 2u);
    EXPECT_EQ(s.skipped_records, 5u);  // 3 index data, 2 chunk info
    EXPECT_EQ(s.unknown_records, 0u);
    EXPECT_TRUE(s.data_end.complete);
    EXPECT_THAT(s.data_end.how, StartsWith("index"));
    EXPECT_EQ(s.profile, "ros1");
  }
}

TEST(Rosbag1ReaderTest, AnUnindexedBagOrOneCutBeforeItsIndexReadsAsIncomplete) {
  const ContainerRead unindexed = ReadAsBag(SmallRos1Bag("lz4", /*indexed=*/false));
  ASSERT_EQ(unindexed.error, "");
  EXPECT_EQ(unindexed.messages.size(), 3u);
  EXPECT_FALSE(unindexed.summary.data_end.complete);
  EXPECT_EQ(unindexed.summary.data_end.how,
            "no index (the bag header's index_pos is 0): the file ends after a complete "
            "record (recording cut off?)");
  const Bytes indexed = SmallRos1Bag("none");
  const std::size_t index_size = Ros1Connection(0, "/scan", "sensor_msgs/LaserScan").size() +
                                 Ros1Connection(1, "/tf_static", "tf2_msgs/TFMessage", true).size() +
                                 2 * Ros1ChunkInfo(0).size();
  const Bytes cut(indexed.begin(), indexed.end() - static_cast<std::ptrdiff_t>(index_size));
  const ContainerRead before_index = ReadAsBag(cut);
  ASSERT_EQ(before_index.error, "");
  EXPECT_FALSE(before_index.summary.data_end.complete);
  EXPECT_EQ(before_index.summary.data_end.how, "no index at index_pos " + std::to_string(cut.size()) +
                                                   ": the file ends after a complete record (recording cut off?)");
}

// A bag that ends inside a record (a power loss while recording) reads up to its last whole
// record, lenient or not, and says how many bytes were not read.
TEST(Rosbag1ReaderTest, ABagCutInsideAChunkReadsUpToItsLastWholeRecord) {
  const Bytes full = SmallRos1Bag("bz2", /*indexed=*/false);
  const std::uint64_t second = SecondChunk("bz2");
  for (const std::uint64_t kept : {2, 60}) {  // inside the header length, inside the data
    const Bytes cut(full.begin(), full.begin() + static_cast<std::ptrdiff_t>(second + kept));
    for (const bool lenient : {false, true}) {
      const ContainerRead read = ReadAsBag(cut, {.lenient = lenient});
      ASSERT_EQ(read.error, "");
      EXPECT_EQ(read.messages.size(), 2u);
      EXPECT_EQ(read.summary.data_end.dropped_bytes, kept);
      EXPECT_FALSE(read.summary.data_end.complete);
      EXPECT_THAT(read.summary.data_end.how, StartsWith("cut off inside a record: read up to its last whole record"));
    }
  }
}

TEST(Rosbag1ReaderTest, AMessageOnAnUndeclaredConnectionIsAnErrorInsideItsChunk) {
  const Bytes records = Concat({Ros1Connection(0, "/scan", "sensor_msgs/LaserScan"), Ros1MessageData(7, 1, 0, "x")});
  const ContainerRead read = ReadAsBag(Concat({BagOpening(), Ros1Chunk(records, "lz4")}));
  EXPECT_EQ(read.error, "b.bag: " + Byte(kFirstChunk) + " (chunk), uncompressed " +
                            Byte(Ros1Connection(0, "/scan", "sensor_msgs/LaserScan").size()) +
                            " (message data record): message on connection 7, which was never declared" + kLenientHint);
}

TEST(Rosbag1ReaderTest, UnknownOrCorruptChunkCompressionIsAnErrorAtTheChunk) {
  const Bytes records = Ros1Connection(0, "/scan", "sensor_msgs/LaserScan");
  EXPECT_EQ(ReadAsBag(Concat({BagOpening(), Ros1Chunk(records, "brotli")})).error,
            "b.bag: " + Byte(kFirstChunk) + " (chunk record): unknown compression \"brotli\"" + kLenientHint);
  const Bytes fake_bz2 = Ros1Record(
      {{"op", {0x05}}, {"compression", ToBytes("bz2")}, {"size", ByteWriter().U32(10).Take()}}, ToBytes("not bz2"));
  EXPECT_EQ(
      ReadAsBag(Concat({BagOpening(), fake_bz2})).error,
      "b.bag: " + Byte(kFirstChunk) + " (chunk record): bz2: BZ_DATA_ERROR_MAGIC (not bzip2 data)" + kLenientHint);
}

TEST(Rosbag1ReaderTest, TopLevelMessagesUnknownOpsAndMalformedHeaders) {
  const Bytes good = Concat({BagOpening(), Ros1Connection(3, "/odom", "nav_msgs/Odometry"),
                             Ros1MessageData(3, 10, 5, "odom"), Ros1Record({{"op", {0x09}}}, {})});
  const ContainerRead read = ReadAsBag(good);
  ASSERT_EQ(read.error, "");
  ASSERT_EQ(read.messages.size(), 1u);
  EXPECT_EQ(read.messages[0].log_time_ns, 10'000'000'005);
  EXPECT_EQ(read.messages[0].location, Byte(kFirstChunk + Ros1Connection(3, "/odom", "nav_msgs/Odometry").size()));
  EXPECT_EQ(read.summary.unknown_records, 1u);
  EXPECT_EQ(read.summary.chunks, 0u);

  EXPECT_EQ(ReadAsBag(Concat({BagOpening(), Ros1Record({{"op", {0x07}}, {"topic", ToBytes("/a")}}, {})})).error,
            "b.bag: " + Byte(kFirstChunk) + " (connection record): no field conn" + kLenientHint);
  EXPECT_EQ(
      ReadAsBag(Concat({BagOpening(), Ros1Record({{"op", {0x02}}, {"conn", {1, 0}}}, {})})).error,
      "b.bag: " + Byte(kFirstChunk) + " (message data record): field conn has 2 bytes, expected 4" + kLenientHint);
  EXPECT_EQ(ReadAsBag(Concat({Ros1Magic(), Ros1Connection(0, "/a", "T")})).error,
            "b.bag: byte 13 (connection record): the first record is not the bag header");
  EXPECT_EQ(ReadAsBag(ToBytes("#ROSBAG V1.2\n")).error,
            "b.bag: byte 0 (version line): not a ROS 1 bag v2.0 (no #ROSBAG V2.0 line)");
}

TEST(Rosbag1ReaderTest, ReadsAFileByPath) {
  const std::string path = FreshTempDir("rosbag1_file") + "/noetic.bag";
  WriteFile(path, SmallRos1Bag("lz4"));
  std::vector<Delivered> messages;
  const ContainerSummary summary = ReadContainerFile(ContainerFormat::kRosbag1, path, {}, Collect(&messages));
  EXPECT_THAT(summary.files, ::testing::ElementsAre(path));
  EXPECT_EQ(summary.format, ContainerFormat::kRosbag1);
  ASSERT_EQ(messages.size(), 3u);
  EXPECT_EQ(messages[0].file, path);
}

TEST(Rosbag1ReaderTest, EveryTruncationAndRandomCorruptionSucceedsOrThrowsInputError) {
  for (const std::string compression : {"none", "bz2", "lz4"}) {
    SCOPED_TRACE(compression);
    ExpectEveryDamageReadOrRefused(ContainerFormat::kRosbag1, SmallRos1Bag(compression), "fuzz.bag");
  }
}

}  // namespace
}  // namespace slamtune::io
