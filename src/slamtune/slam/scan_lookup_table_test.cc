#include "slamtune/slam/scan_lookup_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

std::shared_ptr<const LaserGeometry> FourBeams() {
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = -0.6;
  g->angular_resolution = 0.4;
  g->num_readings = 4;
  g->min_range = 0.5;  // beam 0 below min range: still used (§2.2 [QUIRK])
  g->max_range = 80;
  g->range_threshold = 12;
  return g;
}

TEST(ScanLookupTable, OffsetsAreLinearAndInvalidOnlyForNonFinite) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{0.3, nan, inf, 50.0});
  const LaserScan scan(FourBeams(), ranges, Pose2{1.0, 2.0, 0.3}, 0.0);
  ScanLookupTable table;
  const double scale = 20.0;
  const std::int32_t stride = 648;
  table.Compute(scan, 0.3, 0.1, 0.05, {5.3, -2.1}, scale, stride);
  ASSERT_EQ(table.num_angles(), 5);  // Round(2 * 0.1 / 0.05) + 1
  ASSERT_EQ(table.num_beams(), 4);   // the divisor counts every beam
  for (int k = 0; k < 5; ++k) {
    const double alpha = (0.3 - 0.1) + k * 0.05;
    EXPECT_DOUBLE_EQ(table.angle(k), alpha);
    const auto offsets = table.offsets(k);
    EXPECT_EQ(offsets[1], kInvalidLookup);
    EXPECT_EQ(offsets[2], kInvalidLookup);
    for (const int i : {0, 3}) {
      // Beam i rotated to the candidate heading alpha: direction alpha + min_angle + i res.
      const double r = (*ranges)[static_cast<std::size_t>(i)];
      const double a = alpha - 0.6 + 0.4 * i;
      const int dx = KartoRoundToInt(r * std::cos(a) * scale);
      const int dy = KartoRoundToInt(r * std::sin(a) * scale);
      EXPECT_EQ(offsets[static_cast<std::size_t>(i)], dx + dy * stride) << "k " << k << " beam " << i;
    }
  }
}

TEST(ScanLookupTable, PartitionSeparatesEntriesThatMayLeaveTheGrid) {
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, std::nan(""), 2.0, 50.0});
  const LaserScan scan(FourBeams(), ranges, Pose2{0.0, 0.0, 0.0}, 0.0);
  ScanLookupTable table;
  table.Compute(scan, 0.0, 0.0, 0.05, {0, 0}, 20.0, 100);
  ASSERT_EQ(table.num_angles(), 1);
  const auto all = table.offsets(0);
  // Candidates in [5000, 5100] of a 10000-cell grid: 1 m and 2 m points (|offset| <= 4040)
  // stay inside; the 50 m point (offset ~ 1000 * cos, sin of the beam) may not.
  table.Partition(5000, 5100, 10000);
  const auto safe = table.safe_offsets(0);
  const auto checked = table.checked_offsets(0);
  ASSERT_EQ(safe.size(), 2u);
  ASSERT_EQ(checked.size(), 1u);
  EXPECT_EQ(safe[0], all[0]);
  EXPECT_EQ(safe[1], all[2]);
  EXPECT_EQ(checked[0], all[3]);
}

}  // namespace
}  // namespace slamtune::slam
