// Map panels (map_panels.h).
#include "slamtune/report/figures/map_panels.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/report/figures/figure_style.h"
#include "slamtune/report/figures/plot.h"

namespace slamtune::report {
namespace {

constexpr int kPad = 6;  // px around text and map

struct Scaled {
  cv::Mat bgr;
  cv::Rect crop;        // cells of the map shown
  double factor = 1.0;  // px per cell
};

Scaled ScaledMap(const io::MapImage& map, const MapPanelOptions& options) {
  const cv::Mat view(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  const cv::Rect crop = options.crop ? KnownBounds(map, options.crop_margin) : cv::Rect(0, 0, map.width, map.height);
  const cv::Mat cropped = view(crop);
  double factor = static_cast<double>(options.height) / cropped.rows;
  if (cropped.cols * factor > options.max_width) factor = static_cast<double>(options.max_width) / cropped.cols;
  const cv::Size size(std::max(1, static_cast<int>(std::lround(cropped.cols * factor))),
                      std::max(1, static_cast<int>(std::lround(cropped.rows * factor))));
  cv::Mat scaled;
  cv::resize(cropped, scaled, size, 0, 0, factor < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
  Scaled out;
  cv::cvtColor(scaled, out.bgr, cv::COLOR_GRAY2BGR);
  out.crop = crop;
  out.factor = static_cast<double>(size.width) / cropped.cols;
  return out;
}

// Pixel of a world point in the scaled, cropped map (image rows grow downwards; row 0 is the
// map's largest y).
cv::Point2d ToPanel(const io::MapImage& map, const Scaled& s, double x, double y) {
  const double col = (x - map.origin.x) / map.resolution;
  const double row = map.height - (y - map.origin.y) / map.resolution;
  return {(col - s.crop.x) * s.factor, (row - s.crop.y) * s.factor};
}

cv::Point Px(const cv::Point2d& p) {
  return {static_cast<int>(std::lround(std::clamp(p.x, -1e6, 1e6))),
          static_cast<int>(std::lround(std::clamp(p.y, -1e6, 1e6)))};
}

void DrawOverlay(cv::Mat& body, const io::MapImage& map, const Scaled& s, const MapOverlay& overlay,
                 double font_scale) {
  const cv::Rect all(0, 0, body.cols, body.rows);
  if (overlay.path.size() >= 2) {
    cv::Mat layer = body.clone();
    for (std::size_t i = 1; i < overlay.path.size(); ++i) {
      cv::Point a = Px(ToPanel(map, s, overlay.path[i - 1].x, overlay.path[i - 1].y));
      cv::Point b = Px(ToPanel(map, s, overlay.path[i].x, overlay.path[i].y));
      if (cv::clipLine(all, a, b)) cv::line(layer, a, b, PaletteColour(5), 1, cv::LINE_AA);  // sky blue
    }
    cv::addWeighted(layer, 0.6, body, 0.4, 0.0, body);  // light, so walls stay readable under it
  }
  const cv::Scalar colour = PaletteColour(1);  // vermillion
  const int thickness = std::max(2, static_cast<int>(std::lround(body.cols / 300.0)));
  const int ring = 3 * thickness + 3;
  for (const MapSegment& seg : overlay.segments) {
    const cv::Point from = Px(ToPanel(map, s, seg.x0, seg.y0)), to = Px(ToPanel(map, s, seg.x1, seg.y1));
    cv::Point a = from, b = to;
    if (cv::clipLine(all, a, b)) cv::line(body, a, b, colour, thickness, cv::LINE_AA);
    if (all.contains(from)) cv::circle(body, from, thickness + 1, colour, cv::FILLED, cv::LINE_AA);
    if (!all.contains(to)) continue;
    cv::circle(body, to, ring, colour, thickness, cv::LINE_AA);
    if (seg.label.empty()) continue;
    const cv::Size ts = TextSize(seg.label, font_scale);
    cv::Point at(to.x + ring + 2, to.y - ts.height / 2);
    if (at.x + ts.width > body.cols) at.x = to.x - ring - 2 - ts.width;  // keep it inside the map
    at.y = std::clamp(at.y, 0, std::max(0, body.rows - ts.height));
    DrawText(body, seg.label, at, font_scale, cv::Scalar(255, 255, 255), 3);  // a white halo
    DrawText(body, seg.label, at, font_scale, colour, 1);
  }
}

// `text` broken at spaces into lines no wider than `width` px (a longer word keeps its own line).
std::vector<std::string> WrapText(const std::string& text, double scale, int width) {
  std::vector<std::string> lines;
  std::string line, word;
  auto flush_word = [&] {
    if (word.empty()) return;
    const std::string joined = line.empty() ? word : line + " " + word;
    if (!line.empty() && TextSize(joined, scale).width > width) {
      lines.push_back(line);
      line = word;
    } else {
      line = joined;
    }
    word.clear();
  };
  for (char c : text) {
    if (c == ' ')
      flush_word();
    else
      word += c;
  }
  flush_word();
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string MetresText(double m) {
  if (m >= 1.0) return fmt::format("{:.0f} m", m);
  if (m >= 0.01) return fmt::format("{:.0f} cm", m * 100.0);
  return fmt::format("{:.0f} mm", m * 1000.0);
}

}  // namespace

void MapPanelOptions::Validate() const {
  RequireOption(height >= 32 && height <= 4000, "MapPanelOptions.height", height, "must be in [32, 4000] px");
  RequireOption(max_width >= 32, "MapPanelOptions.max_width", max_width, "must be >= 32 px");
  RequireOption(crop_margin >= 0 && crop_margin <= 1000, "MapPanelOptions.crop_margin", crop_margin,
                "must be in [0, 1000] cells");
  RequireOption(font_scale > 0.0 && font_scale <= 4.0, "MapPanelOptions.font_scale", font_scale, "must be in (0, 4]");
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

double ScaleBarLength(double px_per_m, int width_px) {
  SLAMTUNE_CHECK(px_per_m > 0.0 && width_px > 0);
  const double most = 0.25 * width_px / px_per_m;  // m
  double length = std::pow(10.0, std::floor(std::log10(most)));
  for (double f : {5.0, 2.0}) {
    if (length * f <= most) {
      length *= f;
      break;
    }
  }
  return length;
}

cv::Mat RenderMapPanel(const io::MapImage& map, const std::string& label, const std::string& caption,
                       const MapPanelOptions& options, const MapOverlay& overlay) {
  options.Validate();
  cv::Mat body;
  double px_per_m = 0.0;
  if (HasMap(map)) {
    const Scaled scaled = ScaledMap(map, options);
    body = scaled.bgr;
    if (map.resolution > 0.0) {
      px_per_m = scaled.factor / map.resolution;
      DrawOverlay(body, map, scaled, overlay, options.font_scale * 0.8);
    }
  } else {
    body = cv::Mat(options.height, options.height * 3 / 4, CV_8UC3,
                   cv::Scalar(io::kMapUnknown, io::kMapUnknown, io::kMapUnknown));
    const std::string text = "no map rendered";
    const cv::Size ts = TextSize(text, options.font_scale * 0.85);
    DrawText(body, text, {std::max(kPad, (body.cols - ts.width) / 2), body.rows / 2 - ts.height / 2},
             options.font_scale * 0.85, cv::Scalar(60, 60, 60));
  }
  const double caption_scale = options.font_scale * 0.85;
  const cv::Size label_size = TextSize(label, options.font_scale, 2);
  // The caption wraps to the map's width (at least 320 px), so a long one does not widen the panel.
  const std::vector<std::string> caption_lines =
      WrapText(caption, caption_scale, std::max({body.cols + 2, label_size.width, 320}));
  const int caption_line_h = TextSize("Ag", caption_scale).height + 3;
  cv::Size caption_size(0, static_cast<int>(caption_lines.size()) * caption_line_h);
  for (const auto& line : caption_lines)
    caption_size.width = std::max(caption_size.width, TextSize(line, caption_scale).width);
  // The scale bar: its length in px and its text, under the map's left edge.
  const bool bar = options.scale_bar && px_per_m > 0.0;
  const double bar_m = bar ? ScaleBarLength(px_per_m, body.cols) : 0.0;
  const int bar_px = bar ? std::max(1, static_cast<int>(std::lround(bar_m * px_per_m))) : 0;
  const std::string bar_text = bar ? MetresText(bar_m) : "";
  const cv::Size bar_text_size = bar ? TextSize(bar_text, caption_scale) : cv::Size(0, 0);
  // The bar's row is kept without a map too, so placeholders line up with real panels.
  const int bar_h = options.scale_bar ? kPad + std::max(TextSize("0 m", caption_scale).height, 8) : 0;
  const int width = std::max({body.cols + 2, label_size.width, caption_size.width}) + 2 * kPad;
  const int height = kPad + label_size.height + kPad + body.rows + 2 + bar_h +
                     (caption_lines.empty() ? 0 : kPad + caption_size.height) + kPad;
  cv::Mat panel(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  DrawText(panel, label, {(width - label_size.width) / 2, kPad}, options.font_scale, cv::Scalar(0, 0, 0), 2);
  const int map_top = kPad + label_size.height + kPad;
  const cv::Rect frame((width - body.cols - 2) / 2, map_top, body.cols + 2, body.rows + 2);
  cv::rectangle(panel, frame, cv::Scalar(150, 150, 150), 1);
  body.copyTo(panel(cv::Rect(frame.x + 1, frame.y + 1, body.cols, body.rows)));
  if (bar) {
    const int y = frame.br().y + kPad + std::max(bar_text_size.height, 8) / 2;  // text heights agree: digits and "m"
    const int x0 = frame.x + 1, x1 = frame.x + bar_px;
    const cv::Scalar ink(40, 40, 40);
    cv::line(panel, {x0, y}, {x1, y}, ink, 2);
    cv::line(panel, {x0, y - 4}, {x0, y + 4}, ink, 2);
    cv::line(panel, {x1, y - 4}, {x1, y + 4}, ink, 2);
    DrawText(panel, bar_text, {x1 + kPad, y - bar_text_size.height / 2}, caption_scale, ink);
  }
  for (std::size_t i = 0; i < caption_lines.size(); ++i) {
    const cv::Size ts = TextSize(caption_lines[i], caption_scale);
    DrawText(panel, caption_lines[i],
             {(width - ts.width) / 2, frame.br().y + bar_h + kPad + static_cast<int>(i) * caption_line_h},
             caption_scale, cv::Scalar(60, 60, 60));
  }
  return panel;
}

}  // namespace slamtune::report
