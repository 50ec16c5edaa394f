#include "slamtune/nsga3/variation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

TEST(VariationOptions, DefaultsAreThePapersAndValid) {
  const VariationOptions o;
  EXPECT_NO_THROW(o.Validate());
  EXPECT_EQ(o.crossover_probability, 1.0);
  EXPECT_EQ(o.crossover_eta, 30.0);
  EXPECT_EQ(o.mutation_eta, 20.0);
  EXPECT_DOUBLE_EQ(o.MutationProbability(12), 1.0 / 12.0);
}

TEST(VariationOptions, RejectsInvalidValuesNamingTheField) {
  VariationOptions o;
  o.crossover_probability = 1.5;
  EXPECT_THAT([&] { o.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("variation.crossover_probability = 1.5")));
  o = VariationOptions{};
  o.crossover_eta = 0.5;
  EXPECT_THAT([&] { o.Validate(); }, ::testing::ThrowsMessage<InputError>(HasSubstr("variation.crossover_eta = 0.5")));
  o = VariationOptions{};
  o.mutation_probability = -0.1;
  EXPECT_THAT([&] { o.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("variation.mutation_probability = -0.1")));
  o = VariationOptions{};
  o.mutation_eta = NAN;
  EXPECT_THAT([&] { o.Validate(); }, ::testing::ThrowsMessage<InputError>(HasSubstr("variation.mutation_eta = nan")));
}

TEST(RepairIntegers, RoundsHalfAwayFromZeroAndClampsOnlyTheIntegerGenes) {
  const Bounds bounds = {{-10, -10, -3, 0}, {10, 10, 3, 5}};
  std::vector<double> x = {0.5, 2.5, -2.5, 7.2};
  RepairIntegers(x, bounds, 2);
  EXPECT_THAT(x, ElementsAre(0.5, 2.5, -3.0, 5.0));
  x = {0.5, 1.49, -0.5, 0.4};
  RepairIntegers(x, bounds, 3);
  EXPECT_THAT(x, ElementsAre(0.5, 1.0, -1.0, 0.0));
}

TEST(MakeOffspring, ChildrenStayInBoundsAndIntegerGenesStayIntegral) {
  const Bounds bounds = {{0, -1, 2}, {1, 1, 9}};  // two reals, one integer in [2, 9]
  const std::vector<std::vector<double>> parents = {{0.1, -0.9, 2}, {0.9, 0.5, 9}, {0.5, 0.0, 5}, {0.2, 0.9, 3}};
  std::mt19937 rng(11);
  std::set<double> integer_values;
  for (int round = 0; round < 50; ++round) {
    const auto children = MakeOffspring(parents, 7, bounds, 1, VariationOptions{}, rng);
    ASSERT_EQ(children.size(), 7u);  // odd count: the last pair's second child is dropped
    for (const auto& c : children) {
      ASSERT_EQ(c.size(), 3u);
      for (std::size_t i = 0; i < 3; ++i) {
        EXPECT_GE(c[i], bounds.first[i]);
        EXPECT_LE(c[i], bounds.second[i]);
      }
      EXPECT_EQ(c[2], std::round(c[2]));
      integer_values.insert(c[2]);
    }
  }
  EXPECT_GT(integer_values.size(), 4u) << "integer genes must be explored, not frozen";
}

TEST(MakeOffspring, WithoutCrossoverAndMutationChildrenCopyParents) {
  VariationOptions none;
  none.crossover_probability = 0.0;
  none.mutation_probability = 0.0;
  const std::vector<std::vector<double>> parents = {{0.1, 0.2}, {0.3, 0.4}, {0.5, 0.6}};
  std::mt19937 rng(5);
  for (const auto& c : MakeOffspring(parents, 10, {{0, 0}, {1, 1}}, 0, none, rng)) {
    EXPECT_TRUE(c == parents[0] || c == parents[1] || c == parents[2]);
  }
}

TEST(MakeOffspring, SameSeedSameChildren) {
  const std::vector<std::vector<double>> parents = {{0.1, 0.2, 1}, {0.3, 0.4, 2}, {0.5, 0.6, 3}, {0.7, 0.8, 4}};
  const Bounds bounds = {{0, 0, 0}, {1, 1, 5}};
  std::mt19937 r1(9), r2(9), r3(10);
  const auto a = MakeOffspring(parents, 8, bounds, 1, VariationOptions{}, r1);
  EXPECT_EQ(a, MakeOffspring(parents, 8, bounds, 1, VariationOptions{}, r2));
  EXPECT_NE(a, MakeOffspring(parents, 8, bounds, 1, VariationOptions{}, r3));
}

}  // namespace
}  // namespace slamtune::nsga3
