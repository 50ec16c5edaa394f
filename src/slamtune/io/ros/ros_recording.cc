#include "slamtune/io/ros/ros_recording.h"

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <span>
#include <utility>

#include "slamtune/common/error.h"
#include "slamtune/io/mapped_file.h"
#include "slamtune/io/ros/container_sink.h"
#include "slamtune/io/ros/decompression.h"
#include "slamtune/io/ros/mcap_reader.h"
#include "slamtune/io/ros/rosbag1_reader.h"
#include "slamtune/io/ros/rosbag2_folder.h"
#include "slamtune/io/ros/rosbag2_sqlite_reader.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kHeadBytes = 16;  // the longest magic: "SQLite format 3\0"

// Reads a path of one kind into the sink.
using ReadPath = void (*)(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink);
// Reads a container file's bytes held in memory, `name` standing for the file.
using ReadBytes = void (*)(std::vector<std::uint8_t> bytes, const std::string& name,
                           const ContainerReadOptions& options, ContainerSink* sink);
// A reader of a container file's bytes, wherever they are.
using ReadSpan = void (*)(std::span<const std::uint8_t> bytes, const std::string& name,
                          const ContainerReadOptions& options, ContainerSink* sink);

// One kind of recording: a row of kFormats.
struct RecordingFormat {
  RecordingKind kind;
  const char* name;  // RecordingKindName, and ContainerFormatName of `container`
  // How a path of this kind is recognised: a folder holding this file, ...
  const char* folder_file = nullptr;
  // ... or a file whose first bytes (kHeadBytes of them) pass this test. A row with neither is
  // the kind of every file no other row recognises.
  bool (*has_magic)(std::span<const std::uint8_t> head) = nullptr;
  // The container format of the kind, when it is one.
  std::optional<ContainerFormat> container = std::nullopt;
  // How it is read: from its path (nullptr: not a ROS recording) and, for a container format,
  // from its bytes in memory.
  ReadPath read_path = nullptr;
  ReadBytes read_bytes = nullptr;
};

// A ReadSpan as a ReadPath: the file mapped into memory.
template <ReadSpan read>
void ReadMappedInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink) {
  const MappedFile file(path);
  read(file.bytes(), path, options, sink);
}

// A ReadSpan as a ReadBytes.
template <ReadSpan read>
void ReadHeldInto(std::vector<std::uint8_t> bytes, const std::string& name, const ContainerReadOptions& options,
                  ContainerSink* sink) {
  read(bytes, name, options, sink);
}

void ReadDecompressedInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink);
void ReadBagFolderInto(const std::string& folder, const ContainerReadOptions& options, ContainerSink* sink);

// Every kind, in the order detection tries them.
constexpr std::array kFormats = {
    RecordingFormat{.kind = RecordingKind::kMcap,
                    .name = "MCAP",
                    .has_magic = HasMcapMagic,
                    .container = ContainerFormat::kMcap,
                    .read_path = ReadMappedInto<ReadMcapInto>,
                    .read_bytes = ReadHeldInto<ReadMcapInto>},
    RecordingFormat{.kind = RecordingKind::kRosbag2Sqlite,
                    .name = "rosbag2 SQLite3",
                    .has_magic = HasSqliteMagic,
                    .container = ContainerFormat::kRosbag2Sqlite,
                    .read_path = ReadRosbag2SqliteInto,
                    .read_bytes = ReadRosbag2SqliteBytesInto},
    RecordingFormat{.kind = RecordingKind::kRosbag1,
                    .name = "ROS 1 bag v2.0",
                    .has_magic = HasRosbag1Magic,
                    .container = ContainerFormat::kRosbag1,
                    .read_path = ReadMappedInto<ReadRosbag1Into>,
                    .read_bytes = ReadHeldInto<ReadRosbag1Into>},
    RecordingFormat{.kind = RecordingKind::kZstdFile,
                    .name = "zstd-compressed rosbag2 file",
                    .has_magic = HasZstdMagic,
                    .read_path = ReadDecompressedInto},
    RecordingFormat{.kind = RecordingKind::kRosbag2Folder,
                    .name = "rosbag2 bag folder",
                    .folder_file = kRosbag2MetadataFile,
                    .read_path = ReadBagFolderInto},
    RecordingFormat{.kind = RecordingKind::kCarmenLog, .name = "CARMEN log"},
};

template <typename Predicate>
const RecordingFormat* FindFormat(Predicate predicate) {
  for (const RecordingFormat& format : kFormats) {
    if (predicate(format)) return &format;
  }
  return nullptr;
}

const RecordingFormat& FormatOf(ContainerFormat container) {
  const RecordingFormat* format = FindFormat([&](const RecordingFormat& f) { return f.container == container; });
  SLAMTUNE_CHECK(format != nullptr);
  return *format;
}

// The kind of a file whose first bytes are `head`.
const RecordingFormat& FormatOfBytes(std::span<const std::uint8_t> head) {
  const RecordingFormat* format =
      FindFormat([&](const RecordingFormat& f) { return f.has_magic != nullptr && f.has_magic(head); });
  if (format != nullptr) return *format;
  format = FindFormat([](const RecordingFormat& f) { return f.has_magic == nullptr && f.folder_file == nullptr; });
  SLAMTUNE_CHECK(format != nullptr);
  return *format;
}

// The kind of the folder `path`, by the file it holds.
const RecordingFormat& FormatOfFolder(const std::string& path) {
  const RecordingFormat* format = FindFormat([&](const RecordingFormat& f) {
    struct stat info {};
    return f.folder_file != nullptr && ::stat((path + "/" + f.folder_file).c_str(), &info) == 0 &&
           S_ISREG(info.st_mode);
  });
  if (format == nullptr) {
    throw InputError(path, 0, std::string("a folder but not a rosbag2 bag (no ") + kRosbag2MetadataFile + ")");
  }
  return *format;
}

const RecordingFormat& DetectFormat(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw InputError(path, 0, std::string("cannot open (") + std::strerror(errno) + ")");
  }
  if (S_ISDIR(info.st_mode)) return FormatOfFolder(path);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open (") + std::strerror(errno) + ")");
  std::array<std::uint8_t, kHeadBytes> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  return FormatOfBytes(std::span(head.data(), static_cast<std::size_t>(in.gcount())));
}

// Reads `path`, of the kind `format`, into `sink`, setting the summary's format for a container.
void ReadInto(const RecordingFormat& format, const std::string& path, const ContainerReadOptions& options,
              ContainerSink* sink) {
  if (format.read_path == nullptr) {
    throw InputError(path, 0,
                     "not a ROS recording (MCAP, rosbag2 SQLite3 or ROS 1 bag v2.0): it reads as a CARMEN log");
  }
  if (format.container) sink->summary().format = *format.container;
  format.read_path(path, options, sink);
}

ContainerSummary Read(const RecordingFormat& format, const std::string& path, const ContainerReadOptions& options,
                      const MessageCallback& on_message) {
  ContainerSummary summary;
  ContainerSink sink(&summary, &on_message);
  ReadInto(format, path, options, &sink);
  return summary;
}

// A file compressed whole with zstd: the container it holds, decompressed into memory.
void ReadDecompressedInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink) {
  std::vector<std::uint8_t> bytes;
  {
    const MappedFile file(path);
    try {
      bytes = DecompressZstd(file.bytes(), kMaxWholeFileBytes);
    } catch (const InputError& e) {
      throw InputError(path, 0, "zstd-compressed file: " + e.message());
    }
  }
  ContainerSummary& summary = sink->summary();
  summary.file_compression = "zstd";
  const RecordingFormat& inner = FormatOfBytes(bytes);
  if (inner.read_bytes == nullptr) {
    throw InputError(path, 0, "zstd-compressed, but what it holds is not an MCAP, rosbag2 SQLite3 or ROS 1 bag file");
  }
  summary.format = *inner.container;
  inner.read_bytes(std::move(bytes), path, options, sink);
}

// A rosbag2 bag folder: its split files, each judged by content, read one after the other into
// the one summary.
void ReadBagFolderInto(const std::string& folder, const ContainerReadOptions& options, ContainerSink* sink) {
  const Rosbag2Metadata metadata = ReadRosbag2Metadata(folder);
  ContainerSummary& summary = sink->summary();
  if (metadata.compression_mode == "message") {
    sink->set_zstd_messages(true);
    summary.message_compression = "zstd";
  }
  const std::vector<std::string> paths = Rosbag2SplitFiles(folder, metadata);
  std::string incomplete;  // endings of the splits that did not end complete
  for (const std::string& path : paths) {
    const RecordingFormat& format = DetectFormat(path);
    if (format.folder_file != nullptr) throw InputError(path, 0, "a folder, not a recording file");
    const bool complete_before = summary.data_end.complete;
    summary.data_end.complete = true;
    ReadInto(format, path, options, sink);
    if (!summary.data_end.complete) incomplete += (incomplete.empty() ? "" : "; ") + path + ": " + summary.data_end.how;
    summary.data_end.complete = summary.data_end.complete && complete_before;
  }
  if (!incomplete.empty()) summary.data_end.how = incomplete;
}

}  // namespace

const char* RecordingKindName(RecordingKind kind) {
  const RecordingFormat* format = FindFormat([&](const RecordingFormat& f) { return f.kind == kind; });
  return format != nullptr ? format->name : "?";
}

const char* ContainerFormatName(ContainerFormat container) {
  const RecordingFormat* format = FindFormat([&](const RecordingFormat& f) { return f.container == container; });
  return format != nullptr ? format->name : "?";
}

RecordingKind DetectRecordingKind(const std::string& path) { return DetectFormat(path).kind; }

ContainerSummary ReadRosRecording(const std::string& path, const ContainerReadOptions& options,
                                  const MessageCallback& on_message) {
  return Read(DetectFormat(path), path, options, on_message);
}

ContainerSummary ReadContainerFile(ContainerFormat format, const std::string& path, const ContainerReadOptions& options,
                                   const MessageCallback& on_message) {
  return Read(FormatOf(format), path, options, on_message);
}

ContainerSummary ReadContainerBytes(ContainerFormat format, std::vector<std::uint8_t> bytes, const std::string& name,
                                    const ContainerReadOptions& options, const MessageCallback& on_message) {
  const RecordingFormat& row = FormatOf(format);
  ContainerSummary summary;
  summary.format = format;
  ContainerSink sink(&summary, &on_message);
  row.read_bytes(std::move(bytes), name, options, &sink);
  return summary;
}

}  // namespace slamtune::io
