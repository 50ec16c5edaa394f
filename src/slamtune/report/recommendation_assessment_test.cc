#include "slamtune/report/recommendation_assessment.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <utility>

#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

using ::testing::ElementsAre;

// The fake result (8 individuals, 5 holding the recommended r = 3, g = 12; the knee r = 3.5,
// g = 10; the space r in [2, 6], g in [6, 20]) with the recommendation moved to (r, g).
optim::OptimizeResult ResultRecommending(double r, int g) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  result.candidates[0].record = testing::FakeRecord(r, g, 0.1, false);
  return result;
}

RecommendationAssessment AssessedOrFail(const optim::OptimizeResult& result) {
  const std::optional<RecommendationAssessment> a = AssessRecommendation(result);
  EXPECT_TRUE(a.has_value());
  return a.value_or(RecommendationAssessment{});
}

TEST(AssessRecommendation, NothingToAssessWithoutARecommendation) {
  EXPECT_FALSE(AssessRecommendation(optim::OptimizeResult{}).has_value());
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  result.candidates.erase(result.candidates.begin());  // knee, worst and default remain
  EXPECT_FALSE(AssessRecommendation(result).has_value());
}

TEST(AssessRecommendation, ConvergedWhenAMajorityHoldsTheSet) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  ASSERT_EQ(result.population, 8u);
  result.recommended_share = 5;
  RecommendationAssessment a = AssessedOrFail(result);
  EXPECT_EQ(a.share, 5);
  EXPECT_EQ(a.population, 8u);
  EXPECT_EQ(a.agreement, Agreement::kMajority);
  EXPECT_TRUE(a.converged());

  result.recommended_share = 4;  // half is not a majority
  a = AssessedOrFail(result);
  EXPECT_EQ(a.agreement, Agreement::kPlurality);
  EXPECT_FALSE(a.converged());
}

TEST(AssessRecommendation, NoAgreementWhenNoSetIsShared) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  result.recommended_share = 1;
  EXPECT_EQ(AssessedOrFail(result).agreement, Agreement::kNone);
  EXPECT_FALSE(AssessedOrFail(result).converged());
  result.recommended_share = 2;
  EXPECT_EQ(AssessedOrFail(result).agreement, Agreement::kPlurality);
}

TEST(AssessRecommendation, WithoutThePopulationSizeTwoHoldersAgree) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  result.population = 0;
  result.recommended_share = 2;
  EXPECT_EQ(AssessedOrFail(result).agreement, Agreement::kMajority);
  result.recommended_share = 1;
  EXPECT_EQ(AssessedOrFail(result).agreement, Agreement::kNone);
}

TEST(AssessRecommendation, KneeIsTheSameSetOrAnother) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(false);
  EXPECT_EQ(AssessedOrFail(result).knee, KneeRelation::kOtherSet);  // r = 3.5, g = 10

  result.candidates[1].record = result.candidates[0].record;
  EXPECT_EQ(AssessedOrFail(result).knee, KneeRelation::kSameSet);

  // Without keys the parameters decide.
  result.candidates[0].record.key.clear();
  result.candidates[1].record.key = "another key";
  EXPECT_EQ(AssessedOrFail(result).knee, KneeRelation::kSameSet);
  result.candidates[1].record.params["loop_match_minimum_chain_size"] = 13;
  EXPECT_EQ(AssessedOrFail(result).knee, KneeRelation::kOtherSet);

  result.candidates.erase(result.candidates.begin() + 1);
  EXPECT_EQ(AssessedOrFail(result).knee, KneeRelation::kNoKnee);
}

TEST(AssessRecommendation, NoBoundHitInsideTheRanges) {
  EXPECT_TRUE(AssessedOrFail(ResultRecommending(3.0, 12)).bound_hits.empty());
  // Just over 1 % of the range (0.04 m) from either bound, and an integer one step inside.
  EXPECT_TRUE(AssessedOrFail(ResultRecommending(2.041, 7)).bound_hits.empty());
  EXPECT_TRUE(AssessedOrFail(ResultRecommending(5.959, 19)).bound_hits.empty());
}

TEST(AssessRecommendation, ARealWithinOnePercentOfABoundAndAnIntegerOnOneAreHits) {
  const RecommendationAssessment a = AssessedOrFail(ResultRecommending(5.97, 6));
  ASSERT_EQ(a.bound_hits.size(), 2u);
  EXPECT_EQ(a.bound_hits[0].name, "loop_search_maximum_distance");
  EXPECT_DOUBLE_EQ(a.bound_hits[0].value, 5.97);
  EXPECT_DOUBLE_EQ(a.bound_hits[0].lower, 2.0);
  EXPECT_DOUBLE_EQ(a.bound_hits[0].upper, 6.0);
  EXPECT_FALSE(a.bound_hits[0].at_lower);
  EXPECT_EQ(a.bound_hits[1].name, "loop_match_minimum_chain_size");
  EXPECT_TRUE(a.bound_hits[1].at_lower);

  const RecommendationAssessment low = AssessedOrFail(ResultRecommending(2.0, 20));
  ASSERT_EQ(low.bound_hits.size(), 2u);
  EXPECT_TRUE(low.bound_hits[0].at_lower);
  EXPECT_FALSE(low.bound_hits[1].at_lower);
}

TEST(AssessRecommendation, NoBoundHitWithoutARangeOrAValue) {
  optim::OptimizeResult result = ResultRecommending(6.0, 20);
  result.space.dimensions[0].lower = result.space.dimensions[0].upper = 6.0;  // no range
  result.candidates[0].record.params.erase("loop_match_minimum_chain_size");
  EXPECT_TRUE(AssessedOrFail(result).bound_hits.empty());
}

TEST(AssessRecommendation, NextStepsOfAConvergedBetterAnswerWithGroundTruth) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(true);
  result.verdict_kind = optim::VerdictKind::kBetter;
  EXPECT_THAT(AssessedOrFail(result).next_steps, ElementsAre(NextStep::kLoadAndConfirm, NextStep::kCheckLoopClosures));
}

TEST(AssessRecommendation, NextStepsOfAnUnsettledAnswerOnABound) {
  optim::OptimizeResult result = ResultRecommending(6.0, 12);
  result.verdict_kind = optim::VerdictKind::kWorse;
  result.recommended_share = 3;
  EXPECT_THAT(AssessedOrFail(result).next_steps,
              ElementsAre(NextStep::kKeepBase, NextStep::kWidenRange, NextStep::kRunLonger,
                          NextStep::kCheckLoopClosures, NextStep::kAddGroundTruth));
}

TEST(AssessRecommendation, TheVerdictDecidesTheFirstStep) {
  optim::OptimizeResult result = testing::FakeOptimizeResult(true);
  const std::pair<optim::VerdictKind, NextStep> cases[] = {
      {optim::VerdictKind::kBetter, NextStep::kLoadAndConfirm},
      {optim::VerdictKind::kFailed, NextStep::kReadWhyItFailed},
      {optim::VerdictKind::kEquivalent, NextStep::kKeepBase},
      {optim::VerdictKind::kWorse, NextStep::kKeepBase},
      {optim::VerdictKind::kMixed, NextStep::kKeepBase},
  };
  for (const auto& [verdict, first] : cases) {
    result.verdict_kind = verdict;
    const RecommendationAssessment a = AssessedOrFail(result);
    ASSERT_FALSE(a.next_steps.empty());
    EXPECT_EQ(a.next_steps.front(), first) << optim::VerdictKindName(verdict);
  }
}

}  // namespace
}  // namespace slamtune::report
