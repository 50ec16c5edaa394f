#include "slamtune/slam/matching/correlation_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "slamtune/common/karto_math.h"
#include "slamtune/slam/matching/back_face_filter.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

struct SizeCase {
  const char* name;
  double dimension, resolution, sigma, range_threshold;
  int n, margin, roi, half, stored, stride;
};

// The worked sizes of §4.1.
TEST(CorrelationGridGeometry, MatchesSpecTable) {
  const SizeCase cases[] = {
      {"sequential slam_karto", 0.3, 0.01, 0.03, 12, 31, 1200, 2431, 6, 2445, 2448},
      {"loop", 8.0, 0.05, 0.03, 12, 161, 240, 641, 1, 645, 648},
      {"sequential toolbox", 0.5, 0.01, 0.1, 20, 51, 2000, 4051, 20, 4093, 4096},
  };
  for (const SizeCase& c : cases) {
    SCOPED_TRACE(c.name);
    const auto g = CorrelationGridGeometry::Compute(c.dimension, c.resolution, c.sigma, c.range_threshold);
    EXPECT_EQ(g.search_side, c.n);
    EXPECT_EQ(g.margin, c.margin);
    EXPECT_EQ(g.roi_side, c.roi);
    EXPECT_EQ(g.kernel_half, c.half);
    EXPECT_EQ(g.border, c.half + 1);
    EXPECT_EQ(g.stored_side, c.stored);
    EXPECT_EQ(g.stride, c.stride);
    EXPECT_EQ(g.stride % 8, 0);
  }
}

TEST(SmearKernel, SequentialProfileAlongAnAxis) {
  const std::vector<std::uint8_t> k = MakeSmearKernel(0.03, 0.01);
  ASSERT_EQ(k.size(), 13u * 13u);
  const int expected[] = {100, 95, 80, 61, 41, 25, 14};
  for (int i = 0; i <= 6; ++i) {
    EXPECT_EQ(k[(6 + i) + 13 * 6], expected[i]) << "x offset " << i;
    EXPECT_EQ(k[(6 - i) + 13 * 6], expected[i]) << "x offset " << -i;
    EXPECT_EQ(k[6 + 13 * (6 + i)], expected[i]) << "y offset " << i;
  }
}

TEST(SmearKernel, LoopKernelIsThreeByThree) {
  const std::vector<std::uint8_t> k = MakeSmearKernel(0.03, 0.05);
  const std::vector<std::uint8_t> expected = {6, 25, 6, 25, 100, 25, 6, 25, 6};
  EXPECT_EQ(k, expected);
}

TEST(SmearKernel, ToolboxKernelRoundsAxialNeighboursTo100) {
  // sigma 0.1, rho 0.01: 100 exp(-0.005) = 99.5012 rounds to 100 (§4.3 [QUIRK]).
  const std::vector<std::uint8_t> k = MakeSmearKernel(0.1, 0.01);
  EXPECT_EQ(k[21 + 41 * 20], 100);
  EXPECT_EQ(k[20 + 41 * 21], 100);
  EXPECT_EQ(k[21 + 41 * 21], 99);
}

CorrelationGrid LoopGrid() {
  CorrelationGrid grid(8.0, 0.05, 0.03, 12.0);
  grid.SetRoiOrigin({-16.0, -16.0});
  return grid;
}

TEST(CorrelationGrid, WorldToGridMultipliesAndRoundsHalfAwayFromZero) {
  CorrelationGrid grid = LoopGrid();
  EXPECT_EQ(grid.WorldToGrid({-16.0, -15.98}), Eigen::Vector2i(0, 0));
  EXPECT_EQ(grid.WorldToGrid({-16.03, -15.93}), Eigen::Vector2i(-1, 1));
  // -0.025 * 20 is exactly -0.5: half away from zero gives -1 (floor(v + 0.5) would give 0).
  grid.SetRoiOrigin({0.0, 0.0});
  EXPECT_EQ(grid.WorldToGrid({-0.025, 0.025}), Eigen::Vector2i(-1, 1));
  grid.SetRoiOrigin({-16.0, -16.0});
  // Stored index adds the border (h + 1 = 2) and uses the padded stride.
  EXPECT_EQ(grid.GridIndex({0, 0}), 2 + 2 * 648);
  EXPECT_EQ(grid.GridIndex({3, 5}), 5 + 7 * 648);
}

TEST(CorrelationGrid, SmearIsAMaxMerge) {
  CorrelationGrid grid(0.3, 0.01, 0.03, 12.0);
  grid.SetRoiOrigin({0.0, 0.0});
  ASSERT_TRUE(grid.AddPoint({1.00, 1.00}));  // cell (100, 100)
  ASSERT_TRUE(grid.AddPoint({1.03, 1.00}));  // cell (103, 100)
  const std::vector<std::uint8_t> k = MakeSmearKernel(0.03, 0.01);
  auto kernel = [&](int i, int j) -> int {
    if (std::abs(i) > 6 || std::abs(j) > 6) return 0;
    return k[(i + 6) + 13 * (j + 6)];
  };
  for (int y = 90; y <= 110; ++y) {
    for (int x = 90; x <= 115; ++x) {
      const int expected = std::max(kernel(x - 100, y - 100), kernel(x - 103, y - 100));
      EXPECT_EQ(grid.ValueAt(x, y), expected) << x << "," << y;
    }
  }
  EXPECT_EQ(grid.ValueAt(101, 100), 95);
  EXPECT_EQ(grid.ValueAt(102, 100), 95);
}

TEST(CorrelationGrid, CellAlreadyAt100IsNotSmearedAgain) {
  // Toolbox kernel: the axial neighbour of a point rounds to 100, so a second point there is
  // "already set" and adds no smear; the far side of its kernel stays as the first left it.
  CorrelationGrid grid(0.5, 0.01, 0.1, 20.0);
  grid.SetRoiOrigin({0.0, 0.0});
  ASSERT_TRUE(grid.AddPoint({2.00, 2.00}));   // cell (200, 200)
  EXPECT_FALSE(grid.AddPoint({2.01, 2.00}));  // cell (201, 200) holds 100 from the smear
  EXPECT_EQ(grid.ValueAt(221, 200), 0);       // would be 14 had (201, 200) been smeared
  EXPECT_EQ(grid.ValueAt(220, 200), 14);

  // The other insertion order smears both: order matters (§4.3 [QUIRK]).
  CorrelationGrid other(0.5, 0.01, 0.1, 20.0);
  other.SetRoiOrigin({0.0, 0.0});
  ASSERT_TRUE(other.AddPoint({2.01, 2.00}));
  EXPECT_FALSE(other.AddPoint({2.00, 2.00}));
  EXPECT_EQ(other.ValueAt(221, 200), 14);
  EXPECT_EQ(other.ValueAt(180, 200), 0);
}

TEST(CorrelationGrid, SkipsNonFiniteAndOutsideRoiPoints) {
  CorrelationGrid grid = LoopGrid();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(grid.AddPoint({std::nan(""), 0.0}));
  EXPECT_FALSE(grid.AddPoint({inf, inf}));
  EXPECT_FALSE(grid.AddPoint({-16.05, 0.0}));              // ROI cell -1
  EXPECT_FALSE(grid.AddPoint({-16.0 + 641 * 0.05, 0.0}));  // ROI cell G
  EXPECT_FALSE(grid.AddPoint({1e12, 0.0}));                // would overflow a 32-bit cast
  EXPECT_TRUE(grid.AddPoint({-16.0 + 640 * 0.05, 0.0}));   // last ROI cell; smear spills into the border
  EXPECT_EQ(grid.ValueAt(641, 320), 25);
}

// AddPoint decides and places by truncation; the reference is §1.2's rounding followed by
// the ROI test, on values at and around every rounding and ROI boundary. A resolution of
// 0.25 m keeps (w - origin) * scale exact at the half-cell boundaries.
TEST(CorrelationGrid, InsertionCellIsKartoRoundOfTheWorldPoint) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto make_grid = [] {
    CorrelationGrid grid(8.0, 0.25, 0.25, 12.0);
    grid.SetRoiOrigin({-16.0, -16.0});
    return grid;
  };
  const int side = make_grid().geometry().roi_side;
  std::vector<double> cells = {nan, inf, -inf, 1e12, -1e12, 0.0, -0.0};
  for (const double c : {-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 7.5, side - 1.0, side - 0.5, static_cast<double>(side)}) {
    cells.push_back(c);
    cells.push_back(std::nextafter(c, -inf));
    cells.push_back(std::nextafter(c, inf));
    cells.push_back(c + 1e-9);
    cells.push_back(c - 1e-9);
  }
  int accepted = 0, rejected = 0;
  for (const double cx : cells) {
    for (const double cy : {3.0, cx}) {
      CorrelationGrid grid = make_grid();
      const Eigen::Vector2d world(-16.0 + cx / grid.scale(), -16.0 + cy / grid.scale());
      const double rx = KartoRound((world.x() + 16.0) * grid.scale());
      const double ry = KartoRound((world.y() + 16.0) * grid.scale());
      const bool inside = rx >= 0.0 && rx < side && ry >= 0.0 && ry < side;
      SCOPED_TRACE(::testing::Message() << "cell " << cx << ", " << cy);
      ASSERT_EQ(grid.AddPoint(world), inside);
      if (!inside) {
        ++rejected;
        continue;
      }
      ++accepted;
      EXPECT_EQ(grid.ValueAt(static_cast<int>(rx), static_cast<int>(ry)), kCorrelationOccupied);
    }
  }
  EXPECT_GT(accepted, 20);
  EXPECT_GT(rejected, 20);
}

// The grid is reused and only the written region cleared: building B after A must give the
// bytes of a fresh grid built from B alone.
TEST(CorrelationGrid, RebuildAfterClearEqualsFreshGrid) {
  const LaserScan a = testing::AsymmetricRoomScan({2.0, 2.0, 0.3});
  const LaserScan b = testing::AsymmetricRoomScan({8.5, 4.5, 2.5});
  const LaserScan* list_a[] = {&a};
  const LaserScan* list_b[] = {&b};

  CorrelationGrid reused = LoopGrid();
  reused.SetRoiOrigin({2.0 - 16.0, 2.0 - 16.0});
  reused.AddScans(list_a, {2.0, 2.0});
  reused.SetRoiOrigin({8.5 - 16.0, 4.5 - 16.0});
  reused.AddScans(list_b, {8.5, 4.5});

  CorrelationGrid fresh = LoopGrid();
  fresh.SetRoiOrigin({8.5 - 16.0, 4.5 - 16.0});
  fresh.AddScans(list_b, {8.5, 4.5});
  ASSERT_EQ(reused.data_size(), fresh.data_size());
  EXPECT_EQ(std::vector<std::uint8_t>(reused.data(), reused.data() + reused.data_size() + CorrelationGrid::kPadding),
            std::vector<std::uint8_t>(fresh.data(), fresh.data() + fresh.data_size() + CorrelationGrid::kPadding));
  int occupied = 0;
  for (std::int32_t i = 0; i < fresh.data_size(); ++i) occupied += fresh.data()[i] == kCorrelationOccupied;
  EXPECT_GT(occupied, 100);
}

// AddScans inserts the points row by row when no kernel value off the centre is 100, and in
// beam order otherwise (§4.3 [QUIRK]): either way the bytes must be those of inserting every
// back-face-filtered point in scan and beam order, overlapping scans and repeated cells included.
TEST(CorrelationGrid, AddScansEqualsInsertingEveryPointInBeamOrder) {
  std::vector<LaserScan> scans;
  for (int i = 0; i < 6; ++i) {
    scans.push_back(testing::AsymmetricRoomScan({2.0 + 0.37 * i, 2.0 + 0.11 * i, 0.2 * i}));
  }
  scans.push_back(scans.front());  // every cell of a scan repeated
  std::vector<const LaserScan*> bases;
  for (const LaserScan& scan : scans) bases.push_back(&scan);
  const Eigen::Vector2d viewpoint(3.0, 2.5);
  struct KernelCase {
    const char* name;
    double dimension, resolution, sigma;
  };
  const KernelCase cases[] = {{"sequential slam_karto", 0.3, 0.01, 0.03},
                              {"loop", 8.0, 0.05, 0.03},
                              {"sequential toolbox: neighbours round to 100", 0.5, 0.01, 0.1}};
  for (const KernelCase& c : cases) {
    SCOPED_TRACE(c.name);
    CorrelationGrid by_scans(c.dimension, c.resolution, c.sigma, 12.0);
    CorrelationGrid by_points(c.dimension, c.resolution, c.sigma, 12.0);
    const double half = 0.5 * (by_scans.geometry().roi_side - 1) * c.resolution;
    by_scans.SetRoiOrigin(viewpoint - Eigen::Vector2d(half, half));
    by_points.SetRoiOrigin(by_scans.roi_origin());
    by_scans.AddScans(bases, viewpoint);
    int inserted = 0;
    for (const LaserScan* scan : bases) {
      ForEachValidPoint(scan->unfiltered_points(), viewpoint,
                        [&](const Eigen::Vector2d& p) { inserted += by_points.AddPoint(p); });
    }
    EXPECT_GT(inserted, 300);
    const std::size_t bytes = static_cast<std::size_t>(by_scans.data_size()) + CorrelationGrid::kPadding;
    EXPECT_TRUE(std::equal(by_scans.data(), by_scans.data() + bytes, by_points.data()));
  }
}

// Clear zeroes only what was written (kernel squares or their box): points on every ROI edge
// and corner (whose kernels reach the border and the last stored row and column) and random
// points inside, over rounds that take either path, must leave every byte zero, padding
// included.
TEST(CorrelationGrid, ClearZeroesEverythingWrittenUpToTheGridEdges) {
  // slam_toolbox's sequential smear (h = 20, a padded row spills past the last column) on a
  // small ROI: G = 31 + 2 * 100 = 231 cells.
  CorrelationGrid grid(0.3, 0.01, 0.1, 1.0);
  const int roi = grid.geometry().roi_side;
  grid.SetRoiOrigin({0.0, 0.0});
  const std::size_t bytes = static_cast<std::size_t>(grid.data_size()) + CorrelationGrid::kPadding;
  auto all_zero = [&] {
    for (std::size_t i = 0; i < bytes; ++i) {
      if (grid.data()[i] != 0) return false;
    }
    return true;
  };
  std::uint32_t state = 12345;
  auto uniform = [&state] {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) / static_cast<double>(1u << 24);
  };
  for (int round = 0; round < 4; ++round) {
    std::vector<Eigen::Vector2d> points;
    const double last = 0.01 * (roi - 1);
    for (const double x : {0.0, 0.5 * last, last}) {
      for (const double y : {0.0, 0.5 * last, last}) points.emplace_back(x, y);
    }
    for (int i = 0; i < 40 * round; ++i) points.emplace_back(uniform() * last, uniform() * last);
    int inserted = 0;
    for (const Eigen::Vector2d& p : points) inserted += grid.AddPoint(p);
    EXPECT_GE(inserted, 9);
    EXPECT_EQ(grid.ValueAt(0, 0), kCorrelationOccupied);
    EXPECT_EQ(grid.ValueAt(roi - 1, roi - 1), kCorrelationOccupied);
    EXPECT_GT(grid.ValueAt(-grid.geometry().border + 1, roi + grid.geometry().border - 2), 0);
    grid.Clear();
    EXPECT_TRUE(all_zero()) << "round " << round;
  }
}

}  // namespace
}  // namespace slamtune::slam
