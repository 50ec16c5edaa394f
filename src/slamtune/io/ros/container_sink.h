// Where the single-file container readers (MCAP, rosbag2 SQLite3, ROS 1) put what they read:
// the ContainerSummary being filled (recording_container.h), shared by all split files of a
// rosbag2 bag folder so that their topics merge, and the caller's message callback.
//
// Topics with the same name, type and serialization are one RecordedTopic, whichever file,
// MCAP channel or ROS 1 connection they come from (several publishers on /tf are one topic).
// With message-level compression (rosbag2 compression_mode "message", docs/recordings.md §1.1)
// each payload is a zstd frame, decompressed here before the callback sees it.
//
// ContainerBytesReader is the common base of the readers that walk a file's bytes record by
// record (MCAP, ROS 1): what they read from and into, and how they deliver a message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

class ContainerSink {
 public:
  // Both must outlive the sink.
  ContainerSink(ContainerSummary* summary, const MessageCallback* on_message);

  ContainerSummary& summary() { return *summary_; }

  // The index of `topic` in summary().topics, adding it when new (its `messages` is ignored). A
  // topic latched anywhere is latched.
  std::size_t AddTopic(const RecordedTopic& topic);

  // Message payloads are zstd frames (rosbag2 message-level compression).
  void set_zstd_messages(bool zstd) { zstd_messages_ = zstd; }

  // Counts `message` on its topic and hands it to the callback. `message.topic` must come from
  // AddTopic. The callback may see `message.data` replaced by its decompressed bytes.
  void Deliver(RecordedMessage& message);

  // True while the callback runs, i.e. when an exception comes from the callback rather than
  // from the reader: such an exception must pass through unchanged, even with lenient reading.
  bool in_callback() const { return in_callback_; }

  // Reading ended a file of `file_bytes` bytes `bytes` before its end because of `reason`: the
  // file ends inside a record (cut off, read up to its last whole record whether lenient or
  // not), or a record is corrupt (--lenient).
  enum class TailKind { kCutOff, kCorrupt };
  void DropTail(std::uint64_t bytes, std::uint64_t file_bytes, const std::string& reason, TailKind kind);

  // Where a top-level record of a single-file container failed to read.
  struct BadRecord {
    std::uint64_t offset;      // where the record starts
    std::uint64_t file_bytes;  // the file's size
    bool ends_inside_record;   // the file ends inside it (cut off)
    bool header_seen;          // the file's header was read, so there is something to read up to
    bool lenient;              // --lenient
  };
  // Called from the reader's handler of `error`, for the record `bad`: an error the callback threw
  // passes unchanged; a cut-off file is read up to the record; a corrupt record ends the reading
  // under --lenient and is otherwise an error that names --lenient once the header was read. On
  // return the reader stops.
  void EndAtBadRecord(const InputError& error, const BadRecord& bad);

 private:
  using TopicKey = std::tuple<std::string, std::string, MessageSerialization>;

  ContainerSummary* summary_;
  const MessageCallback* on_message_;
  std::map<TopicKey, std::size_t> topic_index_;
  bool zstd_messages_ = false;
  bool in_callback_ = false;
};

// The base of the readers that walk a single file's bytes record by record (MCAP, ROS 1): the
// bytes, the file's name (in errors and message locations), the options and the sink they read
// into, and the delivery of a message located in that file.
class ContainerBytesReader {
 public:
  // All four must outlive the reader.
  ContainerBytesReader(std::span<const std::uint8_t> bytes, const std::string& name,
                       const ContainerReadOptions& options, ContainerSink* sink);

 protected:
  // Hands the message `data` of `topic` (from ContainerSink::AddTopic), logged at `log_time_ns`,
  // to the sink, located at byte `location` of the file.
  void Deliver(std::size_t topic, std::int64_t log_time_ns, std::span<const std::uint8_t> data, std::uint64_t location);

  std::span<const std::uint8_t> bytes_;
  const std::string& name_;
  const ContainerReadOptions& options_;
  ContainerSink* sink_;

 private:
  RecordedMessage message_;  // filled for each delivery; its location names the file once for all
};

}  // namespace slamtune::io
