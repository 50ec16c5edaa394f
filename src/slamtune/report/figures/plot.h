// A small plotting library for the report's figures, drawn with OpenCV on a cv::Mat canvas:
// scatter and line plots with axes, "nice" ticks (nice_ticks.h), axis labels, a title, a
// legend and several series with distinct colours and markers; and a grid of panels (e.g. the
// 1 x 3 objective-space projections) composed into one image. Encode the result with
// png_encoding.h.
//
// Why not an external plotter: the report must be produced offline, deterministically and
// without external tools, from the same binary that ran the optimisation.
//
// Degenerate data is drawn, never rejected: pairs with a NaN or infinite coordinate are
// skipped (and counted), an empty series only appears in the legend, a single point or
// all-equal values get an axis widened around them (MakeNiceTicks).
//
// Colours default to the Okabe & Ito (2008) colour-universal-design palette, which stays
// distinguishable for colour-blind readers; markers cycle as well so series differ in print.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "slamtune/report/figures/nice_ticks.h"

namespace slamtune::report {

enum class SeriesStyle { kMarkers, kLine, kLineAndMarkers };
enum class Marker { kCircle, kSquare, kTriangle, kDiamond, kCross, kPlus, kStar };

struct Series {
  std::string name;       // legend text; empty: not listed in the legend
  std::vector<double> x;  // data coordinates; x.size() must equal y.size()
  std::vector<double> y;
  SeriesStyle style = SeriesStyle::kMarkers;
  std::optional<cv::Scalar> colour;  // BGR; default PaletteColour(series index)
  std::optional<Marker> marker;      // default MarkerFor(series index)
  std::optional<int> marker_size;    // px; default PlotOptions::marker_size
};

// A series without designated initialisers (which -Wextra flags for the defaulted fields).
Series MakeSeries(std::string name, std::vector<double> x, std::vector<double> y,
                  SeriesStyle style = SeriesStyle::kMarkers);

struct AxisLimits {
  double lower = 0.0;
  double upper = 1.0;
};

struct PlotOptions {
  int width = 640;                     // px, total image width, >= 160
  int height = 480;                    // px, total image height, >= 120
  std::string title;                   // drawn above the plot; empty: none
  std::string x_label;                 // below the x axis; empty: none
  std::string y_label;                 // left of the y axis, rotated; empty: none
  double font_scale = 0.5;             // Hershey simplex scale of tick labels, in (0, 4]; titles are 1.25x
  int target_ticks = 6;                // about this many ticks per axis, >= 2
  int marker_size = 9;                 // px, marker width, in [1, 100]
  int line_thickness = 2;              // px, in [1, 20]
  bool grid = true;                    // light grid lines at the ticks
  bool x_whole_numbers = false;        // x ticks only at whole numbers (generations, counts)
  bool legend = true;                  // legend right of the plot when any series is named
  std::optional<AxisLimits> x_limits;  // fixed x range (e.g. shared by several panels)
  std::optional<AxisLimits> y_limits;  // fixed y range

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

// The size and font of every plot panel of one figure grid; the title and labels differ per panel.
struct PanelSize {
  int width = 520;           // px, width of one plot panel, >= 160
  int height = 420;          // px, height of one plot panel, >= 120
  double font_scale = 0.45;  // tick labels; titles 1.25x; in (0, 4]

  // Throws InputError naming `owner`.FIELD, its value and the rule.
  void Validate(std::string_view owner) const;
  // PlotOptions of this size and font, the rest at their defaults.
  PlotOptions Plot() const;
};

// What RenderPlot drew, and where.
struct RenderedPlot {
  cv::Mat image;           // CV_8UC3 BGR, options.height x options.width, white background
  int points_drawn = 0;    // finite points inside the axes
  int points_skipped = 0;  // pairs with a NaN or infinite coordinate
  int points_clipped = 0;  // finite points outside fixed limits (not drawn)
  AxisTicks x_axis;        // ticks; the axis spans [lower, upper]
  AxisTicks y_axis;
  cv::Rect plot_area;  // px: the data rectangle inside the axes

  // Pixel centre of a data point (x to the right, y up).
  cv::Point2d ToPixel(double x, double y) const;
};

// Draws the series in order (later ones on top). Validates the options first. Each series
// must have x.size() == y.size() (a broken invariant otherwise).
RenderedPlot RenderPlot(const std::vector<Series>& series, const PlotOptions& options);

// A legend on its own, for a grid of panels that share it: the named series of `series`
// listed as RenderPlot lists them, from the top-left of an options.width x options.height
// white image, under options.title as a heading (when not empty). Uses the options' sizes,
// font and line thickness; the axes' fields are ignored. Entries that do not fit are left out.
cv::Mat RenderLegend(const std::vector<Series>& series, const PlotOptions& options);

struct GridOptions {
  int columns = 3;          // panels per row, >= 1
  int padding = 8;          // px between and around panels, in [0, 200]
  std::string title;        // drawn across the top; empty: none
  double font_scale = 0.7;  // Hershey simplex scale of the title, in (0, 4]

  void Validate() const;
};

// Places the panels row by row in cells the size of the largest panel, each panel centred in
// its cell, on white. Grey panels are converted to BGR. `panels` must not be empty and every
// panel must be a non-empty 8-bit image (a broken invariant otherwise).
cv::Mat ComposeGrid(const std::vector<cv::Mat>& panels, const GridOptions& options);

// Okabe-Ito colour `index` (cycled), BGR.
cv::Scalar PaletteColour(std::size_t index);
// Marker `index` (cycled).
Marker MarkerFor(std::size_t index);

// Draws `text` with its top-left corner at `top_left` (Hershey simplex, antialiased) and
// returns its size in px. Shared by the other figure builders.
cv::Size DrawText(cv::Mat& image, const std::string& text, cv::Point top_left, double scale, const cv::Scalar& colour,
                  int thickness = 1);
// Size DrawText would take.
cv::Size TextSize(const std::string& text, double scale, int thickness = 1);

}  // namespace slamtune::report
