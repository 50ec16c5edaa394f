#include "slamtune/slam/matching/scan_lookup_table.h"

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

// A table reused across calls keeps its previous tables only when every input repeats: after
// any change (scan readings, its pose, a reading turning non-finite, headings, grid origin,
// scale, stride) it must equal a table computed fresh from the new inputs.
TEST(ScanLookupTable, ReusedTableEqualsFreshTableAfterAnyInputChange) {
  const double nan = std::nan("");
  auto base = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, 2.0, 3.0, 4.0});
  auto other = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, 2.0, 3.5, 4.0});
  auto with_nan = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, nan, 3.0, 4.0});
  struct Inputs {
    const char* name;
    std::shared_ptr<const std::vector<double>> ranges;
    Pose2 pose;
    double center, offset, step;
    Eigen::Vector2d origin;
    double scale;
    std::int32_t stride;
  };
  const Inputs reference{"reference", base, {1.0, 2.0, 0.3}, 0.3, 0.1, 0.05, {5.3, -2.1}, 20.0, 648};
  std::vector<Inputs> changes(8, reference);
  changes[0].name = "same inputs";
  changes[1].name = "other readings";
  changes[1].ranges = other;
  changes[2].name = "a reading becomes NaN";
  changes[2].ranges = with_nan;
  changes[3].name = "scan pose";
  changes[3].pose.y += 1e-9;
  changes[4].name = "heading centre";
  changes[4].center = std::nextafter(0.3, 1.0);
  changes[5].name = "grid origin";
  changes[5].origin.x() += 0.025;
  changes[6].name = "scale and headings";
  changes[6].scale = 40.0;
  changes[6].offset = 0.2;
  changes[7].name = "stride";
  changes[7].stride = 656;
  auto compute = [](ScanLookupTable* table, const Inputs& in) {
    const LaserScan scan(FourBeams(), in.ranges, in.pose, 0.0);
    table->Compute(scan, in.center, in.offset, in.step, in.origin, in.scale, in.stride);
  };
  auto contents = [](const ScanLookupTable& t) {
    std::vector<double> v;
    for (int k = 0; k < t.num_angles(); ++k) {
      v.push_back(t.angle(k));
      for (const std::int32_t o : t.offsets(k)) v.push_back(o);
    }
    return v;
  };
  int differing = 0;
  for (const Inputs& change : changes) {
    SCOPED_TRACE(change.name);
    ScanLookupTable reused, fresh, first;
    compute(&first, reference);
    compute(&reused, reference);
    compute(&reused, change);
    compute(&fresh, change);
    EXPECT_EQ(contents(reused), contents(fresh));
    differing += contents(fresh) != contents(first);
  }
  // Readings, NaN, headings, scale and stride alter the tables; the pose and the origin enter
  // only through rounding (the points are taken back into the sensor frame) and do not here.
  EXPECT_EQ(differing, 5);
}

}  // namespace
}  // namespace slamtune::slam
