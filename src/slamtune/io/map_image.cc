// Map images in and out (map_image.h; docs/engine.md §8.3 for the format).
#include "slamtune/io/map_image.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <opencv2/core.hpp>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/image_codec.h"

namespace slamtune::io {
namespace {

namespace fs = std::filesystem;

std::string LowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

bool IsYamlPath(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".yaml" || ext == ".yml";
}

// A read-only view of the pixels as a cv::Mat header (no copy). OpenCV's constructor takes a
// non-const pointer; the view is only passed to functions that read it.
cv::Mat PixelView(const MapImage& map) {
  return cv::Mat(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
}

// Shortest text that reads back as the same double (fmt's round-trip formatting).
std::string NumberText(double v) { return fmt::format("{}", v); }

// Checks the file is there, is a regular file and can be opened, so that the errors below
// can say "not an image" rather than a vague decode failure.
void RequireReadableFile(const std::string& path, const std::string& role) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec || !fs::exists(status)) throw InputError(path, 0, "cannot open " + role + ": no such file");
  if (fs::is_directory(status)) throw InputError(path, 0, "cannot open " + role + ": is a directory");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw InputError(path, 0, "cannot open " + role + ": permission denied or unreadable");
}

// Loads an 8-bit single-channel image or throws InputError naming the file (image_codec.h).
// `suffix` is appended to each message (e.g. which YAML named the image).
GreyImage LoadGrey8(const std::string& path, const std::string& suffix) {
  RequireReadableFile(path, "map image" + suffix);
  return DecodeGreyImage(ReadWholeFile(path), path, suffix);
}

// map_server's rule applied to every pixel through a 256-entry lookup table.
MapImage Classify(const GreyImage& image, bool negate, double occupied_thresh, double free_thresh) {
  const cv::Mat grey(image.height, image.width, CV_8UC1, const_cast<std::uint8_t*>(image.pixels.data()));
  cv::Mat lut(1, 256, CV_8UC1);
  for (int v = 0; v < 256; ++v) {
    switch (ClassifyGrey(static_cast<std::uint8_t>(v), negate, occupied_thresh, free_thresh)) {
      case CellClass::kOccupied: lut.at<std::uint8_t>(v) = kMapOccupied; break;
      case CellClass::kFree: lut.at<std::uint8_t>(v) = kMapFree; break;
      case CellClass::kUnknown: lut.at<std::uint8_t>(v) = kMapUnknown; break;
    }
  }
  MapImage map;
  map.width = image.width;
  map.height = image.height;
  map.pixels.resize(static_cast<std::size_t>(map.width) * map.height);
  cv::Mat out = PixelView(map);
  cv::LUT(grey, lut, out);
  SLAMTUNE_CHECK(out.data == map.pixels.data());  // LUT wrote into our buffer, no reallocation
  return map;
}

// YAML helpers: each names the file, the key and the rule.
YAML::Node RequireKey(const YAML::Node& root, const std::string& key, const std::string& path) {
  const YAML::Node node = root[key];
  if (!node) throw InputError(path, 0, "missing required key '" + key + "'");
  return node;
}

double AsNumber(const YAML::Node& node, const std::string& key, const std::string& path) {
  const int line = node.Mark().line + 1;
  double v = 0.0;
  try {
    v = node.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(path, line, "key '" + key + "' must be a number");
  }
  if (!std::isfinite(v)) throw InputError(path, line, "key '" + key + "' must be finite, got " + NumberText(v));
  return v;
}

bool AsNegate(const YAML::Node& node, const std::string& path) {
  const int line = node.Mark().line + 1;
  try {
    const int v = node.as<int>();
    if (v == 0 || v == 1) return v == 1;
  } catch (const YAML::Exception&) {
    try {
      return node.as<bool>();
    } catch (const YAML::Exception&) {
    }
  }
  throw InputError(path, line, "key 'negate' must be 0 or 1");
}

MapImage ReadYaml(const std::string& path) {
  RequireReadableFile(path, "map YAML");
  YAML::Node root;
  try {
    root = YAML::Load(ReadTextFile(path));
  } catch (const YAML::Exception& e) {
    throw InputError(path, static_cast<std::size_t>(e.mark.line + 1), "invalid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw InputError(path, 0, "not a map_server YAML: expected a mapping of keys");

  const YAML::Node image_node = RequireKey(root, "image", path);
  std::string image_name;
  try {
    image_name = image_node.as<std::string>();
  } catch (const YAML::Exception&) {
  }
  if (image_name.empty()) {
    throw InputError(path, image_node.Mark().line + 1, "key 'image' must be a non-empty file name");
  }
  const double resolution = AsNumber(RequireKey(root, "resolution", path), "resolution", path);
  const YAML::Node origin = RequireKey(root, "origin", path);
  if (!origin.IsSequence() || origin.size() != 3) {
    throw InputError(path, origin.Mark().line + 1, "key 'origin' must be a list of 3 numbers [x, y, yaw]");
  }
  const double occupied = AsNumber(RequireKey(root, "occupied_thresh", path), "occupied_thresh", path);
  const double free = AsNumber(RequireKey(root, "free_thresh", path), "free_thresh", path);
  const bool negate = root["negate"] ? AsNegate(root["negate"], path) : false;
  if (const YAML::Node mode = root["mode"]) {
    const std::string m = mode.IsScalar() ? mode.Scalar() : std::string();
    if (m != "trinary" && m != "scale") {
      throw InputError(path, mode.Mark().line + 1,
                       "key 'mode' is '" + m + "'; only 'trinary' and 'scale' maps are supported");
    }
  }

  MapImage probe;  // validate the numbers before touching the image
  probe.width = probe.height = 1;
  probe.pixels.assign(1, kMapUnknown);
  probe.resolution = resolution;
  probe.occupied_thresh = occupied;
  probe.free_thresh = free;
  ValidateMapImage(probe, path);

  fs::path image_path(image_name);
  if (image_path.is_relative()) image_path = fs::path(path).parent_path() / image_path;
  const GreyImage grey = LoadGrey8(image_path.string(), " (named by " + path + ")");
  MapImage map = Classify(grey, negate, occupied, free);
  map.resolution = resolution;
  map.origin = Pose2{AsNumber(origin[0], "origin[0]", path), AsNumber(origin[1], "origin[1]", path),
                     AsNumber(origin[2], "origin[2]", path)};
  return map;
}

}  // namespace

MapImage UniformMap(int width, int height, std::uint8_t grey) {
  MapImage map;
  map.width = width;
  map.height = height;
  map.pixels.assign(static_cast<std::size_t>(width) * height, grey);
  return map;
}

CellClass ClassifyGrey(std::uint8_t v, bool negate, double occupied_thresh, double free_thresh) {
  // map_server: p = (255 - v) / 255 (or v / 255 with negate); occupied tested first.
  const double p = negate ? v / 255.0 : (255.0 - v) / 255.0;
  if (p > occupied_thresh) return CellClass::kOccupied;
  if (p < free_thresh) return CellClass::kFree;
  return CellClass::kUnknown;
}

void ValidateMapImage(const MapImage& map, const std::string& what) {
  if (map.width <= 0 || map.height <= 0) {
    throw InputError(what, 0,
                     fmt::format("empty map ({} x {} cells); a map needs at least one cell", map.width, map.height));
  }
  const std::size_t expected = static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height);
  if (map.pixels.size() != expected) {
    throw InputError(what, 0,
                     fmt::format("map has {} pixels but width x height = {} x {} = {}", map.pixels.size(), map.width,
                                 map.height, expected));
  }
  if (!std::isfinite(map.resolution) || map.resolution <= 0.0) {
    throw InputError(what, 0, "resolution = " + NumberText(map.resolution) + " m/cell; must be finite and > 0");
  }
  for (const auto& [name, value] :
       {std::pair{"occupied_thresh", map.occupied_thresh}, std::pair{"free_thresh", map.free_thresh}}) {
    if (!(value >= 0.0 && value <= 1.0)) {
      throw InputError(what, 0, std::string(name) + " = " + NumberText(value) + "; must be in [0, 1]");
    }
  }
  if (map.free_thresh > map.occupied_thresh) {
    throw InputError(what, 0,
                     "free_thresh = " + NumberText(map.free_thresh) + " > occupied_thresh = " +
                         NumberText(map.occupied_thresh) + "; free_thresh must not exceed occupied_thresh");
  }
}

void WriteMapServer(const MapImage& map, const std::string& yaml_path) {
  if (!IsYamlPath(yaml_path)) {
    throw InputError(yaml_path, 0, "map YAML must end in .yaml or .yml (the PGM is written beside it)");
  }
  ValidateMapImage(map, yaml_path);
  const fs::path pgm_path = fs::path(yaml_path).replace_extension(".pgm");

  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "image" << YAML::Value << pgm_path.filename().string();
  out << YAML::Key << "resolution" << YAML::Value << NumberText(map.resolution);
  out << YAML::Key << "origin" << YAML::Value << YAML::Flow << YAML::BeginSeq << NumberText(map.origin.x)
      << NumberText(map.origin.y) << NumberText(map.origin.theta) << YAML::EndSeq;
  out << YAML::Key << "negate" << YAML::Value << (map.negate ? 1 : 0);
  out << YAML::Key << "occupied_thresh" << YAML::Value << NumberText(map.occupied_thresh);
  out << YAML::Key << "free_thresh" << YAML::Value << NumberText(map.free_thresh);
  out << YAML::EndMap;
  SLAMTUNE_CHECK_MSG(out.good(), out.GetLastError());

  // The PGM first: the YAML that names it appears only once the PGM is whole.
  WriteFileAtomically(pgm_path.string(), EncodePgm(map.width, map.height, map.pixels.data()));
  WriteFileAtomically(yaml_path, std::string(out.c_str()) + "\n");
}

void WritePng(const MapImage& map, const std::string& png_path) {
  if (LowerExtension(png_path) != ".png") throw InputError(png_path, 0, "PNG output must end in .png");
  ValidateMapImage(map, png_path);
  WriteFileAtomically(png_path, EncodeGreyPng(map.width, map.height, map.pixels.data()));
}

MapImage ReadMap(const std::string& path) {
  if (IsYamlPath(path)) return ReadYaml(path);
  return Classify(LoadGrey8(path, ""), false, kDefaultOccupiedThresh, kDefaultFreeThresh);
}

}  // namespace slamtune::io
