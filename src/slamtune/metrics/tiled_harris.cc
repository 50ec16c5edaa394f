#include "slamtune/metrics/tiled_harris.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"

namespace slamtune::metrics {

cv::Mat TiledHarrisResponse(const cv::Mat& image, int block_size, int aperture, double k) {
  SLAMTUNE_CHECK(image.type() == CV_8UC1 && !image.empty());
  SLAMTUNE_CHECK(block_size >= 1);
  SLAMTUNE_CHECK(aperture == 1 || aperture == 3 || aperture == 5 || aperture == 7);
  // Reach of the filters from a pixel of `image` to the response: the Sobel radius (a
  // 3-tap kernel even for aperture 1) plus the box window's radius (anchor at block / 2).
  const int reach = std::max(1, aperture / 2) + block_size / 2;
  const cv::Rect whole(0, 0, image.cols, image.rows);
  cv::Mat response = cv::Mat::zeros(image.size(), CV_32FC1);
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
      tile_response(tile - around.tl()).copyTo(response(tile));
    }
  }
  return response;
}

}  // namespace slamtune::metrics
