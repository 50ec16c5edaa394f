// Parallel-coordinates rendering on OpenCV (parallel_coordinates.h).
#include "slamtune/report/figures/parallel_coordinates.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"
#include "slamtune/report/figures/figure_style.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

constexpr int kLegendSample = 30;   // px, the line sample of a legend entry
constexpr int kLegendSpacing = 24;  // px between legend entries in a row

// The legend's entries placed in rows of at most `width` px; returns each entry's top-left
// corner relative to the legend's origin and the legend's height.
std::pair<std::vector<cv::Point>, int> LayOutLegend(const std::vector<ParallelLegendEntry>& legend, int width,
                                                    double scale) {
  std::vector<cv::Point> at;
  const int line_h = TextSize("Ag", scale).height;
  int x = 0, y = 0;
  for (const ParallelLegendEntry& e : legend) {
    const int w = kLegendSample + kGap + TextSize(e.name, scale).width;
    if (x > 0 && x + w > width) {
      x = 0;
      y += line_h + kGap;
    }
    at.emplace_back(x, y);
    x += w + kLegendSpacing;
  }
  return {at, legend.empty() ? 0 : y + line_h};
}

// Text on a white patch, so lines behind it do not cross it.
void DrawTextOnWhite(cv::Mat& image, const std::string& text, cv::Point top_left, double scale,
                     const cv::Scalar& colour) {
  const cv::Size size = TextSize(text, scale);
  cv::Rect patch(top_left.x - 1, top_left.y - 1, size.width + 2, size.height + 1);
  patch &= cv::Rect(0, 0, image.cols, image.rows);
  image(patch).setTo(kWhite);
  DrawText(image, text, top_left, scale, colour);
}

// A filled triangle pointing up (above an axis) or down (below it), its base `gap` px from `end`.
void DrawEndTriangle(cv::Mat& image, cv::Point end, bool up, int size, const cv::Scalar& colour) {
  const int dir = up ? -1 : 1;
  const int base = end.y + dir * kGap / 2;
  const cv::Point tri[3] = {{end.x - size / 2, base}, {end.x + size / 2, base}, {end.x, base + dir * size}};
  cv::fillConvexPoly(image, tri, 3, colour, cv::LINE_AA);
}

void DrawParallelLegend(cv::Mat& image, const std::vector<ParallelLegendEntry>& legend,
                        const std::vector<cv::Point>& at, cv::Point origin, double scale) {
  const int line_h = TextSize("Ag", scale).height;
  for (std::size_t i = 0; i < legend.size(); ++i) {
    const cv::Point p = origin + at[i];
    const int mid = p.y + line_h / 2;
    if (legend[i].sample == LegendSample::kEndTriangle) {
      DrawEndTriangle(image, {p.x + kLegendSample / 2, mid + line_h / 2}, true, line_h, legend[i].colour);
    } else {
      cv::line(image, {p.x, mid}, {p.x + kLegendSample, mid}, legend[i].colour, std::clamp(legend[i].thickness, 1, 8),
               cv::LINE_AA);
    }
    DrawText(image, legend[i].name, {p.x + kLegendSample + kGap, p.y}, scale, kBlack);
  }
}

}  // namespace

void ParallelCoordinatesOptions::Validate() const {
  RequireOption(width >= 160, "ParallelCoordinatesOptions.width", width, "must be >= 160 px");
  RequireOption(height >= 160, "ParallelCoordinatesOptions.height", height, "must be >= 160 px");
  RequireOption(font_scale > 0.0 && font_scale <= 4.0, "ParallelCoordinatesOptions.font_scale", font_scale,
                "must be in (0, 4]");
  RequireOption(target_ticks >= 2, "ParallelCoordinatesOptions.target_ticks", target_ticks, "must be >= 2");
  RequireOption(marker_size >= 4 && marker_size <= 100, "ParallelCoordinatesOptions.marker_size", marker_size,
                "must be in [4, 100] px");
}

AxisPlacement PlaceOnAxis(double value, const AxisLimits& limits) {
  if (std::isnan(value)) return {value, false};
  if (value < limits.lower) return {limits.lower, true};
  if (value > limits.upper) return {limits.upper, true};
  return {value, false};
}

std::vector<std::string> WrapLabel(const std::string& text, int max_width, double scale) {
  // Words, each keeping the separator that preceded it.
  std::vector<std::string> words;
  std::string word;
  for (char ch : text) {
    if ((ch == '_' || ch == ' ') && !word.empty()) {
      words.push_back(word);
      word.clear();
    }
    word += ch;
  }
  if (!word.empty()) words.push_back(word);
  std::vector<std::string> lines;
  for (const std::string& w : words) {
    if (!lines.empty() && TextSize(lines.back() + w, scale).width <= max_width) {
      lines.back() += w;
    } else {
      // A new line does not start with the separator.
      lines.push_back(lines.empty() || (w[0] != '_' && w[0] != ' ') ? w : w.substr(1));
    }
  }
  return lines;
}

cv::Point2d RenderedParallel::ToPixel(std::size_t axis, double value) const {
  SLAMTUNE_CHECK(axis < axis_x.size() && axis < limits.size());
  const AxisLimits& l = limits[axis];
  const double f = std::clamp((value - l.lower) / (l.upper - l.lower), 0.0, 1.0);
  return {static_cast<double>(axis_x[axis]), axis_bottom - f * (axis_bottom - axis_top)};
}

namespace {

// The inputs' rules: finite limits, upper above lower, one value per axis on every line.
void RequireParallelInput(const std::vector<ParallelAxis>& axes, const std::vector<ParallelLine>& lines) {
  for (std::size_t a = 0; a < axes.size(); ++a) {
    const AxisLimits& l = axes[a].limits;
    RequireOption(std::isfinite(l.lower), fmt::format("ParallelAxis[{}].limits.lower", a), l.lower, "must be finite");
    RequireOption(std::isfinite(l.upper) && l.upper > l.lower, fmt::format("ParallelAxis[{}].limits.upper", a), l.upper,
                  "must be finite and > lower");
  }
  for (const ParallelLine& line : lines) {
    SLAMTUNE_CHECK_MSG(line.values.size() == axes.size(), "a parallel-coordinates line needs one value per axis");
  }
}

// A value beyond its axis, on a line that marks such values.
struct ClampedValue {
  std::size_t axis;
  double value;
  cv::Scalar colour;
};

// The lines, clamped at the axes' ends, in order; returns the values to mark beyond their axis.
std::vector<ClampedValue> DrawParallelLines(const std::vector<ParallelAxis>& axes,
                                            const std::vector<ParallelLine>& lines, RenderedParallel& out) {
  cv::Mat& image = out.image;
  std::vector<ClampedValue> marks;
  for (const ParallelLine& line : lines) {
    std::optional<cv::Point> previous;
    for (std::size_t a = 0; a < axes.size(); ++a) {
      const double v = line.values[a];
      if (!std::isfinite(v)) {
        previous.reset();
        continue;
      }
      const AxisPlacement p = PlaceOnAxis(v, axes[a].limits);
      if (p.clamped) {
        ++out.vertices_clamped;
        if (line.mark_clamped) marks.push_back({a, v, line.colour});
      }
      const cv::Point2d px = out.ToPixel(a, p.value);
      const cv::Point here(static_cast<int>(std::lround(px.x)), static_cast<int>(std::lround(px.y)));
      if (previous) cv::line(image, *previous, here, line.colour, std::clamp(line.thickness, 1, 20), cv::LINE_AA);
      previous = here;
    }
  }
  return marks;
}

// Axes, ticks and labels over the lines, each axis's title lines `clamp_room` px below it.
void DrawParallelAxes(const std::vector<std::vector<std::string>>& titles, int clamp_room, double scale,
                      RenderedParallel& out) {
  cv::Mat& image = out.image;
  const int line_h = TextSize("Ag", scale).height;
  for (std::size_t a = 0; a < out.axis_x.size(); ++a) {
    const int x = out.axis_x[a];
    cv::line(image, {x, out.axis_top}, {x, out.axis_bottom}, kBlack, 1);
    for (std::size_t i = 0; i < out.ticks[a].values.size(); ++i) {
      const int py = static_cast<int>(std::lround(out.ToPixel(a, out.ticks[a].values[i]).y));
      cv::line(image, {x - kTickLength, py}, {x, py}, kBlack, 1);
      const cv::Size ts = TextSize(out.ticks[a].labels[i], scale);
      DrawTextOnWhite(image, out.ticks[a].labels[i], {x - kTickLength - 2 - ts.width, py - ts.height / 2}, scale,
                      kTextGrey);
    }
    int ty = out.axis_bottom + clamp_room;
    for (const std::string& t : titles[a]) {
      const cv::Size ts = TextSize(t, scale);
      DrawText(image, t, {x - ts.width / 2, ty}, scale, kBlack);
      ty += line_h + 3;
    }
  }
}

// Values beyond an axis: a triangle the way they lie, and the value.
void DrawClampedValues(const std::vector<ParallelAxis>& axes, const std::vector<ClampedValue>& marks,
                       const ParallelCoordinatesOptions& options, RenderedParallel& out) {
  cv::Mat& image = out.image;
  const double scale = options.font_scale;
  for (const ClampedValue& m : marks) {
    const bool up = m.value > axes[m.axis].limits.upper;
    const cv::Point end(out.axis_x[m.axis], up ? out.axis_top : out.axis_bottom);
    DrawEndTriangle(image, end, up, options.marker_size, m.colour);
    const std::string text = Readable(m.value);
    const cv::Size ts = TextSize(text, scale);
    const int ty =
        up ? end.y - kGap / 2 - options.marker_size - 2 - ts.height : end.y + kGap / 2 + options.marker_size + 2;
    DrawText(image, text, {end.x - ts.width / 2, ty}, scale, m.colour);
  }
}

}  // namespace

RenderedParallel RenderParallelCoordinates(const std::vector<ParallelAxis>& axes,
                                           const std::vector<ParallelLine>& lines,
                                           const std::vector<ParallelLegendEntry>& legend,
                                           const ParallelCoordinatesOptions& options) {
  options.Validate();
  SLAMTUNE_CHECK_MSG(axes.size() >= 2, "a parallel-coordinates plot needs at least two axes");
  RequireParallelInput(axes, lines);
  const double scale = options.font_scale;
  const double title_scale = scale * 1.25;
  const int line_h = TextSize("Ag", scale).height;
  const int n = static_cast<int>(axes.size());

  RenderedParallel out;
  out.image = cv::Mat(options.height, options.width, CV_8UC3, kWhite);
  cv::Mat& image = out.image;
  for (const ParallelAxis& a : axes) {
    out.limits.push_back(a.limits);
    out.ticks.push_back(MakeTicksWithin(a.limits.lower, a.limits.upper, options.target_ticks));
  }

  // Columns: the room per axis bounds its wrapped title; the first axis's tick labels and the
  // last axis's title set the side margins.
  const int column = std::max((options.width - 2 * kMargin) / n - kGap, 20);
  std::vector<std::vector<std::string>> titles;
  std::size_t title_lines = 0;
  for (const ParallelAxis& a : axes) {
    std::vector<std::string> t = WrapLabel(a.title, column, scale);
    if (!a.note.empty()) t.push_back("(" + a.note + ")");
    title_lines = std::max(title_lines, t.size());
    titles.push_back(std::move(t));
  }
  auto widest = [&](const std::vector<std::string>& texts) {
    int w = 0;
    for (const auto& t : texts) w = std::max(w, TextSize(t, scale).width);
    return w;
  };
  const int left =
      kMargin + std::max(widest(out.ticks.front().labels) + kTickLength + kGap, widest(titles.front()) / 2);
  const int right = kMargin + std::max(widest(titles.back()) / 2, options.marker_size);
  const double spacing = static_cast<double>(options.width - left - right) / (n - 1);
  for (int a = 0; a < n; ++a) out.axis_x.push_back(left + static_cast<int>(std::lround(a * spacing)));

  // Rows: title, legend, the room for a clamped value above the axes, the axes, the room below
  // them, the axis titles.
  int y = kMargin;
  if (!options.title.empty()) {
    const cv::Size ts = TextSize(options.title, title_scale, 2);
    DrawText(image, options.title, {std::max(options.width / 2 - ts.width / 2, kMargin), y}, title_scale, kBlack, 2);
    y += ts.height + kGap;
  }
  const auto [legend_at, legend_h] = LayOutLegend(legend, options.width - 2 * kMargin, scale);
  const int legend_y = y;
  y += legend_h + (legend.empty() ? 0 : kGap);
  const int clamp_room = options.marker_size + line_h + 2 * kGap;
  out.axis_top = y + clamp_room;
  const int titles_h = static_cast<int>(title_lines) * (line_h + 3);
  out.axis_bottom = std::max(out.axis_top + 20, options.height - kMargin - titles_h - kGap - clamp_room);

  const std::vector<ClampedValue> marks = DrawParallelLines(axes, lines, out);
  DrawParallelAxes(titles, clamp_room, scale, out);
  DrawClampedValues(axes, marks, options, out);
  DrawParallelLegend(image, legend, legend_at, {kMargin, legend_y}, scale);
  return out;
}

}  // namespace slamtune::report
