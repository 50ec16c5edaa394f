#include "slamtune/io/ros/rosbag2_folder.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/mapped_file.h"

namespace slamtune::io {
namespace {

namespace fs = std::filesystem;

std::string Lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string Scalar(const YAML::Node& map, const char* key) {
  const YAML::Node value = map[key];
  return value && value.IsScalar() ? value.Scalar() : std::string();
}

Rosbag2Metadata ParseMetadata(const YAML::Node& root, const std::string& path) {
  const YAML::Node info = root.IsMap() ? root["rosbag2_bagfile_information"] : YAML::Node();
  if (!info || !info.IsMap()) throw InputError(path, 0, "no rosbag2_bagfile_information map");
  Rosbag2Metadata metadata;
  metadata.storage_identifier = Scalar(info, "storage_identifier");
  metadata.compression_mode = Lower(Scalar(info, "compression_mode"));
  metadata.compression_format = Lower(Scalar(info, "compression_format"));
  if (metadata.compression_mode == "none") metadata.compression_mode.clear();
  const YAML::Node files = info["relative_file_paths"];
  if (files && files.IsSequence()) {
    for (const YAML::Node& file : files) {
      if (file.IsScalar() && !file.Scalar().empty()) metadata.relative_file_paths.push_back(file.Scalar());
    }
  }
  if (metadata.relative_file_paths.empty()) throw InputError(path, 0, "no relative_file_paths: the bag lists no files");
  if (!metadata.compression_mode.empty() && metadata.compression_mode != "file" &&
      metadata.compression_mode != "message") {
    throw InputError(path, 0, "unknown compression_mode \"" + metadata.compression_mode + "\"");
  }
  if (!metadata.compression_mode.empty() && metadata.compression_format != "zstd") {
    throw InputError(path, 0,
                     "compression_format \"" + metadata.compression_format + "\" is not supported (only zstd)");
  }
  return metadata;
}

// Where the split `relative` of `folder` is (see rosbag2_folder.h); "" when nowhere.
std::string FindSplit(const std::string& folder, const std::string& relative, const Rosbag2Metadata& metadata) {
  std::vector<fs::path> candidates = {fs::path(folder) / relative, fs::path(folder) / fs::path(relative).filename()};
  if (metadata.compression_mode == "file") {
    for (std::size_t i = 0, n = candidates.size(); i < n; ++i) candidates.push_back(candidates[i].string() + ".zstd");
  }
  for (const fs::path& candidate : candidates) {
    std::error_code error;
    if (fs::is_regular_file(candidate, error)) return candidate.string();
  }
  return {};
}

}  // namespace

Rosbag2Metadata ReadRosbag2Metadata(const std::string& folder) {
  const std::string path = (fs::path(folder) / kRosbag2MetadataFile).string();
  CheckReadable(path);
  try {
    return ParseMetadata(YAML::Load(ReadTextFile(path)), path);  // a byte-order mark is stripped
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.is_null() ? 0 : static_cast<std::size_t>(e.mark.line) + 1, e.msg);
  }
}

std::vector<std::string> Rosbag2SplitFiles(const std::string& folder, const Rosbag2Metadata& metadata) {
  // Every split is found before any is read: one file listed twice (by the same or another name)
  // would deliver each of its messages twice.
  std::vector<std::string> paths;
  for (std::size_t k = 0; k < metadata.relative_file_paths.size(); ++k) {
    const std::string& relative = metadata.relative_file_paths[k];
    const std::string path = FindSplit(folder, relative, metadata);
    if (path.empty()) {
      throw InputError((fs::path(folder) / relative).string(), 0,
                       "missing: listed in metadata.yaml's relative_file_paths, but there is no such file");
    }
    for (std::size_t j = 0; j < paths.size(); ++j) {
      std::error_code error;
      if (paths[j] == path || fs::equivalent(paths[j], path, error)) {
        throw InputError((fs::path(folder) / kRosbag2MetadataFile).string(), 0,
                         fmt::format("relative_file_paths lists {} twice (entries {} and {}, \"{}\" and \"{}\"): "
                                     "refused, as reading it twice would give every message twice; remove the "
                                     "repeated entry",
                                     path, j + 1, k + 1, metadata.relative_file_paths[j], relative));
      }
    }
    paths.push_back(path);
  }
  return paths;
}

}  // namespace slamtune::io
