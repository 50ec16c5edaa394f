#include "slamtune/io/ros/rosbag2_sqlite_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_recording.h"
#include "slamtune/io/testing/recording_bytes.h"

namespace slamtune::io {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using namespace testing;  // NOLINT: the bag builders

ContainerRead ReadDb(const std::string& path, ContainerReadOptions options = {}) {
  return ReadFileAs(ContainerFormat::kRosbag2Sqlite, path, options);
}

// The messages of every variant below: given out of order, two at timestamp 200.
void InsertMessages(TestDatabase* db) {
  db->InsertMessage(1, 1, 300, ToBytes("scan-3"));
  db->InsertMessage(2, 1, 100, ToBytes("scan-1"));
  db->InsertMessage(3, 2, 200, ToBytes("tf-1"));
  db->InsertMessage(4, 1, 200, ToBytes("scan-2"));
}

constexpr const char* kMessagesTable =
    "CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, "
    "data BLOB NOT NULL); CREATE INDEX timestamp_idx ON messages (timestamp ASC);";

// Eloquent: topics without offered_qos_profiles, no schema table.
void WriteEloquentDb3(const std::string& path) {
  TestDatabase db(path);
  db.Exec(std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
                      "serialization_format TEXT NOT NULL);") +
          kMessagesTable);
  db.Exec("INSERT INTO topics VALUES (1, '/scan', 'sensor_msgs/msg/LaserScan', 'cdr');");
  db.Exec("INSERT INTO topics VALUES (2, '/tf_static', 'tf2_msgs/msg/TFMessage', 'cdr');");
  InsertMessages(&db);
}

// Jazzy: schema, metadata and message_definitions tables, type_description_hash, QoS by name.
void WriteJazzyDb3(const std::string& path) {
  TestDatabase db(path);
  db.Exec(std::string("CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);"
                      "CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, "
                      "metadata TEXT NOT NULL);"
                      "CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
                      "serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL, "
                      "type_description_hash TEXT NOT NULL);"
                      "CREATE TABLE message_definitions(id INTEGER PRIMARY KEY, topic_type TEXT NOT NULL, "
                      "encoding TEXT NOT NULL, encoded_message_definition TEXT NOT NULL, "
                      "type_description_hash TEXT NOT NULL);") +
          kMessagesTable);
  db.Exec(
      "INSERT INTO schema VALUES (4, 'jazzy'); INSERT INTO metadata VALUES (1, 9, 'rosbag2_bagfile_information: {}');");
  db.Exec(
      "INSERT INTO topics VALUES (1, '/scan', 'sensor_msgs/msg/LaserScan', 'cdr', "
      "'- history: keep_last\n  depth: 5\n  reliability: best_effort\n  durability: volatile', 'RIHS01_1');");
  db.Exec(
      "INSERT INTO topics VALUES (2, '/tf_static', 'tf2_msgs/msg/TFMessage', 'cdr', "
      "'- history: keep_last\n  depth: 1\n  reliability: reliable\n  durability: transient_local', 'RIHS01_2');");
  db.Exec(
      "INSERT INTO message_definitions VALUES (1, 'sensor_msgs/msg/LaserScan', 'ros2msg', 'float32 x', 'RIHS01_1');");
  InsertMessages(&db);
}

TEST(Rosbag2SqliteReaderTest, ReadsEachSchemaVariantInTimestampThenIdOrder) {
  const std::string dir = FreshTempDir("db3_variants");
  struct Variant {
    std::string name;
    void (*write)(const std::string&);
    bool latched;
    std::string distro;
  };
  for (const Variant& variant :
       {Variant{"eloquent", &WriteEloquentDb3, false, ""}, Variant{"humble", &WriteHumbleDb3, true, ""},
        Variant{"jazzy", &WriteJazzyDb3, true, "jazzy"}}) {
    SCOPED_TRACE(variant.name);
    const std::string path = dir + "/" + variant.name + ".db3";
    variant.write(path);
    const ContainerRead read = ReadDb(path);
    ASSERT_EQ(read.error, "");
    std::vector<std::string> order;
    for (const Delivered& m : read.messages)
      order.push_back(m.data + "@" + std::to_string(m.log_time_ns) + "/" + m.location);
    EXPECT_THAT(order, ElementsAre("scan-1@100/row 2", "tf-1@200/row 3", "scan-2@200/row 4", "scan-3@300/row 1"));
    EXPECT_EQ(read.messages[1].topic, "/tf_static");
    EXPECT_EQ(read.messages[0].file, path);
    const ContainerSummary& s = read.summary;
    EXPECT_EQ(s.format, ContainerFormat::kRosbag2Sqlite);
    ASSERT_EQ(s.topics.size(), 2u);
    ExpectScanTopic(s.topics[0], "sensor_msgs/msg/LaserScan", MessageSerialization::kCdr, 3);
    EXPECT_EQ(s.topics[1].latched, variant.latched);
    EXPECT_EQ(s.ros_distro, variant.distro);
    EXPECT_EQ(s.messages, 4u);
    EXPECT_TRUE(s.data_end.complete);
    EXPECT_EQ(s.data_end.how, "end of the messages table");
    EXPECT_THAT(s.files, ElementsAre(path));
  }
}

TEST(Rosbag2SqliteReaderTest, ADatabaseWithoutTheRosbag2TablesIsRefused) {
  const std::string dir = FreshTempDir("db3_not_rosbag2");
  {
    TestDatabase db(dir + "/topics_only.db3");
    db.Exec("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT, type TEXT, serialization_format TEXT);");
    TestDatabase other(dir + "/no_type.db3");
    other.Exec(std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT);") + kMessagesTable);
  }
  EXPECT_EQ(ReadDb(dir + "/topics_only.db3").error,
            dir + "/topics_only.db3: not a rosbag2 database: no table messages");
  EXPECT_EQ(ReadDb(dir + "/no_type.db3").error,
            dir + "/no_type.db3: not a rosbag2 database: table topics has no column type");
}

TEST(Rosbag2SqliteReaderTest, ACorruptOrForeignFileNamesTheSqliteError) {
  const std::string dir = FreshTempDir("db3_corrupt");
  std::mt19937 random(3);
  Bytes header_then_noise = ToBytes(std::string("SQLite format 3") + '\0');
  for (int i = 0; i < 8192; ++i) header_then_noise.push_back(static_cast<std::uint8_t>(random()));
  WriteFile(dir + "/noise.db3", header_then_noise);
  EXPECT_THAT(ReadDb(dir + "/noise.db3").error, HasSubstr(dir + "/noise.db3: sqlite: "));

  WriteHumbleDb3(dir + "/pages.db3");  // 512-byte pages: overwrite every page but the first
  Bytes pages = ReadFile(dir + "/pages.db3");
  for (std::size_t i = 512; i < pages.size(); ++i) pages[i] = static_cast<std::uint8_t>(random());
  WriteFile(dir + "/pages.db3", pages);
  EXPECT_THAT(ReadDb(dir + "/pages.db3").error, HasSubstr("sqlite: database disk image is malformed"));

  WriteFile(dir + "/text.db3", ToBytes("just some text, long enough to be looked at by SQLite as a header......"));
  EXPECT_THAT(ReadDb(dir + "/text.db3").error, HasSubstr("sqlite: file is not a database"));
  EXPECT_EQ(ReadDb(dir + "/missing.db3").error, dir + "/missing.db3: cannot open (No such file or directory)");
}

TEST(Rosbag2SqliteReaderTest, AMessageOnAnUnknownTopicIdNamesItsRow) {
  const std::string path = FreshTempDir("db3_unknown_topic") + "/bag.db3";
  WriteHumbleDb3(path);
  TestDatabase(path).InsertMessage(5, 9, 250, ToBytes("orphan"));
  EXPECT_EQ(ReadDb(path).error, path + ": row 5: message on topic id 9, which is not in the topics table");
  const ContainerRead lenient = ReadDb(path, {.lenient = true});
  ASSERT_EQ(lenient.error, "");
  EXPECT_EQ(lenient.messages.size(), 3u);  // up to timestamp 200
  EXPECT_FALSE(lenient.summary.data_end.complete);
  EXPECT_THAT(lenient.summary.data_end.dropped_reason, HasSubstr("row 5"));
}

TEST(Rosbag2SqliteReaderTest, OtherSerializationFormatsAreMarkedInTheType) {
  const std::string path = FreshTempDir("db3_formats") + "/bag.db3";
  {
    TestDatabase db(path);
    db.Exec(std::string("CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL, "
                        "serialization_format TEXT NOT NULL);") +
            kMessagesTable);
    db.Exec("INSERT INTO topics VALUES (1, '/a', 'std_msgs/String', 'ros1'), (2, '/b', 'x/msg/Y', 'json');");
  }
  const ContainerRead read = ReadDb(path);
  ASSERT_EQ(read.summary.topics.size(), 2u);
  EXPECT_EQ(read.summary.topics[0].serialization, MessageSerialization::kRos1);
  EXPECT_EQ(read.summary.topics[1].type, "x/msg/Y (json encoding)");
  EXPECT_TRUE(read.messages.empty());
}

TEST(Rosbag2SqliteReaderTest, ReadsADatabaseImageInMemory) {
  const std::string path = FreshTempDir("db3_memory") + "/bag.db3";
  WriteJazzyDb3(path);
  std::vector<Delivered> messages;
  const ContainerSummary summary =
      ReadContainerBytes(ContainerFormat::kRosbag2Sqlite, ReadFile(path), "image.db3", {}, Collect(&messages));
  ASSERT_EQ(messages.size(), 4u);
  EXPECT_EQ(messages[0].file, "image.db3");
  EXPECT_EQ(summary.ros_distro, "jazzy");
  EXPECT_TRUE(summary.topics[1].latched);
}

TEST(Rosbag2SqliteReaderTest, EveryTruncationAndRandomCorruptionSucceedsOrThrowsInputError) {
  const std::string path = FreshTempDir("db3_fuzz") + "/bag.db3";
  WriteHumbleDb3(path);
  const Bytes image = ReadFile(path);
  for (const bool lenient : {false, true}) {
    SCOPED_TRACE(lenient ? "lenient" : "strict");
    const FuzzOutcome outcome = FuzzReader(image, 400, [&](const Bytes& bytes) {
      ReadContainerBytes(ContainerFormat::kRosbag2Sqlite, bytes, "fuzz.db3", {.lenient = lenient},
                         [](const RecordedTopic&, const RecordedMessage&) {});
    });
    EXPECT_THAT(outcome.other_failures, ::testing::IsEmpty());
    EXPECT_GT(outcome.succeeded, 0u);
    EXPECT_GT(outcome.input_errors, 0u);
  }
}

}  // namespace
}  // namespace slamtune::io
