// Map-quality figures eta, n_c, n_e (map_quality.h; Han et al. 2020, Filatov et al. 2017).
#include "slamtune/metrics/map_quality.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/metrics/tiled_harris.h"

namespace slamtune::metrics {
namespace {

constexpr int kMaxKernel = 31;  // px; larger windows blur whole rooms together

// 256-entry table: 255 where map_server's rule gives `wanted` for that grey value, else 0.
cv::Mat ClassLut(const io::MapImage& map, io::CellClass wanted) {
  cv::Mat lut(1, 256, CV_8UC1);
  for (int v = 0; v < 256; ++v) {
    const bool hit =
        io::ClassifyGrey(static_cast<std::uint8_t>(v), map.negate, map.occupied_thresh, map.free_thresh) == wanted;
    lut.at<std::uint8_t>(v) = hit ? 255 : 0;
  }
  return lut;
}

// Zero border around the wall window wide enough that no filter below reaches past it:
// Gaussian radius + Sobel radius (ksize 1 still uses a 3-tap kernel) + Harris window radius,
// plus one pixel because findContours treats the image's outermost pixels as background.
int PaddingFor(const MapQualityOptions& o) {
  return o.blur_size / 2 + std::max(1, o.harris_aperture / 2) + o.harris_block_size / 2 + 1;
}

}  // namespace

void MapQualityOptions::Validate() const {
  auto fail = [](const std::string& field, const std::string& value, const std::string& rule) {
    throw InputError("map quality option " + field + " = " + value + ": " + rule);
  };
  if (blur_size < 1 || blur_size > kMaxKernel || blur_size % 2 == 0) {
    fail("blur_size", std::to_string(blur_size), "must be odd and in [1, 31] pixels");
  }
  if (!std::isfinite(blur_sigma) || blur_sigma < 0.0) {
    fail("blur_sigma", fmt::format("{}", blur_sigma), "must be >= 0 pixels (0 = derived from blur_size)");
  }
  if (harris_block_size < 2 || harris_block_size > kMaxKernel) {
    // A 1-pixel window gives det(M) = 0, so R = -k trace(M)^2 <= 0 and never a corner.
    fail("harris_block_size", std::to_string(harris_block_size), "must be in [2, 31] pixels");
  }
  if (harris_aperture != 1 && harris_aperture != 3 && harris_aperture != 5 && harris_aperture != 7) {
    fail("harris_aperture", std::to_string(harris_aperture), "must be 1, 3, 5 or 7 (Sobel aperture)");
  }
  if (!(harris_k > 0.0 && harris_k < 0.25)) {
    fail("harris_k", fmt::format("{}", harris_k), "must be in (0, 0.25)");
  }
  if (!(corner_threshold > 0.0 && corner_threshold <= 1.0)) {
    fail("corner_threshold", fmt::format("{}", corner_threshold),
         "must be in (0, 1] (a fraction of the largest Harris response)");
  }
}

std::string BriefReport(const MapQuality& q) {
  return fmt::format(
      "{}x{} cells: eta {:.6f} (known {:.6f}), n_c {} corner pixels ({} clusters), "
      "n_e {} enclosed areas ({} contours); {}",
      q.width, q.height, q.occupied_ratio, q.occupied_ratio_known, q.corner_pixels, q.corners, q.enclosed_areas,
      q.contours, q.message);
}

MapQualityDetail AnalyseMapQuality(const io::MapImage& map, const MapQualityOptions& options) {
  options.Validate();
  io::ValidateMapImage(map, "map");
  MapQualityDetail detail;
  MapQuality& q = detail.quality;
  q.width = map.width;
  q.height = map.height;
  q.resolution = map.resolution;

  // A header over the caller's pixels: no copy. Only read below.
  const cv::Mat grey(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  const std::int64_t cells = static_cast<std::int64_t>(map.width) * map.height;

  // eta: class counts by map_server's rule (one buffer, reused for the wall mask).
  cv::Mat mask;
  cv::LUT(grey, ClassLut(map, io::CellClass::kFree), mask);
  q.free_cells = cv::countNonZero(mask);
  cv::LUT(grey, ClassLut(map, io::CellClass::kOccupied), mask);  // wall mask: occupied 255, else 0
  q.occupied_cells = cv::countNonZero(mask);
  q.unknown_cells = cells - q.free_cells - q.occupied_cells;
  q.occupied_ratio = static_cast<double>(q.occupied_cells) / static_cast<double>(cells);
  const std::int64_t known = q.occupied_cells + q.free_cells;
  q.occupied_ratio_known = known > 0 ? static_cast<double>(q.occupied_cells) / static_cast<double>(known) : 0.0;
  if (q.occupied_cells == 0) {
    q.message = "no occupied cells: no corners and no enclosed areas";
    return detail;
  }

  // Work on the walls' bounding box with a zero border: the same result as the whole map
  // surrounded by non-wall, at the cost of the box only.
  const cv::Rect window = cv::boundingRect(mask);
  const int pad = PaddingFor(options);
  cv::Mat walls(window.height + 2 * pad, window.width + 2 * pad, CV_8UC1, cv::Scalar(0));
  mask(window).copyTo(walls(cv::Rect(pad, pad, window.width, window.height)));
  const cv::Point to_map(window.x - pad, window.y - pad);  // padded -> map pixel coordinates

  // n_c: smooth, Harris response R = det(M) - k trace(M)^2, threshold at a fraction of max R.
  cv::Mat smoothed;
  cv::GaussianBlur(walls, smoothed, cv::Size(options.blur_size, options.blur_size), options.blur_sigma,
                   options.blur_sigma);
  const HarrisTiles response =
      TiledHarrisResponse(smoothed, options.harris_block_size, options.harris_aperture, options.harris_k);
  // Only pixels of the map count (the padding outside the map image is not part of it).
  const cv::Rect in_map =
      cv::Rect(-to_map.x, -to_map.y, map.width, map.height) & cv::Rect(0, 0, walls.cols, walls.rows);
  detail.corner_window = in_map + to_map;
  const double max_response = response.MaxIn(in_map);
  q.max_corner_response = max_response;
  if (max_response > 0.0) {
    const double threshold = options.corner_threshold * max_response;
    detail.corner_mask = response.Above(in_map, threshold);
    q.corner_pixels = cv::countNonZero(detail.corner_mask);
    // Clusters: every 8-connected component has exactly one outer border (Suzuki & Abe 1985),
    // so counting RETR_EXTERNAL borders gives connectedComponents' count (tested) at a
    // quarter of its time on these sparse masks.
    std::vector<std::vector<cv::Point>> clusters;
    cv::findContours(detail.corner_mask, clusters, cv::RETR_EXTERNAL, cv::CHAIN_APPROX_SIMPLE);
    q.corners = static_cast<int>(clusters.size());
    q.message = fmt::format("walls within a {}x{} box; corner threshold {:.4g} = {} x largest response", window.width,
                            window.height, threshold, options.corner_threshold);
  } else {
    detail.corner_mask = cv::Mat::zeros(in_map.size(), CV_8UC1);
    q.message = "walls without any positive Harris response: no corners";
  }

  // n_e: two-level border following; holes (parent >= 0) are regions enclosed by walls.
  cv::findContours(walls, detail.contours, detail.hierarchy, cv::RETR_CCOMP, cv::CHAIN_APPROX_SIMPLE, to_map);
  q.contours = static_cast<int>(detail.contours.size());
  q.enclosed_areas = static_cast<int>(
      std::count_if(detail.hierarchy.begin(), detail.hierarchy.end(), [](const cv::Vec4i& h) { return h[3] >= 0; }));
  return detail;
}

MapQuality ComputeMapQuality(const io::MapImage& map, const MapQualityOptions& options) {
  return AnalyseMapQuality(map, options).quality;
}

}  // namespace slamtune::metrics
