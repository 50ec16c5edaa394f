#include "slamtune/optim/budget_estimate.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(BudgetEstimateLine, ScalesTheFirstGenerationToTheRest) {
  // 20 runs in 40 s: 2 s each, 40 s per generation, 8 more generations = 320 s.
  const std::string line = BudgetEstimateLine(20, 8, 20, 40.0, true);
  EXPECT_THAT(line, HasSubstr("generation 0: 20 SLAM runs in"));
  EXPECT_THAT(line, HasSubstr("(2.0 s each)"));
  EXPECT_THAT(line, HasSubstr("the 8 generations to come take up to 5m20s"));
  EXPECT_THAT(line, HasSubstr("stops once the answer has settled"));
  EXPECT_THAT(line, Not(HasSubstr("over")));
}

TEST(BudgetEstimateLine, AdvisesOnABudgetOfHours) {
  // The seed paper's budget on a log at 4 s a run: 66 x 60 runs, about 4.4 h.
  const std::string line = BudgetEstimateLine(66, 60, 66, 264.0, false);
  EXPECT_THAT(line, HasSubstr("That is over 30m"));
  EXPECT_THAT(line, HasSubstr("--population or --generations"));
  EXPECT_THAT(line, HasSubstr("(less when parameter sets repeat)"));
}

TEST(BudgetEstimateLine, RefusesABadThreshold) {
  BudgetEstimateOptions bad;
  bad.warn_after_s = 0.0;
  EXPECT_THROW(BudgetEstimateLine(20, 8, 20, 40.0, true, bad), InputError);
}

}  // namespace
}  // namespace slamtune::optim
