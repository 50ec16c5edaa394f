// Occupancy maps as images, in the ROS map_server form (docs/engine.md §8.3):
// 8-bit grey, occupied 0, free 254, unknown 205, image row 0 = the map's top row (largest y),
// with a YAML (image, resolution, origin, negate, occupied_thresh, free_thresh).
//
// MapImage is what the engine writes, what the metrics read and what `slamtune evaluate`
// loads from maps made by other SLAM systems.
//
// Reading follows map_server's trinary rule (ROS1 map_server image_loader, nav2 map_io):
// p = (255 - v) / 255, or v / 255 with negate; p > occupied_thresh -> occupied,
// p < free_thresh -> free, else unknown. ReadMap stores the result as 0 / 254 / 205, so every
// MapImage it returns is trinary with negate = false and the ROS1 default thresholds (the
// values that describe those pixels), whatever the source file used.
//
// Only 8-bit single-channel images are accepted. Colour, grey+alpha and 16-bit images are
// rejected with an InputError rather than silently averaged or rescaled: a metric computed on
// a guessed conversion would not be comparable between maps.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::io {

inline constexpr std::uint8_t kMapOccupied = 0;
inline constexpr std::uint8_t kMapFree = 254;
inline constexpr std::uint8_t kMapUnknown = 205;

// map_server defaults (ROS1 map_saver writes these; nav2 uses free_thresh 0.25).
inline constexpr double kDefaultOccupiedThresh = 0.65;
inline constexpr double kDefaultFreeThresh = 0.196;
inline constexpr double kDefaultResolution = 0.05;  // m per cell, for a bare image

struct MapImage {
  int width = 0;
  int height = 0;
  double resolution = kDefaultResolution;           // m per cell
  Pose2 origin;                                     // world pose of the lower-left cell (map_server `origin`)
  bool negate = false;                              // true: p = v / 255 instead of (255 - v) / 255
  double occupied_thresh = kDefaultOccupiedThresh;  // p above this -> occupied
  double free_thresh = kDefaultFreeThresh;          // p below this -> free
  // Row-major grey values, width * height, row 0 = top row of the image.
  std::vector<std::uint8_t> pixels;

  std::uint8_t at(int col, int row) const { return pixels[static_cast<std::size_t>(row) * width + col]; }
};

// A width x height map of one grey value (e.g. kMapUnknown, to draw the known cells on), at the
// default resolution with its lower-left cell at the world origin.
MapImage UniformMap(int width, int height, std::uint8_t grey);

// The three classes of map_server's trinary rule.
enum class CellClass { kOccupied, kFree, kUnknown };

// map_server's rule for one grey value v under the given negate flag and thresholds.
CellClass ClassifyGrey(std::uint8_t v, bool negate, double occupied_thresh, double free_thresh);

// Throws InputError naming `what` (a file name or "map") if the map is empty (0 x 0), its
// pixel count is not width * height, the resolution is not finite and positive, or the
// thresholds are outside [0, 1] or free_thresh > occupied_thresh.
void ValidateMapImage(const MapImage& map, const std::string& what);

// Writes `yaml_path` and the PGM (P5) beside it: same folder and stem, extension .pgm. The
// YAML names the PGM by its bare file name (relative), with the map's resolution, origin
// [x, y, yaw], negate and thresholds written so that ReadMap gives back the same pixels,
// resolution and origin. Pixels are written as stored. Each file is written whole or not at all
// (atomic_file.h), the PGM before the YAML that names it. Throws InputError on an invalid map,
// or naming the file that could not be written (unwritable path, full disk).
void WriteMapServer(const MapImage& map, const std::string& yaml_path);

// Writes the pixels as an 8-bit grey PNG (lossless; resolution and origin are not stored),
// whole or not at all, as WriteMapServer does.
void WritePng(const MapImage& map, const std::string& png_path);

// Reads a map:
// * `.yaml` / `.yml`: map_server YAML. Required keys: image, resolution, origin (3 numbers),
//   occupied_thresh, free_thresh; optional negate (0/1, default 0) and mode (only "trinary"
//   or "scale", which classify the same way here). The image path is relative to the YAML's
//   folder unless absolute.
// * anything else: a PGM/PNG read alone with negate 0, the default thresholds, resolution
//   0.05 m and origin (0, 0, 0).
// Pixels are classified by ClassifyGrey and stored as 0 / 254 / 205. Throws InputError
// naming the file and the problem (unreadable, not an image, not 8-bit grey, missing or bad
// YAML key, missing image, empty map); images are decoded by image_codec.h, so nothing but that
// one error is printed.
MapImage ReadMap(const std::string& path);

}  // namespace slamtune::io
