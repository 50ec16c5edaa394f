// Map panels (map_panels.h).
#include "slamtune/report/map_panels.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/report/plot.h"

namespace slamtune::report {
namespace {

constexpr int kPad = 6;  // px around text and map

void Require(bool ok, const std::string& field, double value, const std::string& rule) {
  if (!ok) throw InputError(fmt::format("{} = {}: {}", field, value, rule));
}

cv::Mat ScaledMap(const io::MapImage& map, const MapPanelOptions& options) {
  const cv::Mat view(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  const cv::Mat cropped = options.crop ? view(KnownBounds(map, options.crop_margin)) : view;
  double factor = static_cast<double>(options.height) / cropped.rows;
  if (cropped.cols * factor > options.max_width) factor = static_cast<double>(options.max_width) / cropped.cols;
  const cv::Size size(std::max(1, static_cast<int>(std::lround(cropped.cols * factor))),
                      std::max(1, static_cast<int>(std::lround(cropped.rows * factor))));
  cv::Mat scaled;
  cv::resize(cropped, scaled, size, 0, 0, factor < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
  cv::Mat bgr;
  cv::cvtColor(scaled, bgr, cv::COLOR_GRAY2BGR);
  return bgr;
}

}  // namespace

void MapPanelOptions::Validate() const {
  Require(height >= 32 && height <= 4000, "MapPanelOptions.height", height, "must be in [32, 4000] px");
  Require(max_width >= 32, "MapPanelOptions.max_width", max_width, "must be >= 32 px");
  Require(crop_margin >= 0 && crop_margin <= 1000, "MapPanelOptions.crop_margin", crop_margin,
          "must be in [0, 1000] cells");
  Require(font_scale > 0.0 && font_scale <= 4.0, "MapPanelOptions.font_scale", font_scale, "must be in (0, 4]");
}

bool HasMap(const io::MapImage& map) {
  return map.width > 0 && map.height > 0 &&
         map.pixels.size() == static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height);
}

cv::Rect KnownBounds(const io::MapImage& map, int margin) {
  SLAMTUNE_CHECK(HasMap(map));
  const cv::Mat view(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  const cv::Rect whole(0, 0, map.width, map.height);
  const cv::Mat known = view != io::kMapUnknown;
  if (cv::countNonZero(known) == 0) return whole;
  const cv::Rect box = cv::boundingRect(known);
  return cv::Rect(box.x - margin, box.y - margin, box.width + 2 * margin, box.height + 2 * margin) & whole;
}

cv::Mat RenderMapPanel(const io::MapImage& map, const std::string& label, const std::string& caption,
                       const MapPanelOptions& options) {
  options.Validate();
  cv::Mat body;
  if (HasMap(map)) {
    body = ScaledMap(map, options);
  } else {
    body = cv::Mat(options.height, options.height * 3 / 4, CV_8UC3, cv::Scalar(io::kMapUnknown, io::kMapUnknown,
                                                                                io::kMapUnknown));
    const std::string text = "no map rendered";
    const cv::Size ts = TextSize(text, options.font_scale * 0.85);
    DrawText(body, text, {std::max(kPad, (body.cols - ts.width) / 2), body.rows / 2 - ts.height / 2},
             options.font_scale * 0.85, cv::Scalar(60, 60, 60));
  }
  const double caption_scale = options.font_scale * 0.85;
  const cv::Size label_size = TextSize(label, options.font_scale, 2);
  const cv::Size caption_size = caption.empty() ? cv::Size(0, 0) : TextSize(caption, caption_scale);
  const int width = std::max({body.cols + 2, label_size.width, caption_size.width}) + 2 * kPad;
  const int height = kPad + label_size.height + kPad + body.rows + 2 + (caption.empty() ? 0 : kPad + caption_size.height) +
                     kPad;
  cv::Mat panel(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  DrawText(panel, label, {(width - label_size.width) / 2, kPad}, options.font_scale, cv::Scalar(0, 0, 0), 2);
  const int map_top = kPad + label_size.height + kPad;
  const cv::Rect frame((width - body.cols - 2) / 2, map_top, body.cols + 2, body.rows + 2);
  cv::rectangle(panel, frame, cv::Scalar(150, 150, 150), 1);
  body.copyTo(panel(cv::Rect(frame.x + 1, frame.y + 1, body.cols, body.rows)));
  if (!caption.empty()) {
    DrawText(panel, caption, {(width - caption_size.width) / 2, frame.br().y + kPad}, caption_scale,
             cv::Scalar(60, 60, 60));
  }
  return panel;
}

}  // namespace slamtune::report
