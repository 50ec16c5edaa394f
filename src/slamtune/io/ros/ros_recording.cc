#include "slamtune/io/ros/ros_recording.h"

#include <sys/stat.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/io/mapped_file.h"
#include "slamtune/io/ros/decompression.h"
#include "slamtune/io/ros/mcap_reader.h"
#include "slamtune/io/ros/rosbag1_reader.h"
#include "slamtune/io/ros/rosbag2_folder.h"
#include "slamtune/io/ros/rosbag2_sqlite_reader.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kHeadBytes = 16;  // the longest magic: "SQLite format 3\0"

[[noreturn]] void ThrowNotRos(const std::string& path) {
  throw InputError(path, 0, "not a ROS recording (MCAP, rosbag2 SQLite3 or ROS 1 bag v2.0): it reads as a CARMEN log");
}

// Reads the recording decompressed from a zstd-compressed file.
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
  switch (RecordingKindOfBytes(bytes)) {
    case RecordingKind::kMcap:
      summary.format = ContainerFormat::kMcap;
      ReadMcapInto(bytes, path, options, sink);
      return;
    case RecordingKind::kRosbag2Sqlite:
      summary.format = ContainerFormat::kRosbag2Sqlite;
      ReadRosbag2SqliteBytesInto(std::move(bytes), path, options, sink);
      return;
    case RecordingKind::kRosbag1:
      summary.format = ContainerFormat::kRosbag1;
      ReadRosbag1Into(bytes, path, options, sink);
      return;
    default:
      throw InputError(path, 0, "zstd-compressed, but what it holds is not an MCAP, rosbag2 SQLite3 or ROS 1 bag file");
  }
}

}  // namespace

RecordingKind RecordingKindOfBytes(std::span<const std::uint8_t> head) {
  if (HasMcapMagic(head)) return RecordingKind::kMcap;
  if (HasSqliteMagic(head)) return RecordingKind::kRosbag2Sqlite;
  if (HasRosbag1Magic(head)) return RecordingKind::kRosbag1;
  if (HasZstdMagic(head)) return RecordingKind::kZstdFile;
  return RecordingKind::kCarmenLog;
}

RecordingKind DetectRecordingKind(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) {
    throw InputError(path, 0, std::string("cannot open (") + std::strerror(errno) + ")");
  }
  if (S_ISDIR(info.st_mode)) {
    struct stat metadata {};
    if (::stat((path + "/" + kRosbag2MetadataFile).c_str(), &metadata) != 0 || !S_ISREG(metadata.st_mode)) {
      throw InputError(path, 0, std::string("a folder but not a rosbag2 bag (no ") + kRosbag2MetadataFile + ")");
    }
    return RecordingKind::kRosbag2Folder;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, 0, std::string("cannot open (") + std::strerror(errno) + ")");
  std::array<std::uint8_t, kHeadBytes> head{};
  in.read(reinterpret_cast<char*>(head.data()), head.size());
  return RecordingKindOfBytes(std::span(head.data(), static_cast<std::size_t>(in.gcount())));
}

void ReadRecordingFileInto(const std::string& path, const ContainerReadOptions& options, ContainerSink* sink) {
  ContainerSummary& summary = sink->summary();
  switch (DetectRecordingKind(path)) {
    case RecordingKind::kMcap: {
      summary.format = ContainerFormat::kMcap;
      const MappedFile file(path);
      ReadMcapInto(file.bytes(), path, options, sink);
      return;
    }
    case RecordingKind::kRosbag1: {
      summary.format = ContainerFormat::kRosbag1;
      const MappedFile file(path);
      ReadRosbag1Into(file.bytes(), path, options, sink);
      return;
    }
    case RecordingKind::kRosbag2Sqlite:
      summary.format = ContainerFormat::kRosbag2Sqlite;
      ReadRosbag2SqliteInto(path, options, sink);
      return;
    case RecordingKind::kZstdFile: ReadDecompressedInto(path, options, sink); return;
    case RecordingKind::kRosbag2Folder: throw InputError(path, 0, "a folder, not a recording file");
    case RecordingKind::kCarmenLog: ThrowNotRos(path);
  }
}

ContainerSummary ReadRosRecording(const std::string& path, const ContainerReadOptions& options,
                                  const MessageCallback& on_message) {
  if (DetectRecordingKind(path) == RecordingKind::kRosbag2Folder) return ReadRosbag2Folder(path, options, on_message);
  ContainerSummary summary;
  ContainerSink sink(&summary, &on_message);
  ReadRecordingFileInto(path, options, &sink);
  return summary;
}

}  // namespace slamtune::io
