// Harris corner response (Harris & Stephens 1988) of a sparse image, tile by tile.
//
// The numbers of cv::cornerHarris on the whole image (to float rounding), computed only on
// tiles that hold a non-zero pixel within reach of the filters; elsewhere the response is 0,
// as it is for OpenCV on an all-zero neighbourhood. Wall masks are sparse (a few % of the
// cells), and 128-pixel tiles keep OpenCV's intermediate images (two derivative planes and a
// 3-channel structure tensor, all float) inside the L2 cache: on a dense 2000 x 2000 office
// map this halves the time of the whole-image call (bench/bench_map_quality.cc).
//
// Why it matches: each tile is passed as a view into the whole image, so Sobel reads the
// true neighbours across the tile edge, and the structure tensor is box-filtered with a
// margin that is cut off afterwards. What remains is float rounding: OpenCV's vectorised
// loops and their scalar tails round differently, and a tile moves pixels between them, so a
// value may differ in its last bits (tested: <= 1e-6 of the largest response; thresholded
// corner masks of wall maps are identical). Results are deterministic for a given image.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace slamtune::metrics {

inline constexpr int kHarrisTileSize = 128;  // pixels per tile side

// The response where it was computed: tiles (disjoint, in row-major order) with their CV_32F
// values; 0 everywhere else. Kept sparse because a dense float image of a building-sized map
// (30 M pixels) costs more to allocate and zero than the tiles cost to compute.
struct HarrisTiles {
  struct Tile {
    cv::Rect rect;     // in image pixels
    cv::Mat response;  // CV_32F, rect.size()
  };
  cv::Size size;  // of the image
  std::vector<Tile> tiles;

  // The largest response within `window` (image pixels): over the computed pixels, and 0 if
  // some pixel of the window lies in no tile; 0 for an empty window. Equal to cv::minMaxLoc's
  // maximum over Dense()(window).
  double MaxIn(const cv::Rect& window) const;
  // 255 where the response inside `window` exceeds `threshold` (> 0), else 0; window-sized
  // CV_8U. Equal to Dense()(window) > threshold.
  cv::Mat Above(const cv::Rect& window, double threshold) const;
  // The whole response as one CV_32F image, for comparison with cv::cornerHarris (tests).
  cv::Mat Dense() const;
};

// Response R = det(M) - k trace(M)^2 of an 8-bit single-channel image, with cv::cornerHarris's
// arguments and default border. Preconditions (checked): `image` is CV_8UC1 and non-empty,
// block_size >= 1, aperture in {1, 3, 5, 7}.
HarrisTiles TiledHarrisResponse(const cv::Mat& image, int block_size, int aperture, double k);

}  // namespace slamtune::metrics
