#include "slamtune/slam/occupancy_grid.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;
using Cells = std::vector<Eigen::Vector2i>;

Cells Trace(int x0, int y0, int x1, int y1) {
  Cells cells;
  TraceGridLine(x0, y0, x1, y1, [&](int x, int y) { cells.emplace_back(x, y); });
  return cells;
}

TEST(TraceGridLine, HandComputedCells) {
  // dx 5, dy 2: y offset floor((4k + 5) / 10) = 0 0 1 1 2 2.
  EXPECT_EQ(Trace(0, 0, 5, 2), (Cells{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}}));
  // Same segment from the other end: the ends are reordered, the same cells come out.
  EXPECT_EQ(Trace(5, 2, 0, 0), (Cells{{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}}));
  // Steep: axes swapped, (0,0)-(3,1) traced, swapped back.
  EXPECT_EQ(Trace(0, 0, 1, 3), (Cells{{0, 0}, {0, 1}, {1, 2}, {1, 3}}));
  // Decreasing y: step -1, offsets floor((6k + 4) / 8) = 0 1 2 2 3.
  EXPECT_EQ(Trace(0, 3, 4, 0), (Cells{{0, 3}, {1, 2}, {2, 1}, {3, 1}, {4, 0}}));
  // Diagonal and single cell.
  EXPECT_EQ(Trace(2, 2, 4, 4), (Cells{{2, 2}, {3, 3}, {4, 4}}));
  EXPECT_EQ(Trace(7, -3, 7, -3), (Cells{{7, -3}}));
}

// The closed form of §8.1 on random segments.
TEST(TraceGridLine, MatchesClosedFormOnRandomSegments) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coord(-60, 60);
  for (int trial = 0; trial < 20000; ++trial) {
    int x0 = coord(rng), y0 = coord(rng), x1 = coord(rng), y1 = coord(rng);
    const Cells cells = Trace(x0, y0, x1, y1);
    const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
    if (steep) {
      std::swap(x0, y0);
      std::swap(x1, y1);
    }
    if (x0 > x1) {
      std::swap(x0, x1);
      std::swap(y0, y1);
    }
    const int dx = x1 - x0, dy = std::abs(y1 - y0), step = y0 < y1 ? 1 : -1;
    ASSERT_EQ(cells.size(), static_cast<std::size_t>(dx + 1));
    for (int k = 0; k <= dx; ++k) {
      Eigen::Vector2i expected(x0 + k, dx == 0 ? y0 : y0 + step * ((2 * k * dy + dx) / (2 * dx)));
      if (steep) expected = {expected.y(), expected.x()};
      ASSERT_EQ(cells[static_cast<std::size_t>(k)], expected) << "trial " << trial << " k " << k;
    }
  }
}

// A laser whose beams are listed explicitly (angle, reading) around a sensor at the origin.
LaserScan FanScan(const std::vector<double>& readings, double min_angle, double step, double min_range = 0.1,
                  double max_range = 20.0, double range_threshold = 12.0, Pose2 pose = {0, 0, 0}) {
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = min_angle;
  g->angular_resolution = step;
  g->num_readings = static_cast<int>(readings.size());
  g->min_range = min_range;
  g->max_range = max_range;
  g->range_threshold = range_threshold;
  return LaserScan(g, std::make_shared<const std::vector<double>>(readings), pose, 0.0);
}

// Beams at 0, 45 and 90 degrees: the box is (0,0)-(1,1), 20 x 20 cells at 5 cm. The 0 and 90
// degree end points round to index 20 (the max-edge quirk) and fall outside; the 45 degree one,
// at (0.354, 0.354), lands in cell (7, 7).
LaserScan Fan() { return FanScan({1.0, 0.5, 1.0}, 0.0, kPi / 4); }

TEST(OccupancyGrid, ExtentIsTheUnionOfBoxesRoundedToCells) {
  const LaserScan scan = Fan();
  const LaserScan* scans[] = {&scan};
  const OccupancyGrid grid = OccupancyGrid::FromScans(scans, {});
  EXPECT_EQ(grid.width(), 20);
  EXPECT_EQ(grid.height(), 20);
  EXPECT_NEAR(grid.origin().x(), 0.0, 1e-12);
  EXPECT_NEAR(grid.origin().y(), 0.0, 1e-12);
  EXPECT_EQ(grid.summary().hits, 1);
  EXPECT_EQ(grid.summary().hits_outside, 2);
  // 1.024 / 0.05 = 20.48 -> 20 cells; 1.026 / 0.05 = 20.52 -> 21 cells (Round, §8.1).
  const LaserScan a = FanScan({1.024, 1.026}, 0.0, kPi / 2);
  const LaserScan* list_a[] = {&a};
  const OccupancyGrid ga = OccupancyGrid::FromScans(list_a, {});
  EXPECT_EQ(ga.width(), 20);
  EXPECT_EQ(ga.height(), 21);
}

TEST(OccupancyGrid, HitCellGetsTwoPassesAndOneHitPerBeam) {
  const LaserScan scan = Fan();
  const LaserScan* one[] = {&scan};
  const OccupancyGrid grid = OccupancyGrid::FromScans(one, {});
  EXPECT_EQ(grid.pass_count(7, 7), 2u);
  EXPECT_EQ(grid.hit_count(7, 7), 1u);
  // Cells on the way: one pass, no hit. The sensor cell is passed by all three beams.
  EXPECT_EQ(grid.pass_count(3, 3), 1u);
  EXPECT_EQ(grid.hit_count(3, 3), 0u);
  EXPECT_EQ(grid.pass_count(0, 0), 3u);
  EXPECT_EQ(grid.pass_count(10, 0), 1u);
  // MinPassThrough is strict: pass 2 is not > 2, so the hit cell stays unknown; the sensor
  // cell (3 passes, no hit) is free.
  EXPECT_EQ(grid.state(7, 7), CellState::kUnknown);
  EXPECT_EQ(grid.state(3, 3), CellState::kUnknown);
  EXPECT_EQ(grid.state(0, 0), CellState::kFree);
}

TEST(OccupancyGrid, ThreeViewsMakeTheHitCellOccupiedWithAStrictThreshold) {
  const LaserScan scan = Fan();
  const LaserScan* three[] = {&scan, &scan, &scan};
  const OccupancyGrid grid = OccupancyGrid::FromScans(three, {});
  EXPECT_EQ(grid.pass_count(7, 7), 6u);
  EXPECT_EQ(grid.hit_count(7, 7), 3u);
  EXPECT_EQ(grid.state(7, 7), CellState::kOccupied);  // 3/6 > 0.1
  EXPECT_EQ(grid.state(3, 3), CellState::kFree);      // 3 passes, no hit
  OccupancyGridOptions strict;
  strict.occupancy_threshold = 0.5;  // 3/6 is not > 0.5
  EXPECT_EQ(OccupancyGrid::FromScans(three, strict).state(7, 7), CellState::kFree);
  strict.occupancy_threshold = 0.49;
  EXPECT_EQ(OccupancyGrid::FromScans(three, strict).state(7, 7), CellState::kOccupied);
  OccupancyGridOptions lenient;
  lenient.min_pass_through = 0;
  const LaserScan* one[] = {&scan};
  EXPECT_EQ(OccupancyGrid::FromScans(one, lenient).state(7, 7), CellState::kOccupied);
}

TEST(OccupancyGrid, CountsTheHitsTheMapDoesNotBack) {
  const LaserScan scan = Fan();
  const LaserScan* one[] = {&scan};
  const OccupancyGridSummary seen_once = OccupancyGrid::FromScans(one, {}).summary();
  EXPECT_EQ(seen_once.hits, 1);
  EXPECT_EQ(seen_once.hits_in_unknown_cells, 1);  // 2 passes: not known yet
  EXPECT_EQ(seen_once.hits_in_free_cells, 0);
  const LaserScan* three[] = {&scan, &scan, &scan};
  const OccupancyGridSummary wall = OccupancyGrid::FromScans(three, {}).summary();
  EXPECT_EQ(wall.hits, 3);
  EXPECT_EQ(wall.hits_in_unknown_cells, 0);
  EXPECT_EQ(wall.hits_in_free_cells, 0);
  OccupancyGridOptions strict;
  strict.occupancy_threshold = 0.5;  // 3 hits / 6 passes: the cell ends free, its hits overruled
  const OccupancyGridSummary overruled = OccupancyGrid::FromScans(three, strict).summary();
  EXPECT_EQ(overruled.hits_in_free_cells, 3);
  EXPECT_EQ(overruled.hits_in_unknown_cells, 0);
}

TEST(OccupancyGrid, SkipRulesAndTruncationAtTheRangeThreshold) {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  // min_range 0.1, max_range 20, threshold 12; beams 10 degrees apart.
  const std::vector<double> readings = {0.1, 0.05, 20.0, 25.0, nan, inf, 15.0, 12.0, 12.0 - 5e-7, 11.9, 3.0};
  const LaserScan scan = FanScan(readings, 0.0, DegToRad(8.0));
  const LaserScan* scans[] = {&scan};
  const OccupancyGrid grid = OccupancyGrid::FromScans(scans, {});
  const OccupancyGridSummary& s = grid.summary();
  // Skipped: <= min_range (0.1, 0.05), >= max_range (20, 25, inf), NaN.
  EXPECT_EQ(s.beams_skipped, 6);
  EXPECT_EQ(s.beams_traced, 5);
  // 15 and 12 are shortened to 12 m with no hit; 12 - 5e-7 is drawn in full but is within
  // 1e-6 of the threshold, so no hit either; 11.9 and 3.0 are hits.
  EXPECT_EQ(s.beams_shortened, 2);
  EXPECT_EQ(s.hits + s.hits_outside, 2);
  // The box holds only filtered points (<= 12 m), so the shortened 15 m beam at 48 degrees
  // leaves the grid; its cells inside were passed, none was hit.
  const Eigen::Vector2i from = grid.WorldToGrid({0.0, 0.0});
  const Eigen::Vector2i end = grid.WorldToGrid({12.0 * std::cos(DegToRad(48.0)), 12.0 * std::sin(DegToRad(48.0))});
  EXPECT_FALSE(grid.Contains(end.x(), end.y()));
  int inside = 0;
  TraceGridLine(from.x(), from.y(), end.x(), end.y(), [&](int x, int y) {
    if (!grid.Contains(x, y)) return;
    ++inside;
    EXPECT_GE(grid.pass_count(x, y), 1u);
    if (x > 2) {
      EXPECT_EQ(grid.hit_count(x, y), 0u);
    }
  });
  EXPECT_GT(inside, 100);
  // The 3 m beam at 80 degrees is a hit.
  const Eigen::Vector2i hit = grid.WorldToGrid({3.0 * std::cos(DegToRad(80.0)), 3.0 * std::sin(DegToRad(80.0))});
  EXPECT_EQ(grid.hit_count(hit.x(), hit.y()), 1u);
}

TEST(OccupancyGrid, MapImageFlipsRowsAndUsesMapSaverGreyLevels) {
  const LaserScan scan = Fan();
  const LaserScan* three[] = {&scan, &scan, &scan};
  const OccupancyGrid grid = OccupancyGrid::FromScans(three, {});
  const io::MapImage image = grid.ToMapImage();
  ASSERT_EQ(image.width, 20);
  ASSERT_EQ(image.height, 20);
  EXPECT_DOUBLE_EQ(image.resolution, 0.05);
  EXPECT_NEAR(image.origin.x, 0.0, 1e-12);
  EXPECT_EQ(image.origin.theta, 0.0);
  // Map row y is image row height - 1 - y.
  EXPECT_EQ(image.at(7, 19 - 7), io::kMapOccupied);
  EXPECT_EQ(image.at(3, 19 - 3), io::kMapFree);
  EXPECT_EQ(image.at(0, 19), io::kMapFree);
  EXPECT_EQ(image.at(15, 19 - 2), io::kMapUnknown);
  int occupied = 0, free = 0, unknown = 0;
  for (const std::uint8_t v : image.pixels) {
    occupied += v == io::kMapOccupied;
    free += v == io::kMapFree;
    unknown += v == io::kMapUnknown;
  }
  EXPECT_EQ(occupied + free + unknown, 400);
  EXPECT_EQ(occupied, grid.summary().occupied_cells);
  EXPECT_EQ(free, grid.summary().free_cells);
}

TEST(OccupancyGrid, RoomMapHasWallsAndFreeSpace) {
  const auto room = testing::AsymmetricRoom();
  const auto laser = testing::CarmenLikeLaser();
  std::vector<LaserScan> scans;
  for (int i = 0; i < 12; ++i) scans.push_back(testing::CastScan(room, laser, {1.0 + 0.4 * i, 1.5, 0.5 * i}));
  const OccupancyGrid grid = OccupancyGrid::FromScans(std::span<const LaserScan>(scans), {});
  EXPECT_GT(grid.summary().occupied_cells, 100);
  EXPECT_GT(grid.summary().free_cells, 3000);
  // A point on the bottom wall in front of the path is occupied, the path itself free.
  const Eigen::Vector2i wall = grid.WorldToGrid({3.0, 0.0});
  const Eigen::Vector2i path = grid.WorldToGrid({3.0, 1.5});
  EXPECT_EQ(grid.state(wall.x(), wall.y() < 0 ? 0 : wall.y()), CellState::kOccupied);
  EXPECT_EQ(grid.state(path.x(), path.y()), CellState::kFree);
  // The pointer overload gives the same map.
  std::vector<const LaserScan*> ptrs;
  for (const LaserScan& s : scans) ptrs.push_back(&s);
  EXPECT_EQ(OccupancyGrid::FromScans(ptrs, {}).ToMapImage().pixels, grid.ToMapImage().pixels);
}

// Counts live in 64 x 64-cell tiles allocated where beams reach: at 1 cm the room spans many
// tiles. Every cell's state, the image and the summary must agree as if the counts were one
// array, beams must count across tile edges, and tiles no beam reached must read as unknown.
TEST(OccupancyGrid, TiledCountsReadAsOneGrid) {
  const auto room = testing::AsymmetricRoom();
  const auto laser = testing::CarmenLikeLaser();
  std::vector<LaserScan> scans;
  for (int i = 0; i < 6; ++i) scans.push_back(testing::CastScan(room, laser, {1.0 + 0.6 * i, 1.5, 0.7 * i}));
  // A far-off scan of a lone pillar stretches the box, leaving tiles between no beam crosses.
  scans.push_back(FanScan({0.5, 0.5, 0.5}, 0.0, 0.05, 0.1, 20.0, 12.0, {30.0, 30.0, 0.0}));
  OccupancyGridOptions fine;
  fine.resolution = 0.01;
  const OccupancyGrid grid = OccupancyGrid::FromScans(std::span<const LaserScan>(scans), fine);
  const int tiles = ((grid.width() + 63) / 64) * ((grid.height() + 63) / 64);
  ASSERT_GT(grid.allocated_tiles(), 9);
  EXPECT_LT(grid.allocated_tiles(), tiles / 2);

  const io::MapImage image = grid.ToMapImage();
  OccupancyGridSummary counted;
  std::int64_t passes = 0;
  for (int y = 0; y < grid.height(); ++y) {
    for (int x = 0; x < grid.width(); ++x) {
      const CellState state = grid.state(x, y);
      const std::uint8_t pixel = image.at(x, grid.height() - 1 - y);
      counted.hits += grid.hit_count(x, y);
      passes += grid.pass_count(x, y);
      switch (state) {
        case CellState::kOccupied:
          ++counted.occupied_cells;
          ASSERT_EQ(pixel, io::kMapOccupied);
          break;
        case CellState::kFree:
          ++counted.free_cells;
          counted.hits_in_free_cells += grid.hit_count(x, y);
          ASSERT_EQ(pixel, io::kMapFree);
          break;
        case CellState::kUnknown:
          ++counted.unknown_cells;
          counted.hits_in_unknown_cells += grid.hit_count(x, y);
          ASSERT_EQ(pixel, io::kMapUnknown);
          break;
      }
    }
  }
  const OccupancyGridSummary& s = grid.summary();
  EXPECT_GT(s.occupied_cells, 100);
  EXPECT_EQ(counted.occupied_cells, s.occupied_cells);
  EXPECT_EQ(counted.free_cells, s.free_cells);
  EXPECT_EQ(counted.unknown_cells, s.unknown_cells);
  EXPECT_EQ(counted.hits, s.hits);
  EXPECT_EQ(counted.hits_in_free_cells, s.hits_in_free_cells);
  EXPECT_EQ(counted.hits_in_unknown_cells, s.hits_in_unknown_cells);
  EXPECT_GT(passes, s.beams_traced * 100);

  // One beam of the first scan, traced by hand: every cell on its way counted once more than
  // the cells beside the path in an otherwise empty grid.
  const LaserScan ray = FanScan({5.0}, 0.3, 0.1, 0.1, 20.0, 12.0, {0.0, 0.0, 0.0});
  const LaserScan corner = FanScan({0.2}, kPi, 0.1, 0.1, 20.0, 12.0, {0.0, 0.0, 0.0});
  const LaserScan* both[] = {&ray, &corner};
  const OccupancyGrid line = OccupancyGrid::FromScans(both, fine);
  const Eigen::Vector2i from = line.WorldToGrid({0.0, 0.0});
  const Eigen::Vector2i to = line.WorldToGrid({5.0 * std::cos(0.3), 5.0 * std::sin(0.3)});
  int cells = 0;
  TraceGridLine(from.x(), from.y(), to.x(), to.y(), [&](int x, int y) {
    if (!line.Contains(x, y)) return;
    ++cells;
    const bool at_sensor = x == from.x() && y == from.y();
    const bool at_end = x == to.x() && y == to.y();
    EXPECT_EQ(line.pass_count(x, y), at_sensor ? 2u : at_end ? 2u : 1u) << x << "," << y;
  });
  EXPECT_GT(cells, 400);  // crosses several 64-cell tiles
}

TEST(OccupancyGrid, NoScansGiveAnEmptyMap) {
  const OccupancyGrid grid = OccupancyGrid::FromScans(std::span<const LaserScan* const>(), {});
  EXPECT_EQ(grid.width(), 0);
  EXPECT_EQ(grid.height(), 0);
  EXPECT_TRUE(grid.ToMapImage().pixels.empty());
}

TEST(OccupancyGridOptions, ValidateNamesFieldValueAndRule) {
  OccupancyGridOptions o;
  EXPECT_NO_THROW(o.Validate());
  o.resolution = 0.0;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("resolution = 0")));
  o = {};
  o.min_pass_through = -1;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("min_pass_through = -1: must be >= 0")));
  o = {};
  o.occupancy_threshold = 1.5;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("occupancy_threshold = 1.5")));
  // A diverged trajectory: the map would be far too large.
  const LaserScan a = FanScan({1.0}, 0.0, 0.1, 0.1, 20.0, 12.0, {0, 0, 0});
  const LaserScan b = FanScan({1.0}, 0.0, 0.1, 0.1, 20.0, 12.0, {5e4, 5e4, 0});
  const LaserScan* far[] = {&a, &b};
  try {
    OccupancyGrid::FromScans(far, {});
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("exceeds max_cells"));
  }
}

}  // namespace
}  // namespace slamtune::slam
