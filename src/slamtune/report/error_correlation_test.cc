#include "slamtune/report/error_correlation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

using ::testing::HasSubstr;

const std::vector<optim::Objective> kPaper = optim::ObjectiveSet(optim::ObjectiveSetKind::kPaper).objectives();

TEST(GroundTruthRuns, KeepsDistinctSuccessfulRunsWithErrors) {
  const auto result = testing::FakeOptimizeResult(true);
  // 12 distinct sets, one repeated, one failed.
  ASSERT_EQ(result.evaluations.size(), 14u);
  EXPECT_EQ(GroundTruthRuns(result.evaluations).size(), 12u);
  EXPECT_TRUE(GroundTruthRuns(testing::FakeOptimizeResult(false).evaluations).empty());
}

TEST(CorrelateObjectivesWithError, ClassifiesAndStatesTheEvidence) {
  const auto summary = CorrelateObjectivesWithError(testing::FakeOptimizeResult(true).evaluations, kPaper);
  EXPECT_EQ(summary.parameter_sets, 12);
  ASSERT_EQ(summary.objectives.size(), 3u);
  EXPECT_EQ(summary.objectives[0].objective, "occupied_ratio");
  EXPECT_DOUBLE_EQ(summary.objectives[0].spearman.rho, 1.0);
  EXPECT_EQ(summary.objectives[0].tracking, Tracking::kTracks);
  EXPECT_EQ(summary.objectives[1].tracking, Tracking::kTracks);
  EXPECT_EQ(summary.objectives[2].tracking, Tracking::kAgainst);
  EXPECT_THAT(summary.objectives[0].reading, HasSubstr("Occupied ratio (eta) tracks the error"));
  EXPECT_THAT(summary.statement,
              HasSubstr("On this log, eta and n_c track the translational error and n_e runs against it"));
  EXPECT_THAT(summary.statement, HasSubstr("12 distinct parameter sets"));
}

TEST(CorrelateObjectivesWithError, TooFewSetsCannotBeJudged) {
  auto evaluations = testing::FakeOptimizeResult(true).evaluations;
  evaluations.resize(3);
  const auto summary = CorrelateObjectivesWithError(evaluations, kPaper);
  EXPECT_EQ(summary.objectives[0].tracking, Tracking::kUndecided);
  EXPECT_THAT(summary.objectives[0].reading, HasSubstr("too few parameter sets"));
  EXPECT_THAT(summary.statement, HasSubstr("eta, n_c and n_e cannot be judged"));
  const auto none = CorrelateObjectivesWithError({}, kPaper);
  EXPECT_EQ(none.parameter_sets, 0);
  EXPECT_THAT(none.objectives[1].reading, HasSubstr("no correlation"));
}

TEST(CorrelationReadingOptions, ValidateNamesTheField) {
  CorrelationReadingOptions o;
  o.strong = 0.1;
  try {
    o.Validate();
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("CorrelationReadingOptions.strong = 0.1"));
  }
}

}  // namespace
}  // namespace slamtune::report
