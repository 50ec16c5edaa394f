#include "slamtune/report/sweep_report.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <limits>
#include <opencv2/imgcodecs.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/common/text_file.h"
#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::vector<SweepPoint> Points(bool gt) {
  std::vector<SweepPoint> points;
  for (int g = 20; g >= 6; g -= 2) {  // given out of order: the report sorts them
    points.push_back({static_cast<double>(g), testing::FakeRecord(2.0, g, (g - 6) / 14.0, gt)});
  }
  points.push_back(
      {7.0, optim::EvaluationRecord::Failed("k7", {{"loop_match_minimum_chain_size", 7}}, "matcher threw")});
  return points;
}

TEST(WriteSweepReport, WritesCsvFigureAndPage) {
  const fs::path dir = slamtune::testing::UniqueTempDir("sweep_gt");
  SweepReportOptions o;
  o.log_path = "intel.clf.gz";
  const auto summary = WriteSweepReport("loop_match_minimum_chain_size", Points(true), dir.string(), o);
  EXPECT_EQ(summary.points, 9);
  EXPECT_EQ(summary.failed, 1);
  EXPECT_TRUE(summary.with_ground_truth);
  const std::string csv = ReadWholeFile(dir / "sweep.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "parameter,value,status,reason,loop_closures,occupied_ratio,corner_pixels,enclosed_areas,"
            "occupied_ratio_known,corners,contours,occupied_cells,hits,hits_in_free_cells,hits_in_unknown_cells,"
            "unbacked_hits,drawn_wall_cells,nodes,wall_s,trans_mean_m,trans_std_m,rot_mean_deg,rot_std_deg,"
            "relations_used,loop_scans");
  // Sorted by value: 6 first (12 loop closures, error 0.02), then the failed 7, then 8.
  const auto expected6 = testing::FakeRecord(2.0, 6, 0.0, true);
  EXPECT_THAT(csv, HasSubstr("\nloop_match_minimum_chain_size,6,ok,,12,0.05,900,22,"));
  EXPECT_LT(csv.find("\nloop_match_minimum_chain_size,6,"),
            csv.find("\nloop_match_minimum_chain_size,7,failed,matcher threw,"));
  EXPECT_LT(csv.find(",7,failed,"), csv.find("\nloop_match_minimum_chain_size,8,"));
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 10);
  EXPECT_EQ(expected6.loop_closures, 12);

  const cv::Mat png = cv::imread((dir / "sweep.png").string());
  ASSERT_FALSE(png.empty());
  EXPECT_GE(png.cols, 3 * 460);  // 2 x 3 panels with ground truth
  EXPECT_GE(png.rows, 2 * 340);
  const std::string html = ReadWholeFile(dir / "sweep.html");
  EXPECT_THAT(html, HasSubstr("data:image/png;base64,iVBORw0KGgo"));
  EXPECT_THAT(html, HasSubstr("intel.clf.gz"));
  EXPECT_THAT(html, HasSubstr("failed: matcher threw"));
}

TEST(WriteSweepReport, WithoutGroundTruthHasNoErrorColumns) {
  const fs::path dir = slamtune::testing::UniqueTempDir("sweep_nogt");
  const auto summary = WriteSweepReport("loop_match_minimum_chain_size", Points(false), dir.string());
  EXPECT_FALSE(summary.with_ground_truth);
  EXPECT_THAT(ReadWholeFile(dir / "sweep.csv"), ::testing::Not(HasSubstr("trans_mean_m")));
  const cv::Mat png = cv::imread((dir / "sweep.png").string());
  EXPECT_LT(png.rows, 3 * 340);  // loop closures and four map figures: 2 rows of 3 panels
}

TEST(WriteSweepReport, SinglePointAndBadInput) {
  const fs::path dir = slamtune::testing::UniqueTempDir("sweep_one");
  EXPECT_NO_THROW(WriteSweepReport("r", {{2.0, testing::FakeRecord(2.0, 10, 0.5, false)}}, dir.string()));
  EXPECT_THROW(WriteSweepReport("", Points(false), dir.string()), InputError);
  EXPECT_THROW(WriteSweepReport("g", {}, dir.string()), InputError);
  EXPECT_THROW(WriteSweepReport("g", {{std::numeric_limits<double>::quiet_NaN(), {}}}, dir.string()), InputError);
}

}  // namespace
}  // namespace slamtune::report
