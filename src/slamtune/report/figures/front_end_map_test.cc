#include "slamtune/report/figures/front_end_map.h"

#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::report {
namespace {

// A 20 x 10 m map (5 cm cells) of free space with a wall along its south side, origin (0, 0).
io::MapImage Room() {
  io::MapImage map = io::UniformMap(400, 200, io::kMapFree);
  for (int col = 0; col < map.width; ++col) map.pixels[static_cast<std::size_t>(map.height - 1) * map.width + col] = 0;
  return map;
}

int CountColour(const cv::Mat& image, const cv::Vec3b& colour) {
  int n = 0;
  for (int r = 0; r < image.rows; ++r)
    for (int c = 0; c < image.cols; ++c) n += image.at<cv::Vec3b>(r, c) == colour ? 1 : 0;
  return n;
}

// 40 scans along y = 5 m from x = 1 to x = 19.5 m; every other scan matched.
struct StraightRun {
  std::vector<io::TimedPose> trajectory;
  std::vector<slam::SequentialMatchStep> steps;
};
StraightRun Straight() {
  StraightRun run;
  for (int k = 0; k < 40; ++k) run.trajectory.push_back({0.2 * k, Pose2{1.0 + 0.5 * k, 5.0, 0.0}});
  for (int k = 1; k < 40; k += 2) {
    slam::SequentialMatchStep s;
    s.log_index = k;
    s.time = 0.2 * k;
    s.response = 0.8;
    run.steps.push_back(s);
  }
  return run;
}

TEST(RenderFrontEndMap, DrawsThePathEnlargedToAReadableSize) {
  const StraightRun run = Straight();
  const cv::Mat image = RenderFrontEndMap(Room(), run.trajectory, run.steps, slam::AssessFrontEnd(run.steps));
  EXPECT_GE(image.cols, 900);                                   // 400 known cells + margin, enlarged by a whole factor
  EXPECT_GT(CountColour(image, cv::Vec3b(200, 140, 60)), 100);  // the blue path
  EXPECT_EQ(CountColour(image, cv::Vec3b(0, 140, 255)), 0);     // no orange: nothing degenerate
}

TEST(RenderFrontEndMap, MarksDegenerateStretchesAndBreaks) {
  StraightRun run = Straight();
  slam::FrontEndEvidence evidence = slam::AssessFrontEnd(run.steps);
  slam::DegenerateStretch d;
  d.first_log_index = 5;
  d.last_log_index = 25;
  evidence.degenerate_stretches.push_back(d);
  // Scan 31: at the window's edge, collapsed, not undone.
  run.steps[15].at_window_edge = true;
  run.steps[15].response = 0.05;
  run.steps[15].dx = 0.15;
  evidence.median_response = 0.8;
  evidence.breaks = 1;
  const cv::Mat image = RenderFrontEndMap(Room(), run.trajectory, run.steps, evidence);
  EXPECT_GT(CountColour(image, cv::Vec3b(0, 140, 255)), 200);                                          // orange stretch
  EXPECT_GT(CountColour(image, cv::Vec3b(220, 0, 0)) + CountColour(image, cv::Vec3b(0, 0, 220)), 20);  // red ring
}

TEST(RenderFrontEndMap, RefusesAMapWithoutCellsAndBadOptions) {
  const StraightRun run = Straight();
  EXPECT_THROW(RenderFrontEndMap(io::MapImage{}, run.trajectory, run.steps, {}), InputError);
  FrontEndMapOptions bad;
  bad.max_side = 10;
  EXPECT_THROW(bad.Validate(), InputError);
}

}  // namespace
}  // namespace slamtune::report
