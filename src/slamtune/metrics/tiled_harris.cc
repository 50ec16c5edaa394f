#include "slamtune/metrics/tiled_harris.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"

namespace slamtune::metrics {

HarrisTiles TiledHarrisResponse(const cv::Mat& image, int block_size, int aperture, double k) {
  SLAMTUNE_CHECK(image.type() == CV_8UC1 && !image.empty());
  SLAMTUNE_CHECK(block_size >= 1);
  SLAMTUNE_CHECK(aperture == 1 || aperture == 3 || aperture == 5 || aperture == 7);
  // Reach of the filters from a pixel of `image` to the response: the Sobel radius (a
  // 3-tap kernel even for aperture 1) plus the box window's radius (anchor at block / 2).
  const int reach = std::max(1, aperture / 2) + block_size / 2;
  const cv::Rect whole(0, 0, image.cols, image.rows);
  HarrisTiles out;
  out.size = image.size();
  cv::Mat tile_response;
  for (int y = 0; y < image.rows; y += kHarrisTileSize) {
    for (int x = 0; x < image.cols; x += kHarrisTileSize) {
      const cv::Rect tile = cv::Rect(x, y, kHarrisTileSize, kHarrisTileSize) & whole;
      // Every pixel that can influence the tile's response; empty -> the response is 0.
      const cv::Rect around =
          cv::Rect(tile.x - reach, tile.y - reach, tile.width + 2 * reach, tile.height + 2 * reach) & whole;
      if (cv::countNonZero(image(around)) == 0) continue;
      // `image(around)` is a view: Sobel reads real pixels beyond it, and the box filter's
      // border effects stay within the `reach` margin that is dropped here.
      cv::cornerHarris(image(around), tile_response, block_size, aperture, k);
      out.tiles.push_back({tile, tile_response(tile - around.tl()).clone()});
    }
  }
  return out;
}

double HarrisTiles::MaxIn(const cv::Rect& window) const {
  const cv::Rect area = window & cv::Rect(0, 0, size.width, size.height);
  if (area.empty()) return 0.0;
  double best = -std::numeric_limits<double>::infinity();
  std::int64_t covered = 0;
  for (const Tile& tile : tiles) {
    const cv::Rect part = tile.rect & area;
    if (part.empty()) continue;
    double tile_max = 0.0;
    cv::minMaxLoc(tile.response(part - tile.rect.tl()), nullptr, &tile_max);
    best = std::max(best, tile_max);
    covered += part.area();
  }
  // Pixels outside every tile hold 0.
  if (covered < static_cast<std::int64_t>(area.area())) best = std::max(best, 0.0);
  return best;
}

cv::Mat HarrisTiles::Above(const cv::Rect& window, double threshold) const {
  SLAMTUNE_CHECK(threshold > 0.0);
  cv::Mat mask = cv::Mat::zeros(window.size(), CV_8UC1);
  for (const Tile& tile : tiles) {
    const cv::Rect part = tile.rect & window;
    if (part.empty()) continue;
    cv::Mat view = mask(part - window.tl());
    cv::compare(tile.response(part - tile.rect.tl()), threshold, view, cv::CMP_GT);
  }
  return mask;
}

cv::Mat HarrisTiles::Dense() const {
  cv::Mat dense = cv::Mat::zeros(size, CV_32FC1);
  for (const Tile& tile : tiles) tile.response.copyTo(dense(tile.rect));
  return dense;
}

}  // namespace slamtune::metrics
