// rosbag2 SQLite3 storage (`.db3`; ros2/rosbag2 rosbag2_storage_sqlite3; docs/recordings.md §1.3),
// every schema variant from Eloquent to Jazzy: only the columns all of them have are read,
//   topics(id, name, type, serialization_format [, offered_qos_profiles]) and
//   messages(id, topic_id, timestamp, data),
// the optional ones after probing for them (offered_qos_profiles for latched topics, the
// `schema` table's ros_distro). Messages are delivered ORDER BY timestamp, id, located by row id.
// serialization_format "cdr" is MessageSerialization::kCdr ("ros1" kRos1); any other format
// lists the topic and delivers its messages with the type written "TYPE (FORMAT encoding)",
// so that no CDR decoder takes them.
//
// The database is opened read-only; when that fails for want of write access to its folder
// (a journal or WAL file SQLite would create), it is reopened `immutable=1`. Errors: a file that
// is not a database, a corrupt one (SQLITE_NOTADB, SQLITE_CORRUPT, ...) or a database without the
// rosbag2 tables throws InputError "FILE: ..." naming the SQLite error or the missing table, a
// message on an unknown topic id "FILE: row N: ...". Lenient reading ends at a corrupt row
// (ContainerSummary::data_end.dropped_bytes stays 0: a database has rows, not a byte tail).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "slamtune/io/ros/container_sink.h"
#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

// True when `bytes` start with the SQLite file header "SQLite format 3\0".
bool HasSqliteMagic(std::span<const std::uint8_t> bytes);

// Reads the database file `path` into `sink`.
void ReadRosbag2SqliteInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink);
// Reads a database image in memory (sqlite3_deserialize, read-only), named `name` in messages.
void ReadRosbag2SqliteBytesInto(std::vector<std::uint8_t> bytes, const std::string& name,
                                const ContainerReadOptions& options, ContainerSink* sink);

}  // namespace slamtune::io
