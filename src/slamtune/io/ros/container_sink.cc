#include "slamtune/io/ros/container_sink.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/decompression.h"

namespace slamtune::io {

ContainerSink::ContainerSink(ContainerSummary* summary, const MessageCallback* on_message)
    : summary_(summary), on_message_(on_message) {
  SLAMTUNE_CHECK(summary_ != nullptr && on_message_ != nullptr);
}

std::size_t ContainerSink::AddTopic(const RecordedTopic& topic) {
  const auto [it, added] =
      topic_index_.try_emplace(TopicKey{topic.name, topic.type, topic.serialization}, summary_->topics.size());
  if (added) {
    summary_->topics.push_back(topic);
    summary_->topics.back().messages = 0;
  } else if (topic.latched) {
    summary_->topics[it->second].latched = true;
  }
  return it->second;
}

void ContainerSink::Deliver(RecordedMessage& message) {
  SLAMTUNE_CHECK(message.topic < summary_->topics.size());
  const std::span<const std::uint8_t> stored = message.data;
  std::vector<std::uint8_t> decompressed;
  if (zstd_messages_) {
    try {
      decompressed = DecompressZstd(message.data, kMaxChunkBytes);
    } catch (const InputError& e) {
      throw InputError(message.location.file, 0, message.location.ToString() + " (message): " + e.message());
    }
    message.data = decompressed;
  }
  RecordedTopic& topic = summary_->topics[message.topic];
  ++topic.messages;
  ++summary_->messages;
  in_callback_ = true;
  (*on_message_)(topic, message);
  in_callback_ = false;
  message.data = stored;  // not left pointing at `decompressed`
}

void ContainerSink::DropTail(std::uint64_t bytes, std::uint64_t file_bytes, const std::string& reason, TailKind kind) {
  summary_->data_end.dropped_bytes += bytes;
  if (summary_->data_end.dropped_reason.empty()) summary_->data_end.dropped_reason = reason;
  summary_->data_end.complete = false;
  const double share = file_bytes > 0 ? 100.0 * static_cast<double>(bytes) / static_cast<double>(file_bytes) : 0.0;
  if (file_bytes == 0) {  // a database's rows
    summary_->data_end.how = "a corrupt row: read up to it (--lenient) (" + reason + ")";
    return;
  }
  const char* what = kind == TailKind::kCutOff ? "cut off inside a record: read up to its last whole record"
                                               : "a corrupt record: read up to it (--lenient)";
  summary_->data_end.how =
      fmt::format("{}, the last {} bytes ({:.1f} % of the file) not read ({})", what, bytes, share, reason);
}

void ContainerSink::EndAtBadRecord(const InputError& error, const BadRecord& bad) {
  if (in_callback()) throw;
  const std::uint64_t rest = bad.file_bytes - bad.offset;
  if (bad.ends_inside_record) {  // cut off: what is whole is read, and said
    DropTail(rest, bad.file_bytes, error.what(), TailKind::kCutOff);
    return;
  }
  if (!bad.lenient) {
    if (!bad.header_seen) throw;  // nothing to read up to
    throw InputError(error.file(), error.line(),
                     error.message() + " (--lenient reads the recording up to this record)");
  }
  DropTail(rest, bad.file_bytes, error.what(), TailKind::kCorrupt);
}

ContainerBytesReader::ContainerBytesReader(std::span<const std::uint8_t> bytes, const std::string& name,
                                           const ContainerReadOptions& options, ContainerSink* sink)
    : bytes_(bytes), name_(name), options_(options), sink_(sink) {
  message_.location.file = name;
}

void ContainerBytesReader::Deliver(std::size_t topic, std::int64_t log_time_ns, std::span<const std::uint8_t> data,
                                   std::uint64_t location) {
  message_.topic = topic;
  message_.log_time_ns = log_time_ns;
  message_.data = data;
  message_.location.value = location;
  sink_->Deliver(message_);
}

}  // namespace slamtune::io
