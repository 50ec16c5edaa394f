// Parallel-coordinates plots for the report (Inselberg): one vertical axis per variable, side by
// side, and one polyline per item joining its value on each axis. It shows a space of more than
// two parameters in one picture: which values the good items share (their lines bundle on an
// axis) and which parameters do not matter (the lines fan out over the whole axis).
//
// Each axis has its own limits, nice ticks in its own units (nice_ticks.h) and a title wrapped at
// underscores and spaces to the room between axes, so long ROS parameter names stay readable.
// A value beyond its axis's limits is drawn at the axis's end (PlaceOnAxis); for a line with
// `mark_clamped`, that vertex gets a triangle pointing the way the value lies and the value
// itself written beside it. Lines are drawn in order (later ones on top), then the axes and their
// labels over them, on white patches. The legend runs in rows under the title.
#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/report/figures/nice_ticks.h"
#include "slamtune/report/figures/plot.h"

namespace slamtune::report {

struct ParallelAxis {
  std::string title;  // under the axis; wrapped at '_' and ' ' to the room between axes
  std::string note;   // a line "(note)" under the title: a unit, "lower is better"; empty: none
  AxisLimits limits;  // the axis's bottom and top values, upper > lower, both finite
};

struct ParallelLine {
  std::vector<double> values;  // one per axis; a NaN or infinite value breaks the line there
  cv::Scalar colour;           // BGR
  int thickness = 1;           // px, in [1, 20]
  bool mark_clamped = false;   // a triangle and the value at each vertex beyond its axis
};

enum class LegendSample { kLine, kEndTriangle };

struct ParallelLegendEntry {
  std::string name;
  cv::Scalar colour;                          // BGR
  int thickness = 2;                          // px of the line sample
  LegendSample sample = LegendSample::kLine;  // kEndTriangle: the mark of a value beyond its axis
};

struct ParallelCoordinatesOptions {
  int width = 1560;          // px, total image width, >= 160
  int height = 600;          // px, total image height, >= 160
  std::string title;         // drawn above the legend; empty: none
  double font_scale = 0.45;  // Hershey simplex scale of labels, in (0, 4]; the title is 1.25x
  int target_ticks = 5;      // about this many ticks per axis, >= 2
  int marker_size = 12;      // px, the triangle at a clamped vertex, in [4, 100]

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

struct RenderedParallel {
  cv::Mat image;                   // CV_8UC3 BGR, options.height x options.width, white background
  std::vector<int> axis_x;         // px column of each axis
  int axis_top = 0;                // px row of every axis's upper limit
  int axis_bottom = 0;             // px row of every axis's lower limit
  std::vector<AxisLimits> limits;  // per axis, as given
  std::vector<AxisTicks> ticks;    // per axis, inside its limits
  int vertices_clamped = 0;        // finite values beyond their axis, drawn at its end

  // Pixel of `value` on axis `axis`, clamped to the axis's ends.
  cv::Point2d ToPixel(std::size_t axis, double value) const;
};

// Where a value is drawn on an axis that spans `limits`: at itself when inside them, else at
// the nearer end, marked as clamped. NaN stays NaN (not drawn), unclamped.
struct AxisPlacement {
  double value = 0.0;
  bool clamped = false;
};
AxisPlacement PlaceOnAxis(double value, const AxisLimits& limits);

// `text` split at '_' and ' ' into lines no wider than `max_width` px at `scale`, words joined
// with the character that separated them; a single word wider than `max_width` stays whole on
// its own line. Empty text: no lines.
std::vector<std::string> WrapLabel(const std::string& text, int max_width, double scale);

// Draws the axes and lines. Requires at least two axes and every line to hold one value per
// axis (a broken invariant otherwise); validates the options and each axis's limits first.
RenderedParallel RenderParallelCoordinates(const std::vector<ParallelAxis>& axes,
                                           const std::vector<ParallelLine>& lines,
                                           const std::vector<ParallelLegendEntry>& legend,
                                           const ParallelCoordinatesOptions& options);

}  // namespace slamtune::report
