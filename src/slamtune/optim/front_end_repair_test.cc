#include "slamtune/optim/front_end_repair.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>

#include "slamtune/optim/space_choice.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;

struct Probed {
  SlamEvaluationContext context;
  DefaultSpaceChoice choice;
};

// The first `scans` scans of `world` (each planted fault lies well within them: office-jump's
// at scan 201, office-slip's at 451), probed as the default optimize probes a log.
Probed ProbeWorld(const char* world, std::size_t scans) {
  sim::SimulationOptions options;
  options.world = world;
  Probed p;
  auto log = std::make_shared<io::LaserLog>(sim::Simulate(options).log);
  log->scans.resize(std::min(log->scans.size(), scans));
  p.context.log = std::move(log);
  p.choice = ChooseDefaultSpace(p.context);
  return p;
}

// A wheel slip beyond the heading range: the repair widens the heading range until the prefix
// holds past the slip, and the search may not go below what broke.
TEST(RepairFrontEnd, AWheelSlipWidensTheHeadingRange) {
  const Probed p = ProbeWorld("office-slip", 900);
  ASSERT_EQ(p.choice.kind, DefaultSpaceKind::kFrontEnd);
  const SearchSpace space = SearchSpace::FrontEnd(p.context.base);
  const FrontEndRepair repair = RepairFrontEnd(p.context, p.choice.steps, p.choice.evidence, space);
  ASSERT_TRUE(repair.repaired.count("coarse_search_angle_offset")) << repair.Describe();
  const double kept = repair.repaired.at("coarse_search_angle_offset");
  const double lower = repair.lower_bounds.at("coarse_search_angle_offset");
  EXPECT_GT(kept, lower);
  EXPECT_GE(lower, p.context.base.coarse_search_angle_offset);
  EXPECT_GE(kept, 1.0);  // the slip is 60 deg (1.05 rad)
  EXPECT_THAT(repair.Describe(), HasSubstr("informed start: at log scan"));
  EXPECT_THAT(repair.Describe(), HasSubstr("held"));
  // The repaired configuration maps past the slip without a break, to the end of the slice.
  SlamEvaluationContext watched = p.context;
  watched.stop_broken_runs = true;
  Assignment a = repair.repaired;
  EXPECT_EQ(EvaluateSlam(watched, a).status, RunStatus::kOk);
  // The space starts at the bound; the dimension's lattice is kept.
  const SearchSpace narrowed = WithLowerBounds(space, repair.lower_bounds);
  for (const Dimension& d : narrowed.dimensions) {
    if (d.name != "coarse_search_angle_offset") continue;
    EXPECT_DOUBLE_EQ(d.lower, lower);
    EXPECT_DOUBLE_EQ(d.ValueOf(kept), kept);
  }
  // Deterministic.
  EXPECT_EQ(RepairFrontEnd(p.context, p.choice.steps, p.choice.evidence, space).repaired, repair.repaired);
}

// A jump beyond the window widens the window; a base run without a break tries nothing.
TEST(RepairFrontEnd, AJumpWidensTheWindowAndAWorkingRunTriesNothing) {
  const Probed jump = ProbeWorld("office-jump", 700);
  const FrontEndRepair repair =
      RepairFrontEnd(jump.context, jump.choice.steps, jump.choice.evidence, SearchSpace::FrontEnd(jump.context.base));
  ASSERT_TRUE(repair.repaired.count("correlation_search_space_dimension")) << repair.Describe();
  EXPECT_GT(repair.repaired.at("correlation_search_space_dimension"),
            jump.context.base.correlation_search_space_dimension);
  EXPECT_GT(repair.prefix_runs, 0);
  const Probed office = ProbeWorld("office", 700);
  const FrontEndRepair none = RepairFrontEnd(office.context, office.choice.steps, office.choice.evidence,
                                             SearchSpace::FrontEnd(office.context.base));
  EXPECT_TRUE(none.empty());
  EXPECT_EQ(none.Describe(), "");
  EXPECT_EQ(none.prefix_runs, 0);
}

}  // namespace
}  // namespace slamtune::optim
