#include "slamtune/optim/optimization_history.h"

#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/optim/testing/objective_sets.h"

namespace slamtune::optim {
namespace {

using testing::kPaper;

TEST(Hypervolume, IsTheDominatedVolumeUpToTheReference) {
  EXPECT_DOUBLE_EQ(Hypervolume({}, 1.1), 0.0);
  EXPECT_DOUBLE_EQ(Hypervolume({{0.4}, {0.7}}, 1.0), 0.6);
  EXPECT_NEAR(Hypervolume({{0.5, 0.5}}, 1.0), 0.25, 1e-12);
  // Two boxes overlapping in a corner: 0.5 * 0.25 + 0.25 * 0.5 - 0.25 * 0.25.
  EXPECT_NEAR(Hypervolume({{0.5, 0.75}, {0.75, 0.5}}, 1.0), 0.1875, 1e-12);
  // 3-D: (1, 0, 0) and (0, 1, 1) up to 1.1: 0.121 + 0.011 - 0.001.
  EXPECT_NEAR(Hypervolume({{1, 0, 0}, {0, 1, 1}}, 1.1), 0.131, 1e-12);
  // A dominated point adds nothing; a point beyond the reference adds nothing.
  EXPECT_NEAR(Hypervolume({{0.5, 0.5, 0.5}, {0.6, 0.6, 0.6}, {2.0, 0.0, 0.0}}, 1.0), 0.125, 1e-12);
}

TEST(SummarizeGenerations, BestValuesAndNormalisedHypervolumePerGeneration) {
  const double nan = std::nan("");
  const std::vector<std::vector<std::vector<double>>> populations = {
      {{0.10, 0.0, 10.0}, {0.0, 10.0, 0.0}},        // normalised: (1, 0, 1) and (0, 1, 0)
      {{0.05, 5.0, 5.0}, {1.0, 1e9, 1e9}},          // (0.5, 0.5, 0.5) and a failed run
      {{1.0, 1e9, 1e9}},                            // only failed runs
      {{0.05, 5.0, 5.0}, {0.06, 6.0, 6.0}, {nan}},  // a dominated run and a malformed vector
  };
  const OptimizationHistory h = SummarizeGenerations(populations, kPaper);
  ASSERT_EQ(h.generations.size(), 4u);
  EXPECT_EQ(h.lower, (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_EQ(h.upper, (std::vector<double>{0.10, 10.0, 10.0}));

  const GenerationSummary& g0 = h.generations[0];
  EXPECT_EQ(g0.generation, 0);
  EXPECT_EQ(g0.best, (std::vector<double>{0.0, 0.0, 0.0}));
  EXPECT_NEAR(g0.hypervolume, 0.131, 1e-12);
  EXPECT_EQ(g0.front_size, 2);
  EXPECT_EQ(g0.failed, 0);

  const GenerationSummary& g1 = h.generations[1];
  EXPECT_NEAR(g1.hypervolume, 0.6 * 0.6 * 0.6, 1e-12);
  EXPECT_EQ(g1.front_size, 1);
  EXPECT_EQ(g1.failed, 1);
  EXPECT_DOUBLE_EQ(g1.best[1], 5.0);

  const GenerationSummary& g2 = h.generations[2];
  EXPECT_EQ(g2.hypervolume, 0.0);
  EXPECT_EQ(g2.front_size, 0);
  EXPECT_EQ(g2.failed, 1);
  EXPECT_TRUE(std::isnan(g2.best[0]));

  const GenerationSummary& g3 = h.generations[3];
  EXPECT_NEAR(g3.hypervolume, 0.216, 1e-12);
  EXPECT_EQ(g3.front_size, 1);
  EXPECT_EQ(g3.failed, 1);
}

TEST(SummarizeGenerations, AnObjectiveWithOneValueNormalisesToZeroAndNoSuccessLeavesNoRange) {
  const OptimizationHistory one = SummarizeGenerations({{{0.1, 3.0, 4.0}}, {{0.1, 3.0, 4.0}}}, kPaper);
  EXPECT_NEAR(one.generations[1].hypervolume, 1.1 * 1.1 * 1.1, 1e-12);
  const OptimizationHistory none = SummarizeGenerations({{{1.0, 1e9, 1e9}}}, kPaper);
  ASSERT_EQ(none.generations.size(), 1u);
  EXPECT_EQ(none.generations[0].hypervolume, 0.0);
  EXPECT_TRUE(std::isnan(none.lower[0]));
  EXPECT_TRUE(SummarizeGenerations({}, kPaper).generations.empty());
}

}  // namespace
}  // namespace slamtune::optim
