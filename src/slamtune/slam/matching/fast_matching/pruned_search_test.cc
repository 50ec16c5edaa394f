#include "slamtune/slam/matching/fast_matching/pruned_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

// The loop matcher's coarse pass, set up by hand: grid of 10 scans seen from the query's
// position, 81 x 81 candidates two cells apart around the ROI centre, 21 headings.
struct LoopPass {
  CorrelationGrid grid{8.0, 0.05, 0.03, 12.0};
  ScanLookupTable table;
  CandidateCells cells;
  std::vector<double> response;  // sum -> response, as the matcher's table

  explicit LoopPass(const Pose2& query_pose) {
    std::vector<LaserScan> base;
    for (int i = 0; i < 10; ++i) base.push_back(testing::AsymmetricRoomScan({2.0 + 0.5 * i, 1.5 + 0.3 * i, 0.4 * i}));
    std::vector<const LaserScan*> ptrs;
    for (const LaserScan& s : base) ptrs.push_back(&s);
    const LaserScan query = testing::AsymmetricRoomScan(query_pose);
    grid.SetRoiOrigin({query_pose.x - 320 * 0.05, query_pose.y - 320 * 0.05});
    grid.AddScans(ptrs, {query_pose.x, query_pose.y});
    table.Compute(query, query_pose.theta, 0.349066, 0.0349066, grid.roi_origin(), grid.scale(),
                  grid.geometry().stride);
    cells.nx = cells.ny = 81;
    for (int y = 0; y < 81; ++y) {
      for (int x = 0; x < 81; ++x) cells.index.push_back(grid.GridIndex({240 + 2 * x, 240 + 2 * y}));
    }
    table.Partition(cells.index.front(), cells.index.back(), grid.data_size());
    for (int s = 0; s <= 100 * table.num_beams(); ++s) response.push_back(s / (100.0 * table.num_beams()));
  }
};

TEST(PrunedSearch, SkipsOnlyCandidatesFarBelowTheBest) {
  const LoopPass pass({4.6, 3.1, 0.9});
  std::vector<std::int32_t> full;
  SumAllCandidates(pass.grid.data(), pass.grid.data_size(), pass.table, pass.cells, 1, &full);
  const int k_count = pass.table.num_angles();
  const std::int32_t best = *std::max_element(full.begin(), full.end());

  auto prunable = [&](std::int32_t bound, std::int32_t best_sum) {
    return pass.response[static_cast<std::size_t>(bound)] < pass.response[static_cast<std::size_t>(best_sum)] - 0.1;
  };
  PrunedSearchScratch scratch;
  std::vector<std::int32_t> sums, max_sum_at;
  const PrunedSearchStats stats =
      SumCandidatesPruned(pass.grid.data(), pass.grid.data_size(), pass.grid.geometry().stride, pass.table, pass.cells,
                          prunable, &scratch, &sums, &max_sum_at);
  EXPECT_EQ(stats.blocks, 21 * 6);
  EXPECT_LT(stats.blocks_evaluated, stats.blocks / 2) << "the bound should prune most blocks";
  EXPECT_EQ(*std::max_element(max_sum_at.begin(), max_sum_at.end()), best);
  int skipped = 0;
  for (std::size_t c = 0; c < pass.cells.index.size(); ++c) {
    const auto first = full.begin() + static_cast<std::ptrdiff_t>(c * k_count);
    const std::int32_t true_max = *std::max_element(first, first + k_count);
    if (max_sum_at[c] < 0) {
      ++skipped;
      // Skipped: provably outside the covariance window best - 0.1.
      EXPECT_LT(pass.response[static_cast<std::size_t>(true_max)], pass.response[static_cast<std::size_t>(best)] - 0.1);
    } else {
      EXPECT_EQ(max_sum_at[c], true_max);
      for (int k = 0; k < k_count; ++k) ASSERT_EQ(sums[c * k_count + k], full[c * k_count + k]);
    }
  }
  EXPECT_GT(skipped, 0);
}

TEST(PrunedSearch, NothingPrunableGivesTheExhaustiveSums) {
  const LoopPass pass({7.0, 2.0, -2.0});
  std::vector<std::int32_t> full;
  SumAllCandidates(pass.grid.data(), pass.grid.data_size(), pass.table, pass.cells, 1, &full);
  PrunedSearchScratch scratch;
  std::vector<std::int32_t> sums, max_sum_at;
  const PrunedSearchStats stats = SumCandidatesPruned(
      pass.grid.data(), pass.grid.data_size(), pass.grid.geometry().stride, pass.table, pass.cells,
      [](std::int32_t, std::int32_t) { return false; }, &scratch, &sums, &max_sum_at);
  EXPECT_EQ(stats.blocks_evaluated, stats.blocks);
  EXPECT_EQ(sums, full);
}

TEST(PrunedSearch, RecognisesTheCoarseLattice) {
  const LoopPass pass({4.6, 3.1, 0.9});
  EXPECT_TRUE(IsStepTwoLattice(pass.cells, pass.grid.geometry().stride));
  CandidateCells shifted = pass.cells;
  shifted.index[5] += 1;
  EXPECT_FALSE(IsStepTwoLattice(shifted, pass.grid.geometry().stride));
  EXPECT_FALSE(IsStepTwoLattice(CandidateCells{}, 648));
}

}  // namespace
}  // namespace slamtune::slam
