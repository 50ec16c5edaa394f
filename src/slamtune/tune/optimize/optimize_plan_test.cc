#include "slamtune/tune/optimize/optimize_plan.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/optim/space_choice.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(DefaultBudget, TheBuiltInWorldsBudgetIsForNewRunsOnly) {
  EXPECT_EQ(DefaultBudget(true, false).population, kBuiltInWorldBudget.population);
  EXPECT_EQ(DefaultBudget(true, false).generations, kBuiltInWorldBudget.generations);
  EXPECT_EQ(DefaultBudget(true, true).population, optim::OptimizeSettings{}.population);
  EXPECT_EQ(DefaultBudget(false, false).divisions, optim::OptimizeSettings{}.divisions);
}

TEST(DefaultBudget, ABrokenMapTakesItsPopulationDivisionsAndStopButNotTheGenerations) {
  const BudgetDefaults broken = BrokenMapDefaults(kBuiltInWorldBudget);
  EXPECT_EQ(broken.population, optim::BrokenMapBudget{}.population);
  EXPECT_EQ(broken.divisions, optim::BrokenMapBudget{}.divisions);
  EXPECT_EQ(broken.sound_answer_window, optim::BrokenMapBudget{}.sound_answer_window);
  EXPECT_EQ(broken.generations, kBuiltInWorldBudget.generations);
}

TEST(NamedOrFileSpace, EachNameIsItsSpace) {
  slam::MapperParams base;
  base.loop_search_maximum_distance = 5;
  OptimizeOptions o;
  o.space = "loop";
  EXPECT_EQ(NamedOrFileSpace(o, base).Fingerprint(), optim::SearchSpace::Loop(base).Fingerprint());
  o.space = "paper";
  EXPECT_EQ(NamedOrFileSpace(o, base).Fingerprint(), optim::SearchSpace::PaperDefault().Fingerprint());
  o.space = "front-end";
  EXPECT_EQ(NamedOrFileSpace(o, base).Fingerprint(), optim::SearchSpace::FrontEnd(base).Fingerprint());
  const optim::Dimension first = optim::SearchSpace::FrontEnd(base).dimensions.front();
  o.space_lower = {{first.name, first.step > 0 ? first.lower + first.step : (first.lower + first.upper) / 2}};
  EXPECT_NE(NamedOrFileSpace(o, base).Fingerprint(), optim::SearchSpace::FrontEnd(base).Fingerprint());
  o = OptimizeOptions{};
  o.around_base_without_steps = true;
  EXPECT_EQ(NamedOrFileSpace(o, base).Fingerprint(),
            optim::SearchSpace::AroundBase(5, base.loop_match_minimum_chain_size).Fingerprint());
  o = OptimizeOptions{};
  o.space = "/nonexistent/space.yaml";
  EXPECT_THROW(NamedOrFileSpace(o, base), InputError);
}

// Plans on the built-in office world with the space given, so no SLAM run is made.
class PlanOnTheOffice : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    inputs_ = new TuningInputs(LoadTuningInputs(TuningInputOptions{}, InputNotes::kNone));
  }
  static void TearDownTestSuite() { delete inputs_; }
  void SetUp() override { dir_ = testing::UniqueTempDir("optimize_plan"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  OptimizationPlan Plan(OptimizeOptions& options, bool resume = false) {
    RunFolder folder(resume ? "" : dir_.string(), resume ? dir_.string() : "");
    run_.quiet = true;
    return PlanOptimization(*inputs_, folder, options, run_);
  }

  static TuningInputs* inputs_;
  std::filesystem::path dir_;
  TuningRunOptions run_;
};
TuningInputs* PlanOnTheOffice::inputs_ = nullptr;

TEST_F(PlanOnTheOffice, TheBudgetLeftToTheTunerIsTheWorldsAndIsRecorded) {
  OptimizeOptions o;
  o.space = "loop";
  o.budget.generations = 3;
  const OptimizationPlan plan = Plan(o);
  EXPECT_EQ(plan.settings.population, kBuiltInWorldBudget.population);
  EXPECT_EQ(plan.settings.divisions, kBuiltInWorldBudget.divisions);
  EXPECT_EQ(plan.settings.generations, 3u);
  EXPECT_EQ(o.budget.population, kBuiltInWorldBudget.population);  // recorded for --resume
  EXPECT_EQ(o.objectives, "occupied");                             // auto: the space does not vary sampling
  EXPECT_FALSE(plan.context->stop_broken_runs);
  EXPECT_EQ(plan.settings.default_assignment.size(), 2u);
  EXPECT_FALSE(o.space_probed);
}

TEST_F(PlanOnTheOffice, FlagsGiveTheSpaceAndTheFrontEndStopsBrokenRuns) {
  OptimizeOptions o;
  o.vary = {"correlation_search_space_dimension=0.3:1.2", "r=2:6"};
  o.fix = {"g=8"};
  const OptimizationPlan plan = Plan(o);
  EXPECT_EQ(plan.settings.space.size(), 2u);
  EXPECT_TRUE(plan.context->stop_broken_runs);
  EXPECT_EQ(plan.settings.engine.at("stop_broken_runs"), true);
  EXPECT_EQ(plan.context->base.loop_match_minimum_chain_size, 8);  // the fixed value is in every run's base
}

TEST_F(PlanOnTheOffice, ConflictingOrUnknownOptionsAreRefusedBeforeAnyRun) {
  OptimizeOptions o;
  o.space = "loop";
  o.vary = {"r=2:6"};
  EXPECT_THAT([&] { Plan(o); }, ThrowsMessage<InputError>(HasSubstr("either with --space or with --vary/--fix")));
  o = OptimizeOptions{};
  o.fix = {"g=8"};
  EXPECT_THAT([&] { Plan(o); }, ThrowsMessage<InputError>(HasSubstr("--fix goes with --vary")));
  o = OptimizeOptions{};
  o.space = "loop";
  o.objectives = "beauty";
  EXPECT_THAT([&] { Plan(o); }, ThrowsMessage<InputError>(HasSubstr("--objectives: unknown objective set 'beauty'")));
  o.objectives = "paper";
  o.budget.population = 2;
  EXPECT_THAT([&] { Plan(o); }, ThrowsMessage<InputError>(HasSubstr("population")));
}

}  // namespace
}  // namespace slamtune::tune
