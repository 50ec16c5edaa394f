// Plot rendering on OpenCV (plot.h).
#include "slamtune/report/figures/plot.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/report/figures/figure_style.h"

namespace slamtune::report {
namespace {

constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
const cv::Scalar kGridGrey(225, 225, 225);

bool Finite(double x, double y) { return std::isfinite(x) && std::isfinite(y); }

// Data range of the finite points of all series along one coordinate.
std::pair<double, double> DataRange(const std::vector<Series>& series, bool along_x) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const Series& s : series) {
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!Finite(s.x[i], s.y[i])) continue;
      const double v = along_x ? s.x[i] : s.y[i];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  if (lo > hi) return {0.0, 1.0};  // no finite point at all
  return {lo, hi};
}

AxisTicks AxisFor(const std::vector<Series>& series, bool along_x, const std::optional<AxisLimits>& fixed, int target) {
  // Fixed limits: nice ticks inside them, but the axis spans exactly the limits.
  if (fixed) return MakeTicksWithin(fixed->lower, fixed->upper, target);
  const auto [lo, hi] = DataRange(series, along_x);
  AxisTicks ticks = MakeNiceTicks(lo, hi, target);
  // A 3 % margin keeps extreme points off the frame; the axis may then end between ticks.
  const double pad = std::isfinite(0.03 * (hi - lo)) ? 0.03 * (hi - lo) : 0.0;
  ticks.lower = std::min(ticks.lower, lo - pad);
  ticks.upper = std::max(ticks.upper, hi + pad);
  return ticks;
}

// The ticks at whole numbers, labelled without decimals (a generation 0.5 does not exist).
AxisTicks KeepWholeNumbers(AxisTicks ticks) {
  std::vector<double> values;
  std::vector<std::string> labels;
  for (double v : ticks.values) {
    if (std::abs(v - std::round(v)) > 1e-9 * std::max(1.0, std::abs(v))) continue;
    values.push_back(std::round(v));
    labels.push_back(FormatTick(std::round(v), 1.0));
  }
  ticks.values = std::move(values);
  ticks.labels = std::move(labels);
  return ticks;
}

void DrawMarker(cv::Mat& image, cv::Point centre, Marker marker, const cv::Scalar& colour, int size) {
  const int thickness = size >= 7 ? 2 : 1;
  switch (marker) {
    case Marker::kCircle: cv::circle(image, centre, std::max(size / 2, 1), colour, cv::FILLED, cv::LINE_AA); return;
    case Marker::kSquare:
      cv::drawMarker(image, centre, colour, cv::MARKER_SQUARE, size, thickness, cv::LINE_AA);
      return;
    case Marker::kTriangle:
      cv::drawMarker(image, centre, colour, cv::MARKER_TRIANGLE_UP, size, thickness, cv::LINE_AA);
      return;
    case Marker::kDiamond:
      cv::drawMarker(image, centre, colour, cv::MARKER_DIAMOND, size, thickness, cv::LINE_AA);
      return;
    case Marker::kCross:
      cv::drawMarker(image, centre, colour, cv::MARKER_TILTED_CROSS, size, thickness, cv::LINE_AA);
      return;
    case Marker::kPlus: cv::drawMarker(image, centre, colour, cv::MARKER_CROSS, size, thickness, cv::LINE_AA); return;
    case Marker::kStar: cv::drawMarker(image, centre, colour, cv::MARKER_STAR, size, thickness, cv::LINE_AA); return;
  }
}

bool HasMarkers(SeriesStyle style) { return style != SeriesStyle::kLine; }
bool HasLine(SeriesStyle style) { return style != SeriesStyle::kMarkers; }

// Vertical text: drawn horizontally on a white patch, then rotated a quarter turn.
void DrawRotatedText(cv::Mat& image, const std::string& text, cv::Point centre, double scale) {
  const cv::Size size = TextSize(text, scale);
  cv::Mat patch(size.height + 4, size.width + 4, CV_8UC3, kWhite);
  DrawText(patch, text, {2, 2}, scale, kBlack);
  cv::Mat rotated;
  cv::rotate(patch, rotated, cv::ROTATE_90_COUNTERCLOCKWISE);
  cv::Rect target(centre.x - rotated.cols / 2, centre.y - rotated.rows / 2, rotated.cols, rotated.rows);
  target &= cv::Rect(0, 0, image.cols, image.rows);
  rotated(cv::Rect(0, 0, target.width, target.height)).copyTo(image(target));
}

struct LegendEntry {
  std::string name;
  cv::Scalar colour;
  Marker marker;
  SeriesStyle style;
  int marker_size;
};

// The resolved style of series `index`: its own, else the defaults for its place.
LegendEntry StyleOf(const Series& s, std::size_t index, const PlotOptions& options) {
  return {s.name, s.colour.value_or(PaletteColour(index)), s.marker.value_or(MarkerFor(index)), s.style,
          s.marker_size.value_or(options.marker_size)};
}

// The named series' resolved styles, in order.
std::vector<LegendEntry> LegendEntries(const std::vector<Series>& series, const PlotOptions& options) {
  std::vector<LegendEntry> out;
  for (std::size_t i = 0; i < series.size(); ++i) {
    if (!series[i].name.empty()) out.push_back(StyleOf(series[i], i, options));
  }
  return out;
}

// One entry per line from `top_left` down, stopping before `bottom`.
void DrawLegend(cv::Mat& image, const std::vector<LegendEntry>& legend, cv::Point top_left, int bottom,
                const PlotOptions& options) {
  const int line_h = TextSize("Ag", options.font_scale).height;
  const int sample_w = std::max(options.marker_size, 18);
  int y = top_left.y;
  const int x = top_left.x;
  for (const LegendEntry& e : legend) {
    const int mid = y + line_h / 2;
    if (HasLine(e.style)) cv::line(image, {x, mid}, {x + sample_w, mid}, e.colour, options.line_thickness, cv::LINE_AA);
    if (HasMarkers(e.style))
      DrawMarker(image, {x + sample_w / 2, mid}, e.marker, e.colour, std::min(e.marker_size, line_h + 4));
    DrawText(image, e.name, {x + sample_w + kGap, y}, options.font_scale, kBlack);
    y += line_h + kGap;
    if (y > bottom) break;
  }
}

}  // namespace

void PanelSize::Validate(std::string_view owner) const {
  RequireOption(width >= 160, fmt::format("{}.width", owner), width, "must be >= 160 px");
  RequireOption(height >= 120, fmt::format("{}.height", owner), height, "must be >= 120 px");
  RequireOption(font_scale > 0.0 && font_scale <= 4.0, fmt::format("{}.font_scale", owner), font_scale,
                "must be in (0, 4]");
}

PlotOptions PanelSize::Plot() const {
  PlotOptions o;
  o.width = width;
  o.height = height;
  o.font_scale = font_scale;
  return o;
}

void PlotOptions::Validate() const {
  RequireOption(width >= 160, "PlotOptions.width", width, "must be >= 160 px");
  RequireOption(height >= 120, "PlotOptions.height", height, "must be >= 120 px");
  RequireOption(font_scale > 0.0 && font_scale <= 4.0, "PlotOptions.font_scale", font_scale, "must be in (0, 4]");
  RequireOption(target_ticks >= 2, "PlotOptions.target_ticks", target_ticks, "must be >= 2");
  RequireOption(marker_size >= 1 && marker_size <= 100, "PlotOptions.marker_size", marker_size,
                "must be in [1, 100] px");
  RequireOption(line_thickness >= 1 && line_thickness <= 20, "PlotOptions.line_thickness", line_thickness,
                "must be in [1, 20] px");
  for (const auto& [name, limits] : {std::pair{"x_limits", x_limits}, std::pair{"y_limits", y_limits}}) {
    if (!limits) continue;
    RequireOption(std::isfinite(limits->lower), fmt::format("PlotOptions.{}.lower", name), limits->lower,
                  "must be finite");
    RequireOption(std::isfinite(limits->upper) && limits->upper > limits->lower,
                  fmt::format("PlotOptions.{}.upper", name), limits->upper, "must be finite and > lower");
  }
}

void GridOptions::Validate() const {
  RequireOption(columns >= 1, "GridOptions.columns", columns, "must be >= 1");
  RequireOption(padding >= 0 && padding <= 200, "GridOptions.padding", padding, "must be in [0, 200] px");
  RequireOption(font_scale > 0.0 && font_scale <= 4.0, "GridOptions.font_scale", font_scale, "must be in (0, 4]");
}

Series MakeSeries(std::string name, std::vector<double> x, std::vector<double> y, SeriesStyle style) {
  Series s;
  s.name = std::move(name);
  s.x = std::move(x);
  s.y = std::move(y);
  s.style = style;
  return s;
}

cv::Scalar PaletteColour(std::size_t index) {
  // Okabe & Ito (2008), reordered so that the first colours contrast most on white; BGR.
  static const std::array<cv::Scalar, 8> kPalette = {
      cv::Scalar(178, 114, 0),    // blue
      cv::Scalar(0, 94, 213),     // vermillion
      cv::Scalar(115, 158, 0),    // bluish green
      cv::Scalar(167, 121, 204),  // reddish purple
      cv::Scalar(0, 159, 230),    // orange
      cv::Scalar(233, 180, 86),   // sky blue
      cv::Scalar(0, 0, 0),        // black
      cv::Scalar(66, 228, 240),   // yellow
  };
  return kPalette[index % kPalette.size()];
}

Marker MarkerFor(std::size_t index) {
  static const std::array<Marker, 7> kMarkers = {Marker::kCircle, Marker::kSquare, Marker::kTriangle, Marker::kDiamond,
                                                 Marker::kCross,  Marker::kPlus,   Marker::kStar};
  return kMarkers[index % kMarkers.size()];
}

cv::Size TextSize(const std::string& text, double scale, int thickness) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, thickness, &baseline);
  return {size.width, size.height + baseline};
}

cv::Size DrawText(cv::Mat& image, const std::string& text, cv::Point top_left, double scale, const cv::Scalar& colour,
                  int thickness) {
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, scale, thickness, &baseline);
  cv::putText(image, text, {top_left.x, top_left.y + size.height}, kFont, scale, colour, thickness, cv::LINE_AA);
  return {size.width, size.height + baseline};
}

cv::Point2d RenderedPlot::ToPixel(double x, double y) const {
  const double fx = (x - x_axis.lower) / (x_axis.upper - x_axis.lower);
  const double fy = (y - y_axis.lower) / (y_axis.upper - y_axis.lower);
  return {plot_area.x + fx * (plot_area.width - 1), plot_area.y + (1.0 - fy) * (plot_area.height - 1)};
}

namespace {

// The plot area within the image, and the legend's width (0: no legend), from the outside in.
struct PlotLayout {
  cv::Rect area;
  int legend_width = 0;
  int line_height = 0;  // of a line of text at the options' scale
};

PlotLayout LayOut(const RenderedPlot& plot, const std::vector<LegendEntry>& legend, const PlotOptions& options) {
  const double scale = options.font_scale;
  const double title_scale = scale * 1.25;
  PlotLayout layout;
  const int line_h = layout.line_height = TextSize("Ag", scale).height;
  int y_tick_width = 0;
  for (const auto& label : plot.y_axis.labels) y_tick_width = std::max(y_tick_width, TextSize(label, scale).width);
  const int sample_w = std::max(options.marker_size, 18);
  int legend_w = 0;
  if (options.legend) {
    for (const auto& e : legend) legend_w = std::max(legend_w, sample_w + kGap + TextSize(e.name, scale).width);
    if (legend_w > 0) legend_w += 2 * kGap + kMargin;
  }
  const int top =
      kMargin + (options.title.empty() ? line_h / 2 : TextSize(options.title, title_scale, 2).height + kGap);
  const int bottom = kMargin + kTickLength + kGap + line_h + (options.x_label.empty() ? 0 : line_h + kGap);
  const int left = kMargin + (options.y_label.empty() ? 0 : line_h + kGap) + y_tick_width + kGap + kTickLength;
  int right = kMargin + TextSize(plot.x_axis.labels.back(), scale).width / 2;
  if (options.width - left - right - legend_w < 60) legend_w = 0;  // too narrow: drop the legend
  right += legend_w;
  layout.legend_width = legend_w;
  layout.area =
      cv::Rect(left, top, std::max(options.width - left - right, 10), std::max(options.height - top - bottom, 10));
  return layout;
}

// Grid, ticks and tick labels, and the frame of the axes.
void DrawAxes(RenderedPlot& out, const PlotOptions& options) {
  cv::Mat& image = out.image;
  const cv::Rect& area = out.plot_area;
  const double scale = options.font_scale;
  for (std::size_t i = 0; i < out.x_axis.values.size(); ++i) {
    const int px = static_cast<int>(std::lround(out.ToPixel(out.x_axis.values[i], out.y_axis.lower).x));
    if (options.grid) cv::line(image, {px, area.y}, {px, area.br().y - 1}, kGridGrey, 1);
    cv::line(image, {px, area.br().y}, {px, area.br().y + kTickLength}, kBlack, 1);
    const cv::Size ts = TextSize(out.x_axis.labels[i], scale);
    DrawText(image, out.x_axis.labels[i], {px - ts.width / 2, area.br().y + kTickLength + kGap / 2}, scale, kTextGrey);
  }
  for (std::size_t i = 0; i < out.y_axis.values.size(); ++i) {
    const int py = static_cast<int>(std::lround(out.ToPixel(out.x_axis.lower, out.y_axis.values[i]).y));
    if (options.grid) cv::line(image, {area.x, py}, {area.br().x - 1, py}, kGridGrey, 1);
    cv::line(image, {area.x - kTickLength, py}, {area.x, py}, kBlack, 1);
    const cv::Size ts = TextSize(out.y_axis.labels[i], scale);
    DrawText(image, out.y_axis.labels[i], {area.x - kTickLength - kGap / 2 - ts.width, py - ts.height / 2}, scale,
             kTextGrey);
  }
  cv::rectangle(image, area, kBlack, 1);
}

// The title and the axis labels.
void DrawTitles(cv::Mat& image, const cv::Rect& area, int line_height, const PlotOptions& options) {
  const double scale = options.font_scale;
  const double title_scale = scale * 1.25;
  if (!options.title.empty()) {
    const cv::Size ts = TextSize(options.title, title_scale, 2);
    DrawText(image, options.title, {std::max(area.x + area.width / 2 - ts.width / 2, kMargin), kMargin}, title_scale,
             kBlack, 2);
  }
  if (!options.x_label.empty()) {
    const cv::Size ts = TextSize(options.x_label, scale);
    DrawText(image, options.x_label, {area.x + area.width / 2 - ts.width / 2, options.height - kMargin - ts.height},
             scale, kBlack);
  }
  if (!options.y_label.empty())
    DrawRotatedText(image, options.y_label, {kMargin + line_height / 2, area.y + area.height / 2}, scale);
}

// One series: its line clipped to the axes, then the markers of its points inside them (counted
// in `out`: drawn, outside the axes, or not finite).
void DrawSeries(RenderedPlot& out, const Series& s, const LegendEntry& st, const PlotOptions& options) {
  const cv::Rect& clip = out.plot_area;
  if (HasLine(s.style)) {
    for (std::size_t i = 1; i < s.x.size(); ++i) {
      if (!Finite(s.x[i - 1], s.y[i - 1]) || !Finite(s.x[i], s.y[i])) continue;  // gaps break the line
      const cv::Point2d a = out.ToPixel(s.x[i - 1], s.y[i - 1]), b = out.ToPixel(s.x[i], s.y[i]);
      // Far-out points (fixed limits) are clamped before the integer conversion.
      auto clamp = [](double v) { return static_cast<int>(std::lround(std::clamp(v, -1e6, 1e6))); };
      cv::Point p{clamp(a.x), clamp(a.y)}, q{clamp(b.x), clamp(b.y)};
      if (cv::clipLine(clip, p, q)) cv::line(out.image, p, q, st.colour, options.line_thickness, cv::LINE_AA);
    }
  }
  const double tol_x = 1e-9 * (out.x_axis.upper - out.x_axis.lower);
  const double tol_y = 1e-9 * (out.y_axis.upper - out.y_axis.lower);
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (!Finite(s.x[i], s.y[i])) {
      ++out.points_skipped;
      continue;
    }
    if (s.x[i] < out.x_axis.lower - tol_x || s.x[i] > out.x_axis.upper + tol_x || s.y[i] < out.y_axis.lower - tol_y ||
        s.y[i] > out.y_axis.upper + tol_y) {
      ++out.points_clipped;
      continue;
    }
    ++out.points_drawn;
    if (!HasMarkers(s.style)) continue;
    const cv::Point2d p = out.ToPixel(s.x[i], s.y[i]);
    DrawMarker(out.image, {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))}, st.marker,
               st.colour, st.marker_size);
  }
}

}  // namespace

RenderedPlot RenderPlot(const std::vector<Series>& series, const PlotOptions& options) {
  options.Validate();
  for (const Series& s : series) {
    SLAMTUNE_CHECK_MSG(s.x.size() == s.y.size(), "series '" + s.name + "' has x and y of different lengths");
  }
  RenderedPlot out;
  out.x_axis = AxisFor(series, true, options.x_limits, options.target_ticks);
  if (options.x_whole_numbers) out.x_axis = KeepWholeNumbers(std::move(out.x_axis));
  out.y_axis = AxisFor(series, false, options.y_limits, options.target_ticks);

  // Resolved styles of every series, and the legend's entries (the named series).
  std::vector<LegendEntry> styles;
  for (std::size_t i = 0; i < series.size(); ++i) styles.push_back(StyleOf(series[i], i, options));
  const std::vector<LegendEntry> legend = LegendEntries(series, options);

  const PlotLayout layout = LayOut(out, legend, options);
  out.plot_area = layout.area;
  out.image = cv::Mat(options.height, options.width, CV_8UC3, kWhite);
  DrawAxes(out, options);
  DrawTitles(out.image, out.plot_area, layout.line_height, options);
  for (std::size_t k = 0; k < series.size(); ++k) DrawSeries(out, series[k], styles[k], options);
  // Legend, right of the axes.
  if (layout.legend_width > 0) {
    DrawLegend(out.image, legend, {out.plot_area.br().x + kGap + kMargin / 2, out.plot_area.y}, out.plot_area.br().y,
               options);
  }
  return out;
}

cv::Mat RenderLegend(const std::vector<Series>& series, const PlotOptions& options) {
  options.Validate();
  cv::Mat image(options.height, options.width, CV_8UC3, kWhite);
  int top = kMargin;
  if (!options.title.empty()) {
    top += DrawText(image, options.title, {kMargin, top}, options.font_scale * 1.25, kBlack, 2).height + kGap;
  }
  DrawLegend(image, LegendEntries(series, options), {kMargin, top}, options.height - kMargin, options);
  return image;
}

cv::Mat ComposeGrid(const std::vector<cv::Mat>& panels, const GridOptions& options) {
  options.Validate();
  SLAMTUNE_CHECK_MSG(!panels.empty(), "ComposeGrid needs at least one panel");
  int cell_w = 0, cell_h = 0;
  for (const cv::Mat& p : panels) {
    SLAMTUNE_CHECK_MSG(!p.empty() && p.depth() == CV_8U && (p.channels() == 1 || p.channels() == 3),
                       "ComposeGrid panels must be non-empty 8-bit grey or BGR images");
    cell_w = std::max(cell_w, p.cols);
    cell_h = std::max(cell_h, p.rows);
  }
  const int columns = std::min<int>(options.columns, static_cast<int>(panels.size()));
  const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
  const int pad = options.padding;
  const int title_h = options.title.empty() ? 0 : TextSize(options.title, options.font_scale, 2).height + pad + kGap;
  const int width = columns * cell_w + (columns + 1) * pad;
  cv::Mat canvas(title_h + rows * cell_h + (rows + 1) * pad, width, CV_8UC3, kWhite);
  if (!options.title.empty()) {
    const cv::Size ts = TextSize(options.title, options.font_scale, 2);
    DrawText(canvas, options.title, {std::max(width / 2 - ts.width / 2, pad), pad + kGap / 2}, options.font_scale,
             kBlack, 2);
  }
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int r = static_cast<int>(i) / columns, c = static_cast<int>(i) % columns;
    cv::Mat bgr;
    if (panels[i].channels() == 1)
      cv::cvtColor(panels[i], bgr, cv::COLOR_GRAY2BGR);
    else
      bgr = panels[i];
    const int x = pad + c * (cell_w + pad) + (cell_w - bgr.cols) / 2;
    const int y = title_h + pad + r * (cell_h + pad) + (cell_h - bgr.rows) / 2;
    bgr.copyTo(canvas(cv::Rect(x, y, bgr.cols, bgr.rows)));
  }
  return canvas;
}

}  // namespace slamtune::report
