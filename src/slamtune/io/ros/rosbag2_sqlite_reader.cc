#include "slamtune/io/ros/rosbag2_sqlite_reader.h"

#include <sqlite3.h>

#include <algorithm>
#include <memory>
#include <set>
#include <string_view>
#include <unordered_map>

#include "slamtune/common/error.h"
#include "slamtune/io/mapped_file.h"
#include "slamtune/io/ros/rosbag2_qos.h"

namespace slamtune::io {
namespace {

constexpr std::string_view kSqliteMagic{"SQLite format 3\0", 16};  // sqlite.org/fileformat.html §1.3

struct DatabaseCloser {
  void operator()(sqlite3* db) const { sqlite3_close_v2(db); }
};
struct StatementFinalizer {
  void operator()(sqlite3_stmt* statement) const { sqlite3_finalize(statement); }
};
using Database = std::unique_ptr<sqlite3, DatabaseCloser>;
using Statement = std::unique_ptr<sqlite3_stmt, StatementFinalizer>;

// InputError "NAME: sqlite: MESSAGE (error code N) (while WHAT)".
[[noreturn]] void ThrowSqlite(const std::string& name, sqlite3* db, int rc, const std::string& what) {
  const char* message = db != nullptr ? sqlite3_errmsg(db) : sqlite3_errstr(rc);
  throw InputError(name, 0,
                   std::string("sqlite: ") + message + " (error code " + std::to_string(rc) + ") (while " + what + ")");
}

// `what` says what the statement is for, in messages.
Statement Prepare(sqlite3* db, const std::string& name, const std::string& sql, const std::string& what) {
  sqlite3_stmt* statement = nullptr;
  const int rc = sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr);
  if (rc != SQLITE_OK) {
    sqlite3_finalize(statement);
    ThrowSqlite(name, db, rc, what);
  }
  return Statement(statement);
}

// Steps `statement`: true at a row, false when done; throws on an error.
bool Step(sqlite3* db, sqlite3_stmt* statement, const std::string& name, const std::string& what) {
  const int rc = sqlite3_step(statement);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  ThrowSqlite(name, db, rc, what);
}

std::string_view Text(sqlite3_stmt* statement, int column) {
  const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(statement, column));
  return text == nullptr ? std::string_view() : std::string_view(text, sqlite3_column_bytes(statement, column));
}

// The values of the first column of every row of `sql`.
std::set<std::string> FirstColumn(sqlite3* db, const std::string& name, const std::string& sql,
                                  const std::string& what) {
  const Statement statement = Prepare(db, name, sql, what);
  std::set<std::string> values;
  while (Step(db, statement.get(), name, what)) values.emplace(Text(statement.get(), 0));
  return values;
}

// `path` as an SQLite URI filename opening it immutable (sqlite.org/uri.html).
std::string ImmutableUri(const std::string& path) {
  std::string uri = "file:";
  for (const char c : path) {
    if (c == '%' || c == '?' || c == '#') {
      static constexpr char kHex[] = "0123456789ABCDEF";
      uri += '%';
      uri += kHex[(static_cast<unsigned char>(c) >> 4) & 0xF];
      uri += kHex[static_cast<unsigned char>(c) & 0xF];
    } else {
      uri += c;
    }
  }
  return uri + "?immutable=1";
}

Database OpenDatabase(const std::string& path, bool immutable) {
  sqlite3* db = nullptr;
  const int flags = SQLITE_OPEN_READONLY | (immutable ? SQLITE_OPEN_URI : 0);
  const int rc = sqlite3_open_v2(immutable ? ImmutableUri(path).c_str() : path.c_str(), &db, flags, nullptr);
  Database database(db);
  if (rc != SQLITE_OK) ThrowSqlite(path, db, rc, "opening the database");
  sqlite3_db_config(db, SQLITE_DBCONFIG_DEFENSIVE, 1, nullptr);
  return database;
}

// Reads one open database into the sink.
class SqliteBagReader {
 public:
  SqliteBagReader(sqlite3* db, const std::string& name, const ContainerReadOptions& options, ContainerSink* sink)
      : db_(db), name_(name), options_(options), sink_(sink) {}

  // The tables and columns; throws when they are not a rosbag2 database's.
  void ProbeSchema();
  void Read();

 private:
  std::set<std::string> Columns(const std::string& table) const {
    return FirstColumn(db_, name_, "SELECT name FROM pragma_table_info('" + table + "')",
                       "listing the columns of table " + table);
  }
  void RequireColumns(const std::string& table, std::initializer_list<const char*> columns) const;
  void ReadRosDistro();
  void ReadTopics();
  void ReadMessages();

  sqlite3* db_;
  const std::string& name_;
  const ContainerReadOptions& options_;
  ContainerSink* sink_;
  std::set<std::string> tables_;
  std::unordered_map<std::int64_t, std::size_t> topic_index_;  // topics.id -> topic index
};

void SqliteBagReader::ProbeSchema() {
  tables_ = FirstColumn(db_, name_, "SELECT name FROM sqlite_master WHERE type = 'table'", "listing the tables");
  for (const char* table : {"topics", "messages"}) {
    if (!tables_.contains(table)) throw InputError(name_, 0, std::string("not a rosbag2 database: no table ") + table);
  }
  RequireColumns("topics", {"id", "name", "type", "serialization_format"});
  RequireColumns("messages", {"id", "topic_id", "timestamp", "data"});
}

void SqliteBagReader::RequireColumns(const std::string& table, std::initializer_list<const char*> columns) const {
  const std::set<std::string> present = Columns(table);
  for (const char* column : columns) {
    if (!present.contains(column)) {
      throw InputError(name_, 0, "not a rosbag2 database: table " + table + " has no column " + column);
    }
  }
}

void SqliteBagReader::Read() {
  ContainerSummary& summary = sink_->summary();
  summary.files.push_back(name_);
  ReadRosDistro();
  ReadTopics();
  ReadMessages();
}

// The `schema` table (schema version >= 3) says which distro wrote the file.
void SqliteBagReader::ReadRosDistro() {
  if (!tables_.contains("schema") || !Columns("schema").contains("ros_distro")) return;
  const std::set<std::string> distros =
      FirstColumn(db_, name_, "SELECT ros_distro FROM schema LIMIT 1", "reading the schema table");
  ContainerSummary& summary = sink_->summary();
  if (!distros.empty() && summary.ros_distro.empty()) summary.ros_distro = *distros.begin();
}

RecordedTopic TopicRow(sqlite3_stmt* row, bool has_qos) {
  RecordedTopic topic;
  topic.name = std::string(Text(row, 1));
  topic.type = std::string(Text(row, 2));
  const std::string_view format = Text(row, 3);
  if (format == "cdr") {
    topic.serialization = MessageSerialization::kCdr;
  } else if (format == "ros1") {
    topic.serialization = MessageSerialization::kRos1;
  } else {
    topic.type += " (" + std::string(format) + " encoding)";
  }
  topic.latched = has_qos && OfferedQosIsTransientLocal(Text(row, 4));
  return topic;
}

void SqliteBagReader::ReadTopics() {
  const bool has_qos = Columns("topics").contains("offered_qos_profiles");
  const std::string sql = std::string("SELECT id, name, type, serialization_format") +
                          (has_qos ? ", offered_qos_profiles" : "") + " FROM topics ORDER BY id";
  const Statement statement = Prepare(db_, name_, sql, "reading the topics table");
  while (Step(db_, statement.get(), name_, "reading the topics table")) {
    const std::int64_t id = sqlite3_column_int64(statement.get(), 0);
    topic_index_.try_emplace(id, sink_->AddTopic(TopicRow(statement.get(), has_qos)));
  }
}

void SqliteBagReader::ReadMessages() {
  ContainerSummary& summary = sink_->summary();
  const Statement statement =
      Prepare(db_, name_, "SELECT m.id, m.timestamp, m.topic_id, m.data FROM messages m ORDER BY m.timestamp, m.id",
              "reading the messages table");
  RecordedMessage message;
  message.location.kind = MessageLocation::Kind::kRow;
  message.location.file = name_;
  std::int64_t last_id = -1;
  try {
    for (;;) {
      sqlite3_stmt* row = statement.get();
      const int rc = sqlite3_step(row);
      if (rc == SQLITE_DONE) break;
      if (rc != SQLITE_ROW) {
        ThrowSqlite(
            name_, db_, rc,
            last_id < 0 ? "reading the first message" : "reading the message after row " + std::to_string(last_id));
      }
      const std::int64_t id = sqlite3_column_int64(row, 0);
      const std::int64_t topic_id = sqlite3_column_int64(row, 2);
      const auto topic = topic_index_.find(topic_id);
      if (topic == topic_index_.end()) {
        throw InputError(name_, 0,
                         "row " + std::to_string(id) + ": message on topic id " + std::to_string(topic_id) +
                             ", which is not in the topics table");
      }
      const auto* data = static_cast<const std::uint8_t*>(sqlite3_column_blob(row, 3));
      message.data = {data, data == nullptr ? 0 : static_cast<std::size_t>(sqlite3_column_bytes(row, 3))};
      message.topic = topic->second;
      message.log_time_ns = sqlite3_column_int64(row, 1);
      message.location.value = static_cast<std::uint64_t>(id);
      sink_->Deliver(message);
      last_id = id;
    }
  } catch (const InputError& e) {
    if (!options_.lenient || sink_->in_callback()) throw;
    sink_->DropTail(0, 0, e.what(), ContainerSink::TailKind::kCorrupt);
    return;
  }
  summary.data_end.how = "end of the messages table";
}

void ReadDatabase(sqlite3* db, const std::string& name, const ContainerReadOptions& options, ContainerSink* sink) {
  SqliteBagReader reader(db, name, options, sink);
  reader.ProbeSchema();
  reader.Read();
}

// Primary result codes a read-only open gives when SQLite would need to write beside the file.
bool WantsWriteAccess(int rc) {
  const int primary = rc & 0xFF;
  return primary == SQLITE_CANTOPEN || primary == SQLITE_READONLY || primary == SQLITE_BUSY;
}

// Reads the schema once: SQLITE_OK, or the error code.
int FirstRead(sqlite3* db) {
  sqlite3_stmt* statement = nullptr;
  int rc = sqlite3_prepare_v2(db, "SELECT count(*) FROM sqlite_master", -1, &statement, nullptr);
  const Statement owned(statement);
  if (rc != SQLITE_OK) return rc;
  rc = sqlite3_step(statement);
  return rc == SQLITE_ROW ? SQLITE_OK : rc;
}

}  // namespace

bool HasSqliteMagic(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= kSqliteMagic.size() && std::equal(kSqliteMagic.begin(), kSqliteMagic.end(), bytes.begin());
}

void ReadRosbag2SqliteInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink) {
  CheckReadable(path);
  {
    // First a plain read-only open; reading the schema is the first access to the file.
    const Database db = OpenDatabase(path, /*immutable=*/false);
    const int rc = FirstRead(db.get());
    if (rc == SQLITE_OK || !WantsWriteAccess(rc)) {
      if (rc != SQLITE_OK) ThrowSqlite(path, db.get(), rc, "reading the schema");
      ReadDatabase(db.get(), path, options, sink);
      return;
    }
  }
  const Database db = OpenDatabase(path, /*immutable=*/true);
  ReadDatabase(db.get(), path, options, sink);
}

void ReadRosbag2SqliteBytesInto(std::vector<std::uint8_t> bytes, const std::string& name,
                                const ContainerReadOptions& options, ContainerSink* sink) {
  sqlite3* raw = nullptr;
  const int rc = sqlite3_open_v2(":memory:", &raw, SQLITE_OPEN_READWRITE, nullptr);
  const Database db(raw);
  if (rc != SQLITE_OK) ThrowSqlite(name, raw, rc, "opening an in-memory database");
  sqlite3_db_config(raw, SQLITE_DBCONFIG_DEFENSIVE, 1, nullptr);
  const auto size = static_cast<sqlite3_int64>(bytes.size());
  const int loaded = sqlite3_deserialize(raw, "main", bytes.data(), size, size, SQLITE_DESERIALIZE_READONLY);
  if (loaded != SQLITE_OK) ThrowSqlite(name, raw, loaded, "loading the database image");
  ReadDatabase(raw, name, options, sink);
}

}  // namespace slamtune::io
