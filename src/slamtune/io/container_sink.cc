#include "slamtune/io/container_sink.h"

#include "slamtune/common/error.h"
#include "slamtune/io/decompression.h"

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

void ContainerSink::DropTail(std::uint64_t bytes, const std::string& reason) {
  summary_->dropped_tail_bytes += bytes;
  if (summary_->dropped_tail_reason.empty()) summary_->dropped_tail_reason = reason;
  summary_->complete = false;
  summary_->ending = "corrupt or truncated tail dropped (--lenient): " + reason;
}

}  // namespace slamtune::io
