#include "slamtune/metrics/map_quality_overlay.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"

namespace slamtune::metrics {
namespace {

// Fill colours (BGR) for enclosed areas, cycled; light enough that walls and red corners show.
constexpr std::array<std::array<int, 3>, 6> kAreaColours = {
    {{230, 180, 120}, {140, 220, 140}, {120, 200, 240}, {220, 150, 220}, {200, 220, 110}, {150, 170, 250}}};
const cv::Scalar kCornerColour(0, 0, 230);
const cv::Scalar kCaptionColour(30, 30, 30);
constexpr int kCaptionHeight = 22;  // px

// The map as trinary grey (its own grey rule applied) in BGR.
cv::Mat TrinaryBgr(const io::MapImage& map) {
  cv::Mat lut(1, 256, CV_8UC1);
  for (int v = 0; v < 256; ++v) {
    switch (io::ClassifyGrey(static_cast<std::uint8_t>(v), map.negate, map.occupied_thresh, map.free_thresh)) {
      case io::CellClass::kOccupied: lut.at<std::uint8_t>(v) = io::kMapOccupied; break;
      case io::CellClass::kFree: lut.at<std::uint8_t>(v) = 255; break;
      case io::CellClass::kUnknown: lut.at<std::uint8_t>(v) = 170; break;  // darker than map_server's 205 for contrast
    }
  }
  const cv::Mat grey(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  cv::Mat trinary, bgr;
  cv::LUT(grey, lut, trinary);
  cv::cvtColor(trinary, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

}  // namespace

cv::Mat RenderMapQualityOverlay(const io::MapImage& map, const MapQualityDetail& detail) {
  SLAMTUNE_CHECK(detail.quality.width == map.width && detail.quality.height == map.height);
  cv::Mat image = TrinaryBgr(map);
  cv::Mat walls;
  cv::inRange(image, cv::Scalar(0, 0, 0), cv::Scalar(0, 0, 0), walls);

  // Enclosed areas, largest first so an area inside another keeps its own colour; then the
  // walls again on top, since a filled hole border covers the wall cells it runs along.
  std::vector<int> holes;
  for (int i = 0; i < static_cast<int>(detail.hierarchy.size()); ++i) {
    if (detail.hierarchy[i][3] >= 0) holes.push_back(i);
  }
  std::vector<double> area(detail.contours.size(), 0.0);
  for (int i : holes) area[i] = std::abs(cv::contourArea(detail.contours[i]));
  std::stable_sort(holes.begin(), holes.end(), [&](int a, int b) { return area[a] > area[b]; });
  for (std::size_t n = 0; n < holes.size(); ++n) {
    const auto& c = kAreaColours[n % kAreaColours.size()];
    cv::drawContours(image, detail.contours, holes[n], cv::Scalar(c[0], c[1], c[2]), cv::FILLED, cv::LINE_8);
  }
  image.setTo(cv::Scalar(0, 0, 0), walls);
  if (!detail.corner_mask.empty()) image(detail.corner_window).setTo(kCornerColour, detail.corner_mask);

  const int longer = std::max(map.width, map.height);
  const int scale = std::clamp(kOverlayTargetSide / longer, 1, kOverlayMaxScale);
  if (scale > 1) cv::resize(image, image, cv::Size(), scale, scale, cv::INTER_NEAREST);

  // A ring around each corner cluster, so single pixels are visible on large maps too.
  if (!detail.corner_mask.empty()) {
    cv::Mat labels, stats, centroids;
    const int n = cv::connectedComponentsWithStats(detail.corner_mask, labels, stats, centroids, 8, CV_32S);
    for (int i = 1; i < n; ++i) {
      const double cx = (detail.corner_window.x + centroids.at<double>(i, 0) + 0.5) * scale;
      const double cy = (detail.corner_window.y + centroids.at<double>(i, 1) + 0.5) * scale;
      const int extent = std::max(stats.at<int>(i, cv::CC_STAT_WIDTH), stats.at<int>(i, cv::CC_STAT_HEIGHT));
      const int radius = std::max(5, (extent * scale) / 2 + 3);
      cv::circle(image, cv::Point(static_cast<int>(std::lround(cx)), static_cast<int>(std::lround(cy))), radius,
                 kCornerColour, 1, cv::LINE_AA);
    }
  }

  const MapQuality& q = detail.quality;
  cv::Mat canvas(image.rows + kCaptionHeight, image.cols, CV_8UC3, cv::Scalar(255, 255, 255));
  image.copyTo(canvas(cv::Rect(0, kCaptionHeight, image.cols, image.rows)));
  const std::string caption = fmt::format("eta {:.4f}  n_c {} px ({} clusters)  n_e {}", q.occupied_ratio,
                                          q.corner_pixels, q.corners, q.enclosed_areas);
  cv::putText(canvas, caption, cv::Point(4, kCaptionHeight - 6), cv::FONT_HERSHEY_SIMPLEX, 0.45, kCaptionColour, 1,
              cv::LINE_AA);
  return canvas;
}

MapQuality WriteMapQualityOverlay(const io::MapImage& map, const MapQualityOptions& options,
                                  const std::string& png_path) {
  if (std::filesystem::path(png_path).extension() != ".png") {
    throw InputError(png_path, 0, "overlay output must end in .png");
  }
  const MapQualityDetail detail = AnalyseMapQuality(map, options);
  bool ok = false;
  try {
    ok = cv::imwrite(png_path, RenderMapQualityOverlay(map, detail));
  } catch (const cv::Exception& e) {
    throw InputError(png_path, 0, "cannot write the overlay: " + e.msg);
  }
  if (!ok) throw InputError(png_path, 0, "cannot write the overlay (missing folder or no permission?)");
  return detail.quality;
}

}  // namespace slamtune::metrics
