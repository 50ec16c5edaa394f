#include "slamtune/io/ros/ros_recording.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/io/ros/rosbag2_folder.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using ::testing::HasSubstr;
using namespace testing;  // NOLINT: the recording builders

struct RecordingRead {
  ContainerSummary summary;
  std::vector<Delivered> messages;
  std::string error;
};

RecordingRead ReadRecording(const std::string& path, ContainerReadOptions options = {}) {
  RecordingRead read;
  try {
    read.summary = ReadRosRecording(path, options, Collect(&read.messages));
  } catch (const InputError& e) {
    read.error = e.what();
  }
  return read;
}

// metadata.yaml as rosbag2 writes it (the fields the reader does not use shortened).
std::string MetadataYaml(const std::string& storage, const std::vector<std::string>& files,
                         const std::string& mode = "", const std::string& format = "") {
  std::string yaml = "rosbag2_bagfile_information:\n  version: 5\n  storage_identifier: " + storage +
                     "\n  duration:\n    nanoseconds: 200\n  message_count: 4\n  topics_with_message_count: []\n"
                     "  compression_format: \"" +
                     format + "\"\n  compression_mode: \"" + mode + "\"\n  relative_file_paths:\n";
  for (const std::string& file : files) yaml += "    - " + file + "\n";
  return yaml;
}

void WriteTextFile(const std::string& path, const std::string& text) { WriteFile(path, ToBytes(text)); }

// An MCAP split whose /scan channel has id `scan_channel`, with one more topic /odom.
Bytes McapSplit(std::uint16_t scan_channel, std::uint64_t t0, std::string_view suffix, bool zstd_payloads = false) {
  const auto payload = [&](std::string text) {
    const Bytes bytes = zstd_payloads ? ZstdCompress(ToBytes(text)) : ToBytes(text);
    return std::string(bytes.begin(), bytes.end());
  };
  return Concat({McapMagic(), McapHeader(), McapSchema(1, "sensor_msgs/msg/LaserScan"),
                 McapSchema(2, "nav_msgs/msg/Odometry"), McapChannel(scan_channel, 1, "/scan"),
                 McapChannel(9, 2, "/odom"), McapMessage(scan_channel, t0, payload("scan" + std::string(suffix))),
                 McapMessage(9, t0 + 1, payload("odom" + std::string(suffix))), McapDataEnd(), McapFooter(),
                 McapMagic()});
}

std::string Summary(const std::vector<Delivered>& messages) {
  std::string text;
  for (const Delivered& m : messages) {
    text += m.topic + ":" + m.data + "@" + std::to_string(m.log_time_ns) + " in " +
            std::filesystem::path(m.file).filename().string() + "; ";
  }
  return text;
}

TEST(RosRecordingTest, DetectsEachKindByContentNeverByName) {
  const std::string dir = FreshTempDir("detect");
  WriteFile(dir + "/a.bag", SmallMcap("zstd"));  // names lie: content decides
  WriteFile(dir + "/b.mcap", SmallRos1Bag("none"));
  WriteHumbleDb3(dir + "/c.txt");
  WriteFile(dir + "/d.db3", ZstdCompress(SmallMcap("")));
  WriteTextFile(dir + "/e.clf", "# CARMEN log\nODOM 0 0 0 0 0 0 1.0 host 1.0\n");
  WriteTextFile(dir + "/empty", "");
  gzFile gz = gzopen((dir + "/f.mcap").c_str(), "wb");
  gzputs(gz, "FLASER 0\n");
  gzclose(gz);
  EXPECT_EQ(DetectRecordingKind(dir + "/a.bag"), RecordingKind::kMcap);
  EXPECT_EQ(DetectRecordingKind(dir + "/b.mcap"), RecordingKind::kRosbag1);
  EXPECT_EQ(DetectRecordingKind(dir + "/c.txt"), RecordingKind::kRosbag2Sqlite);
  EXPECT_EQ(DetectRecordingKind(dir + "/d.db3"), RecordingKind::kZstdFile);
  EXPECT_EQ(DetectRecordingKind(dir + "/e.clf"), RecordingKind::kCarmenLog);
  EXPECT_EQ(DetectRecordingKind(dir + "/empty"), RecordingKind::kCarmenLog);
  EXPECT_EQ(DetectRecordingKind(dir + "/f.mcap"), RecordingKind::kCarmenLog);  // gzip: a CARMEN log
  EXPECT_EQ(slamtune::testing::ErrorMessageOf([&] { DetectRecordingKind(dir + "/nothing"); }),
            dir + "/nothing: cannot open (No such file or directory)");
  EXPECT_EQ(slamtune::testing::ErrorMessageOf([&] { DetectRecordingKind(dir); }),
            dir + ": a folder but not a rosbag2 bag (no metadata.yaml)");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"a.bag"}));
  EXPECT_EQ(DetectRecordingKind(dir), RecordingKind::kRosbag2Folder);
  EXPECT_STREQ(RecordingKindName(RecordingKind::kRosbag2Folder), "rosbag2 bag folder");
  EXPECT_STREQ(ContainerFormatName(ContainerFormat::kRosbag1), "ROS 1 bag v2.0");
  EXPECT_EQ((MessageLocation{MessageLocation::Kind::kRow, 17, ""}).ToString(), "row 17");
}

TEST(RosRecordingTest, ReadsEverySingleFileKindAndRefusesACarmenLog) {
  const std::string dir = FreshTempDir("single_files");
  WriteFile(dir + "/drive.mcap", SmallMcap("lz4"));
  WriteFile(dir + "/drive.bag", SmallRos1Bag("bz2"));
  WriteHumbleDb3(dir + "/drive.db3");
  WriteFile(dir + "/drive.mcap.zstd", ZstdCompress(SmallMcap("")));
  WriteFile(dir + "/drive.db3.zstd", ZstdCompress(ReadFile(dir + "/drive.db3")));
  struct Expected {
    std::string file;
    ContainerFormat format;
    std::size_t messages;
    std::string file_compression;
  };
  for (const Expected& e :
       {Expected{"drive.mcap", ContainerFormat::kMcap, 4, ""}, Expected{"drive.bag", ContainerFormat::kRosbag1, 3, ""},
        Expected{"drive.db3", ContainerFormat::kRosbag2Sqlite, 4, ""},
        Expected{"drive.mcap.zstd", ContainerFormat::kMcap, 4, "zstd"},
        Expected{"drive.db3.zstd", ContainerFormat::kRosbag2Sqlite, 4, "zstd"}}) {
    SCOPED_TRACE(e.file);
    const RecordingRead read = ReadRecording(dir + "/" + e.file);
    ASSERT_EQ(read.error, "");
    EXPECT_EQ(read.summary.format, e.format);
    EXPECT_EQ(read.messages.size(), e.messages);
    EXPECT_EQ(read.summary.file_compression, e.file_compression);
    EXPECT_THAT(read.summary.files, ::testing::ElementsAre(dir + "/" + e.file));
  }
  WriteTextFile(dir + "/intel.clf", "ODOM 0 0 0 0 0 0 1.0 host 1.0\n");
  EXPECT_EQ(ReadRecording(dir + "/intel.clf").error,
            dir +
                "/intel.clf: not a ROS recording (MCAP, rosbag2 SQLite3 or ROS 1 "
                "bag v2.0): it reads as a CARMEN log");
  WriteFile(dir + "/text.zstd", ZstdCompress(ToBytes("plain text")));
  EXPECT_THAT(ReadRecording(dir + "/text.zstd").error, HasSubstr("zstd-compressed, but what it holds is not"));
  Bytes cut = ZstdCompress(SmallMcap(""));
  cut.resize(cut.size() / 2);
  WriteFile(dir + "/cut.mcap.zstd", cut);
  EXPECT_THAT(ReadRecording(dir + "/cut.mcap.zstd").error,
              ::testing::StartsWith(dir + "/cut.mcap.zstd: zstd-compressed file: zstd: "));
}

TEST(RosRecordingTest, ABagFolderReadsItsSplitsInOrderWithTopicsMergedByName) {
  const std::string dir = FreshTempDir("two_splits");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"two_splits_0.mcap", "two_splits_1.mcap"}));
  WriteFile(dir + "/two_splits_0.mcap", McapSplit(0, 100, "-0"));
  WriteFile(dir + "/two_splits_1.mcap", McapSplit(4, 200, "-1"));  // /scan on another channel id
  const RecordingRead read = ReadRecording(dir);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(Summary(read.messages),
            "/scan:scan-0@100 in two_splits_0.mcap; /odom:odom-0@101 in two_splits_0.mcap; "
            "/scan:scan-1@200 in two_splits_1.mcap; /odom:odom-1@201 in two_splits_1.mcap; ");
  const ContainerSummary& s = read.summary;
  ASSERT_EQ(s.topics.size(), 2u);
  EXPECT_EQ(s.topics[0].name, "/scan");
  EXPECT_EQ(s.topics[0].messages, 2u);
  EXPECT_EQ(s.topics[1].messages, 2u);
  EXPECT_EQ(s.messages, 4u);
  EXPECT_THAT(s.files, ::testing::ElementsAre(dir + "/two_splits_0.mcap", dir + "/two_splits_1.mcap"));
  EXPECT_EQ(s.format, ContainerFormat::kMcap);
  EXPECT_TRUE(s.data_end.complete);
}

TEST(RosRecordingTest, FileCompressedSplitsAreDecompressedWhole) {
  const std::string dir = FreshTempDir("file_compressed");
  WriteTextFile(dir + "/metadata.yaml",
                MetadataYaml("sqlite3", {"file_compressed_0.db3.zstd", "file_compressed_1.db3"}, "FILE", "zstd"));
  WriteHumbleDb3(dir + "/plain.db3");
  WriteFile(dir + "/file_compressed_0.db3.zstd", ZstdCompress(ReadFile(dir + "/plain.db3")));
  // Listed without ".zstd", found with it.
  std::filesystem::rename(dir + "/plain.db3", dir + "/file_compressed_1.db3.zstd.tmp");
  WriteFile(dir + "/file_compressed_1.db3.zstd", ZstdCompress(ReadFile(dir + "/file_compressed_1.db3.zstd.tmp")));
  const RecordingRead read = ReadRecording(dir);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.messages.size(), 8u);
  EXPECT_EQ(read.summary.topics.size(), 2u);
  EXPECT_EQ(read.summary.topics[0].messages, 6u);
  EXPECT_EQ(read.summary.file_compression, "zstd");
  EXPECT_EQ(read.summary.format, ContainerFormat::kRosbag2Sqlite);
  EXPECT_EQ(read.messages[4].file, dir + "/file_compressed_1.db3.zstd");
}

TEST(RosRecordingTest, MessageCompressedPayloadsAreDecompressedForTheCallback) {
  const std::string dir = FreshTempDir("message_compressed");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"message_compressed_0.mcap"}, "MESSAGE", "zstd"));
  WriteFile(dir + "/message_compressed_0.mcap", McapSplit(1, 100, "-z", /*zstd_payloads=*/true));
  const RecordingRead read = ReadRecording(dir);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(Summary(read.messages),
            "/scan:scan-z@100 in message_compressed_0.mcap; "
            "/odom:odom-z@101 in message_compressed_0.mcap; ");
  EXPECT_EQ(read.summary.message_compression, "zstd");

  WriteFile(dir + "/message_compressed_0.mcap", McapSplit(1, 100, "-plain"));  // payloads not zstd
  EXPECT_THAT(ReadRecording(dir).error, HasSubstr("message_compressed_0.mcap: byte "));
  EXPECT_THAT(ReadRecording(dir).error, HasSubstr("(message): zstd: "));
}

TEST(RosRecordingTest, AMissingSplitOrAnUnusableMetadataFileIsNamed) {
  const std::string dir = FreshTempDir("missing_split");
  WriteFile(dir + "/missing_split_0.mcap", McapSplit(0, 100, "-0"));
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"missing_split_0.mcap", "missing_split_1.mcap"}));
  EXPECT_EQ(ReadRecording(dir).error,
            dir +
                "/missing_split_1.mcap: missing: listed in metadata.yaml's relative_file_paths, "
                "but there is no such file");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"old_style_prefix/missing_split_0.mcap"}));
  EXPECT_EQ(ReadRecording(dir).error, "");  // found by its base name
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {}));
  EXPECT_EQ(ReadRecording(dir).error, dir + "/metadata.yaml: no relative_file_paths: the bag lists no files");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"missing_split_0.mcap"}, "file", "lz4"));
  EXPECT_EQ(ReadRecording(dir).error, dir + "/metadata.yaml: compression_format \"lz4\" is not supported (only zstd)");
  WriteTextFile(dir + "/metadata.yaml", "rosbag2_bagfile_information: [unclosed\n");
  EXPECT_THAT(ReadRecording(dir).error, ::testing::StartsWith(dir + "/metadata.yaml:"));
  WriteTextFile(dir + "/metadata.yaml", "something_else: 1\n");
  EXPECT_EQ(ReadRecording(dir).error, dir + "/metadata.yaml: no rosbag2_bagfile_information map");
}

// A split listed twice, by the same name or another that finds the same file, is refused before
// anything is read: read twice, every message would count twice.
TEST(RosRecordingTest, ASplitListedTwiceIsRefused) {
  const std::string dir = FreshTempDir("split_twice");
  WriteFile(dir + "/split_twice_0.mcap", McapSplit(0, 100, "-0"));
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"split_twice_0.mcap", "split_twice_0.mcap"}));
  EXPECT_EQ(ReadRecording(dir).error,
            dir + "/metadata.yaml: relative_file_paths lists " + dir +
                "/split_twice_0.mcap twice (entries 1 and 2, \"split_twice_0.mcap\" and "
                "\"split_twice_0.mcap\"): refused, as reading it twice would give every message "
                "twice; remove the repeated entry");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"split_twice_0.mcap", "split_twice/split_twice_0.mcap"}));
  EXPECT_THAT(ReadRecording(dir).error, HasSubstr("twice (entries 1 and 2"));
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"split_twice_0.mcap"}));
  EXPECT_EQ(ReadRecording(dir).error, "");
}

TEST(RosRecordingTest, AnIncompleteSplitMakesTheBagIncompleteAndSaysWhich) {
  const std::string dir = FreshTempDir("incomplete_split");
  WriteTextFile(dir + "/metadata.yaml", MetadataYaml("mcap", {"incomplete_split_0.mcap", "incomplete_split_1.mcap"}));
  Bytes cut = McapSplit(0, 100, "-0");
  cut.resize(cut.size() - McapDataEnd().size() - McapFooter().size() - McapMagic().size());
  WriteFile(dir + "/incomplete_split_0.mcap", cut);
  WriteFile(dir + "/incomplete_split_1.mcap", McapSplit(0, 200, "-1"));
  const RecordingRead read = ReadRecording(dir);
  ASSERT_EQ(read.error, "");
  EXPECT_EQ(read.messages.size(), 4u);
  EXPECT_FALSE(read.summary.data_end.complete);
  EXPECT_EQ(read.summary.data_end.how,
            dir +
                "/incomplete_split_0.mcap: no data end record: the file ends after a complete "
                "record (recording cut off?)");
}

TEST(RosRecordingTest, AZstdCompressedFileSurvivesEveryTruncationAndRandomCorruption) {
  const std::string path = FreshTempDir("zstd_fuzz") + "/bag_0.mcap.zstd";
  for (const bool lenient : {false, true}) {
    SCOPED_TRACE(lenient ? "lenient" : "strict");
    const FuzzOutcome outcome = FuzzReader(ZstdCompress(SmallMcap("lz4")), 300, [&](const Bytes& bytes) {
      WriteFile(path, bytes);
      ReadRosRecording(path, {.lenient = lenient}, [](const RecordedTopic&, const RecordedMessage&) {});
    });
    EXPECT_THAT(outcome.other_failures, ::testing::IsEmpty());
    EXPECT_GT(outcome.succeeded, 0u);
    EXPECT_GT(outcome.input_errors, 0u);
  }
}

}  // namespace
}  // namespace slamtune::io
