// Occupancy maps as images, in the ROS map_server form (karto-algorithm.md §8.3):
// 8-bit grey, occupied 0, free 254, unknown 205, image row 0 = the map's top row (largest y),
// with a YAML (image, resolution, origin, negate, occupied_thresh, free_thresh).
//
// MapImage is what the engine writes, what the metrics read and what `slamtune evaluate`
// loads from maps made by other SLAM systems.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::io {

inline constexpr std::uint8_t kMapOccupied = 0;
inline constexpr std::uint8_t kMapFree = 254;
inline constexpr std::uint8_t kMapUnknown = 205;

struct MapImage {
  int width = 0;
  int height = 0;
  double resolution = 0.05;  // m per cell
  Pose2 origin;              // world pose of the lower-left cell (map_server `origin`)
  bool negate = false;
  double occupied_thresh = 0.65;
  double free_thresh = 0.196;
  // Row-major grey values, width * height, row 0 = top row of the image.
  std::vector<std::uint8_t> pixels;

  std::uint8_t at(int col, int row) const { return pixels[static_cast<std::size_t>(row) * width + col]; }
};

}  // namespace slamtune::io
