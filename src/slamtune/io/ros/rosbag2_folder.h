// A rosbag2 bag folder (docs/recordings.md §1.1): metadata.yaml, whose
// rosbag2_bagfile_information lists the split files (relative_file_paths, in recording order),
// their storage (storage_identifier: sqlite3 or mcap) and compression (compression_mode
// file / message, compression_format zstd), and the split files themselves.
//
// What the folder lists is read here; the splits themselves are read by ReadRosRecording
// (ros_recording.h), one after the other into one ContainerSummary: topics with the same name
// and type are one topic whichever split they come from. Each split's format is judged by its
// content (a file-compressed split, `*.db3.zstd` / `*.mcap.zstd`, is decompressed into memory
// first); with compression_mode message every payload is a zstd frame, decompressed before the
// callback sees it. A listed split is looked for as written, by its base name in the folder
// (early rosbag2 wrote paths with the folder name in front) and, file-compressed, with ".zstd"
// appended; a split found under none of them is an InputError naming it.
#pragma once

#include <string>
#include <vector>

namespace slamtune::io {

inline constexpr const char* kRosbag2MetadataFile = "metadata.yaml";

// What metadata.yaml says that the reader uses. Modes and formats are lower-cased; "none" is "".
struct Rosbag2Metadata {
  std::string storage_identifier;                // "sqlite3", "mcap"
  std::vector<std::string> relative_file_paths;  // split files, in order
  std::string compression_mode;                  // "", "file" or "message"
  std::string compression_format;                // "" or "zstd"
};

// Parses FOLDER/metadata.yaml. InputError "FOLDER/metadata.yaml[:LINE]: ..." for a file that
// cannot be read, is not YAML, has no rosbag2_bagfile_information or no relative_file_paths,
// or names a compression other than zstd.
Rosbag2Metadata ReadRosbag2Metadata(const std::string& folder);

// The paths of the split files `metadata` lists for the bag folder `folder`, in order, each found
// as described above. InputError "FOLDER/SPLIT: missing: ..." for a split found nowhere, and
// "FOLDER/metadata.yaml: relative_file_paths lists PATH twice ..." for one file listed twice (it
// would give every message twice).
std::vector<std::string> Rosbag2SplitFiles(const std::string& folder, const Rosbag2Metadata& metadata);

}  // namespace slamtune::io
