#include "slamtune/tune/optimize/optimize_options.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/optim/optimizer.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

OptimizeOptions Planned() {
  OptimizeOptions o;
  o.inputs.log = "drive.mcap";
  o.inputs.sets = {"minimum_travel_distance=0.3"};
  o.space = "front-end";
  o.objectives = "drawn";
  o.settling.tolerance = 0.01;
  o.budget = {12, 30, 3, 2};
  o.seed = 9;
  o.space_probed = true;
  o.space_lower = {{"correlation_search_space_dimension", 0.6}};
  o.initial = {{{"correlation_search_space_dimension", 0.8}, {"loop_search_maximum_distance", 3.0}}};
  return o;
}

TEST(NamedSpace, NamesReadBackAndFilesAreNotNames) {
  for (NamedSpace s : {NamedSpace::kLoop, NamedSpace::kPaper, NamedSpace::kFrontEnd}) {
    EXPECT_EQ(ParseNamedSpace(NameOf(s)), s);
  }
  EXPECT_EQ(ParseNamedSpace("front-end.yaml"), std::nullopt);
  EXPECT_EQ(ParseNamedSpace(""), std::nullopt);
  EXPECT_STREQ(NameOf(NamedSpace::kFrontEnd), "front-end");
}

TEST(OptimizeOptions, TheRecordKeepsEverythingThatChangesResults) {
  const OptimizeOptions o = Planned();
  const nlohmann::json j = o.ToJson();
  EXPECT_EQ(j.at("schema"), kInvocationSchema);
  EXPECT_EQ(j.at("settling").at("sound_answer_window"), 2);  // the budget's window is the stop's
  const OptimizeOptions back = OptimizeOptions::FromJson(j);
  EXPECT_EQ(back.ToJson(), j);
  EXPECT_EQ(back.budget.population, 12u);
  EXPECT_EQ(back.budget.sound_answer_window, 2);
  EXPECT_EQ(back.settling.sound_answer_window, 2);
  EXPECT_EQ(back.initial, o.initial);
  EXPECT_EQ(back.inputs.sets, o.inputs.sets);
  // A current record passes through the migration unchanged.
  EXPECT_EQ(MigrateInvocation(j, "run.sqlite"), j);
}

TEST(OptimizeOptions, ABudgetLeftToTheTunerIsRecordedAsTheDefaults) {
  const nlohmann::json j = OptimizeOptions{}.ToJson();
  const optim::OptimizeSettings defaults;
  EXPECT_EQ(j.at("population"), defaults.population);
  EXPECT_EQ(j.at("generations"), defaults.generations);
  EXPECT_EQ(j.at("divisions"), defaults.divisions);
  EXPECT_EQ(j.at("objectives"), kAutomaticObjectives);
}

// The record of a folder written before the record had a schema number (and before objective
// sets, early stopping, named spaces, --vary, the informed start and the base rule).
nlohmann::json OldestRecord() {
  nlohmann::json inputs = TuningInputOptions{}.ToJson();
  inputs.erase("base_rule");
  return {{"inputs", inputs}, {"space", ""}, {"population", 36}, {"generations", 60}, {"divisions", 7}, {"seed", 1}};
}

TEST(MigrateInvocation, TheOldestFoldersResumeAsTheyRan) {
  const OptimizeOptions o = OptimizeOptions::FromJson(MigrateInvocation(OldestRecord(), "run.sqlite"));
  EXPECT_EQ(o.objectives, "paper");
  EXPECT_FALSE(o.settling.enabled);  // the whole budget
  EXPECT_TRUE(o.around_base_without_steps);
  EXPECT_FALSE(o.space_probed);
  EXPECT_TRUE(o.vary.empty());
  EXPECT_TRUE(o.initial.empty());
  EXPECT_EQ(o.inputs.base_rule, slam::BaseRule::kPresetThenFile);
  EXPECT_EQ(o.budget.sound_answer_window, 0);
}

TEST(MigrateInvocation, AnOldFolderWithASpaceOrVaryIsNotAroundTheBase) {
  nlohmann::json with_space = OldestRecord();
  with_space["space"] = "space.yaml";
  EXPECT_FALSE(OptimizeOptions::FromJson(MigrateInvocation(with_space, "x")).around_base_without_steps);
  nlohmann::json with_vary = OldestRecord();
  with_vary["vary"] = {"r=2:6"};
  EXPECT_FALSE(OptimizeOptions::FromJson(MigrateInvocation(with_vary, "x")).around_base_without_steps);
  // What an old folder did record is kept.
  nlohmann::json with_objectives = OldestRecord();
  with_objectives["objectives"] = "occupied";
  with_objectives["inputs"]["base_rule"] = "node_defaults";
  const OptimizeOptions o = OptimizeOptions::FromJson(MigrateInvocation(with_objectives, "x"));
  EXPECT_EQ(o.objectives, "occupied");
  EXPECT_EQ(o.inputs.base_rule, slam::BaseRule::kNodeDefaults);
}

TEST(MigrateInvocation, ANewerSchemaIsRefusedNamingTheDatabase) {
  nlohmann::json j = Planned().ToJson();
  j["schema"] = kInvocationSchema + 1;
  EXPECT_THAT(
      [&] { MigrateInvocation(j, "runs/a/run.sqlite"); },
      ThrowsMessage<InputError>(HasSubstr("runs/a/run.sqlite: the run folder was written by a newer slamtune")));
}

}  // namespace
}  // namespace slamtune::tune
