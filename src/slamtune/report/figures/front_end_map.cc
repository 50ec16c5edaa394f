#include "slamtune/report/figures/front_end_map.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>

#include "slamtune/common/error.h"
#include "slamtune/report/figures/map_panels.h"

namespace slamtune::report {
namespace {

const cv::Scalar kPath(200, 140, 60);       // BGR: blue
const cv::Scalar kDegenerate(0, 140, 255);  // orange
const cv::Scalar kSuspect(200, 0, 200);     // magenta
const cv::Scalar kBreak(0, 0, 220);         // red
const cv::Scalar kText(30, 30, 30);

// World position -> pixel of the cropped, scaled image.
struct PixelFrame {
  const io::MapImage* map = nullptr;
  cv::Rect crop;
  double scale = 1.0;
  cv::Point At(double x, double y) const {
    const double col = (x - map->origin.x) / map->resolution - crop.x;
    const double row = (map->height - (y - map->origin.y) / map->resolution) - crop.y;
    return {static_cast<int>(std::lround(col * scale)), static_cast<int>(std::lround(row * scale))};
  }
};

bool Within(const slam::SequentialMatchStep& s, int first, int last) {
  return s.log_index >= first && s.log_index <= last;
}

// Polyline through the final poses of the steps with log index in [first, last].
void DrawPath(cv::Mat& image, const PixelFrame& frame, const std::vector<io::TimedPose>& trajectory,
              const std::vector<slam::SequentialMatchStep>& steps, int first, int last, const cv::Scalar& colour,
              int thickness) {
  std::vector<cv::Point> points;
  for (const slam::SequentialMatchStep& s : steps) {
    if (!Within(s, first, last) || s.log_index < 0 || s.log_index >= static_cast<int>(trajectory.size())) continue;
    const Pose2& p = trajectory[static_cast<std::size_t>(s.log_index)].pose;
    points.push_back(frame.At(p.x, p.y));
  }
  if (points.size() == 1) cv::circle(image, points[0], thickness, colour, cv::FILLED, cv::LINE_AA);
  if (points.size() > 1) cv::polylines(image, points, false, colour, thickness, cv::LINE_AA);
}

}  // namespace

using slam::SequentialMatchStep;  // in the functions below

void FrontEndMapOptions::Validate() const {
  if (min_side < 64) throw InputError(fmt::format("FrontEndMapOptions.min_side = {}: must be >= 64", min_side));
  if (max_side < min_side) {
    throw InputError(fmt::format("FrontEndMapOptions.max_side = {}: must be >= min_side = {}", max_side, min_side));
  }
  if (crop_margin < 0 || crop_margin > 1000) {
    throw InputError(fmt::format("FrontEndMapOptions.crop_margin = {}: must be in [0, 1000]", crop_margin));
  }
}

cv::Mat RenderFrontEndMap(const io::MapImage& map, const std::vector<io::TimedPose>& trajectory,
                          const std::vector<slam::SequentialMatchStep>& steps, const slam::FrontEndEvidence& evidence,
                          const FrontEndMapOptions& options) {
  options.Validate();
  if (!HasMap(map)) throw InputError("front-end map: the run's map has no cells");
  PixelFrame frame;
  frame.map = &map;
  frame.crop = KnownBounds(map, options.crop_margin);
  const int side = std::max(frame.crop.width, frame.crop.height);
  frame.scale = side >= options.min_side ? 1.0 : std::ceil(static_cast<double>(options.min_side) / side);
  if (side * frame.scale > options.max_side) frame.scale = static_cast<double>(options.max_side) / side;

  const cv::Mat grey(map.height, map.width, CV_8UC1, const_cast<std::uint8_t*>(map.pixels.data()));
  cv::Mat scaled, image;
  cv::resize(grey(frame.crop), scaled, cv::Size(), frame.scale, frame.scale,
             frame.scale < 1.0 ? cv::INTER_AREA : cv::INTER_NEAREST);
  cv::cvtColor(scaled, image, cv::COLOR_GRAY2BGR);

  const int thin = std::max(1, image.cols / 600), thick = 3 * thin;
  DrawPath(image, frame, trajectory, steps, 0, 1 << 30, kPath, thin);
  for (const slam::DegenerateStretch& d : evidence.degenerate_stretches) {
    DrawPath(image, frame, trajectory, steps, d.first_log_index, d.last_log_index, kDegenerate, thick);
  }
  for (const slam::SuspectStretch& s : evidence.stretches) {
    DrawPath(image, frame, trajectory, steps, s.first_log_index, s.last_log_index, kSuspect, thick);
  }
  const double font = 0.5 * thin;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const SequentialMatchStep& s = steps[i];
    if (s.log_index < 0 || s.log_index >= static_cast<int>(trajectory.size())) continue;
    if (!slam::IsBreak(steps, i, evidence.median_response, {})) continue;
    const Pose2& p = trajectory[static_cast<std::size_t>(s.log_index)].pose;
    const cv::Point at = frame.At(p.x, p.y);
    cv::circle(image, at, 6 * thin, kBreak, thin + 1, cv::LINE_AA);
    cv::putText(image, fmt::format("break, scan {}", s.log_index), at + cv::Point(8 * thin, -4 * thin),
                cv::FONT_HERSHEY_SIMPLEX, font, kBreak, thin, cv::LINE_AA);
  }

  // Legend under the map.
  const std::string legend = fmt::format(
      "blue: path ({} matches)   orange: {} degenerate stretch{}   magenta: {} suspect stretch{}   red: {} break{}",
      evidence.matches, evidence.degenerate_stretches.size(), evidence.degenerate_stretches.size() == 1 ? "" : "es",
      evidence.stretches.size(), evidence.stretches.size() == 1 ? "" : "es", evidence.breaks,
      evidence.breaks == 1 ? "" : "s");
  int baseline = 0;
  const double legend_font = std::max(0.4, 0.45 * thin);
  const cv::Size text = cv::getTextSize(legend, cv::FONT_HERSHEY_SIMPLEX, legend_font, thin, &baseline);
  cv::Mat out(image.rows + text.height + 16, std::max(image.cols, text.width + 16), CV_8UC3, cv::Scalar(255, 255, 255));
  image.copyTo(out(cv::Rect(0, 0, image.cols, image.rows)));
  cv::putText(out, legend, cv::Point(8, image.rows + text.height + 6), cv::FONT_HERSHEY_SIMPLEX, legend_font, kText,
              thin, cv::LINE_AA);
  return out;
}

}  // namespace slamtune::report
