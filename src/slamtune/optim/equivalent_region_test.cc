#include "slamtune/optim/equivalent_region.h"

#include <gtest/gtest.h>

#include "slamtune/optim/testing/objective_sets.h"

namespace slamtune::optim {
namespace {

using testing::kPaper;

SearchSpace Space() {
  SearchSpace space;
  space.dimensions = {{"loop_search_maximum_distance", 2.0, 6.0, false},
                      {"loop_match_minimum_chain_size", 6.0, 20.0, true}};
  return space;
}

// eta, n_c, n_e as given; `loops` loop closures.
EvaluationRecord MakeRun(double r, int g, double eta, double nc, double ne, int loops) {
  EvaluationRecord e = testing::PaperRecord(std::to_string(r) + "/" + std::to_string(g), eta, nc, ne, loops);
  e.params = {{"loop_search_maximum_distance", r}, {"loop_match_minimum_chain_size", g}};
  return e;
}

TEST(FindEquivalentRegion, SameLoopsAndEveryObjectiveWithinTheToleranceOfItsRange) {
  // Ranges over the successful runs: eta [0.10, 0.20], n_c [1000, 2000], n_e [10, 30].
  const EvaluationRecord rec = MakeRun(3.5, 10, 0.150, 1500, 20, 4);
  const std::vector<EvaluationRecord> all = {
      rec,
      MakeRun(3.2, 8, 0.151, 1510, 20.2, 4),   // within 2 % of each range: a member
      MakeRun(4.6, 14, 0.149, 1490, 19.8, 4),  // a member
      MakeRun(4.6, 14, 0.149, 1490, 19.8, 4),  // the same set again: counted once
      MakeRun(5.0, 9, 0.150, 1500, 20, 3),     // one loop closure fewer
      MakeRun(2.5, 12, 0.150, 1530, 20, 4),    // n_c 30 away, more than 2 % of 1000
      MakeRun(2.0, 6, 0.100, 1000, 10, 4),     // the range's ends
      MakeRun(6.0, 20, 0.200, 2000, 30, 9),
      EvaluationRecord::Failed("f", {{"loop_search_maximum_distance", 2.1}}, "crash"),
  };
  const auto region = FindEquivalentRegion(all, rec, Space(), kPaper);
  ASSERT_TRUE(region.has_value());
  EXPECT_EQ(region->members, 3u);
  EXPECT_EQ(region->evaluated, 7u);
  EXPECT_EQ(region->loop_closures, 4);
  ASSERT_EQ(region->ranges.size(), 2u);
  EXPECT_EQ(region->ranges[0].name, "loop_search_maximum_distance");
  EXPECT_DOUBLE_EQ(region->ranges[0].lower, 3.2);
  EXPECT_DOUBLE_EQ(region->ranges[0].upper, 4.6);
  EXPECT_DOUBLE_EQ(region->ranges[1].lower, 8.0);
  EXPECT_DOUBLE_EQ(region->ranges[1].upper, 14.0);
  EXPECT_EQ(region->Describe(),
            "loop_search_maximum_distance in [3.2, 4.6], loop_match_minimum_chain_size in [8, 14] give an "
            "equivalent map (3 of 7 evaluated parameter sets)");
  // A wider tolerance takes in the run 30 corners away.
  EXPECT_EQ(FindEquivalentRegion(all, rec, Space(), kPaper, 0.05)->members, 4u);
}

TEST(FindEquivalentRegion, AloneOrFailed) {
  const EvaluationRecord rec = MakeRun(3.5, 10, 0.150, 1500, 20, 4);
  const auto alone = FindEquivalentRegion({}, rec, Space(), kPaper);
  ASSERT_TRUE(alone.has_value());
  EXPECT_EQ(alone->members, 1u);
  EXPECT_EQ(alone->evaluated, 1u);
  EXPECT_EQ(alone->Describe(),
            "loop_search_maximum_distance = 3.5, loop_match_minimum_chain_size = 10 give an equivalent map (1 of 1 "
            "evaluated parameter set)");
  EXPECT_FALSE(FindEquivalentRegion({rec}, EvaluationRecord::Failed("k", {}, "crash"), Space(), kPaper).has_value());
}

}  // namespace
}  // namespace slamtune::optim
