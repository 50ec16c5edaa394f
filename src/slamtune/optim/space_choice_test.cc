#include "slamtune/optim/space_choice.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "slamtune/sim/simulation.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;

DefaultSpaceChoice ChooseOn(const char* world, bool plant_world_faults = true) {
  sim::SimulationOptions options;
  options.world = world;
  options.plant_world_faults = plant_world_faults;
  SlamEvaluationContext context;
  context.log = std::make_shared<io::LaserLog>(sim::Simulate(options).log);
  return ChooseDefaultSpace(context);
}

TEST(ChooseDefaultSpace, AWorkingFrontEndKeepsTheLoopSpace) {
  const DefaultSpaceChoice choice = ChooseOn("office");
  EXPECT_EQ(choice.kind, DefaultSpaceKind::kLoop);
  EXPECT_STREQ(choice.space_name(), "loop");
  EXPECT_EQ(choice.evidence.breaks, 0);
  EXPECT_TRUE(choice.evidence.degenerate_stretches.empty());
  EXPECT_EQ(static_cast<int>(choice.steps.size()), choice.evidence.matches);
  EXPECT_THAT(choice.Reason(), HasSubstr("search space: r and g around the base configuration"));
}

TEST(ChooseDefaultSpace, ABreakInTheSequentialMatchingChoosesTheFrontEndSpace) {
  const DefaultSpaceChoice choice = ChooseOn("office-jump");
  EXPECT_EQ(choice.kind, DefaultSpaceKind::kFrontEnd);
  EXPECT_EQ(choice.evidence.breaks, 1);
  EXPECT_THAT(choice.Reason(), HasSubstr("search space: front-end"));
  EXPECT_THAT(choice.Reason(), HasSubstr("lost its place"));
  // The run's map and poses come with it, to draw the break where it happened.
  EXPECT_GT(choice.map.width, 0);
  EXPECT_EQ(choice.map.pixels.size(), static_cast<std::size_t>(choice.map.width) * choice.map.height);
  EXPECT_FALSE(choice.trajectory.empty());
}

// The corridor-long world's bare south corridor: no match is at the window's edge, yet the
// scans there constrain one direction only, over tens of metres.
TEST(ChooseDefaultSpace, ALongFeaturelessCorridorChoosesTheFrontEndSpace) {
  const DefaultSpaceChoice choice = ChooseOn("corridor-long");
  EXPECT_EQ(choice.kind, DefaultSpaceKind::kFrontEnd);
  EXPECT_EQ(choice.evidence.breaks, 0);
  ASSERT_FALSE(choice.evidence.degenerate_stretches.empty());
  EXPECT_GE(choice.evidence.degenerate_stretches[0].length_m, 35.0);
  EXPECT_THAT(choice.Reason(), HasSubstr("structure in one direction only"));
}

}  // namespace
}  // namespace slamtune::optim
