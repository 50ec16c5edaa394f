#include "slamtune/tune/sweep_command.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(ParseSweepRange, ShortNamesExpandAndTheStepDefaultsToOne) {
  const SweepRange r = ParseSweepRange("g=6:20");
  EXPECT_EQ(r.name, "loop_match_minimum_chain_size");
  EXPECT_EQ(r.lo, 6);
  EXPECT_EQ(r.hi, 20);
  EXPECT_EQ(r.step, 1);
  EXPECT_EQ(ParseSweepRange("r=2:6:0.25").step, 0.25);
}

TEST(ParseSweepRange, MalformedRangesAreNamed) {
  EXPECT_THAT([] { ParseSweepRange("r2:6"); }, ThrowsMessage<InputError>(HasSubstr("--vary must be NAME=LO:HI")));
  EXPECT_THAT([] { ParseSweepRange("r=2"); }, ThrowsMessage<InputError>(HasSubstr("--vary must be NAME=LO:HI")));
  EXPECT_THAT([] { ParseSweepRange("r=6:2"); }, ThrowsMessage<InputError>(HasSubstr("bounds reversed (6 > 2)")));
  EXPECT_THAT([] { ParseSweepRange("r=2:6:0"); }, ThrowsMessage<InputError>(HasSubstr("STEP must be > 0")));
  EXPECT_THAT([] { ParseSweepRange("r=0:2:0.0001"); }, ThrowsMessage<InputError>(HasSubstr("more than 10000")));
  EXPECT_THAT([] { ParseSweepRange("r=a:6"); }, ThrowsMessage<InputError>(HasSubstr("--vary LO")));
}

TEST(SweepBatch, EveryValueWithTheFixedOnesAndValuesPrintAsWritten) {
  optim::SlamEvaluationContext context;
  const std::vector<optim::Assignment> batch = SweepBatch(ParseSweepRange("r=2:3:0.25"), {"g=8"}, context);
  ASSERT_EQ(batch.size(), 5u);
  EXPECT_EQ(batch[3].at("loop_search_maximum_distance"), 2.75);
  EXPECT_EQ(batch[4].at("loop_search_maximum_distance"), 3.0);
  for (const optim::Assignment& a : batch) EXPECT_EQ(a.at("loop_match_minimum_chain_size"), 8.0);
  EXPECT_THAT([&] { SweepBatch(ParseSweepRange("r=2:3"), {"g"}, context); },
              ThrowsMessage<InputError>(HasSubstr("--fix must be NAME=VALUE")));
  EXPECT_THROW(SweepBatch(ParseSweepRange("r=-3:-2"), {}, context), InputError);  // validated before any run
}

TEST(RunSweep, EachValueIsOneRunAndTheReportIsWritten) {
  const std::filesystem::path dir = testing::UniqueTempDir("sweep");
  sim::Simulation s = sim::Simulate(sim::SimulationOptions{});
  io::WriteCarmenLog((dir / "office.clf").string(), s.log);
  SweepOptions o;
  o.inputs.log = (dir / "office.clf").string();
  o.inputs.input.max_scans = 300;
  o.vary = "g=6:8:2";
  o.out = (dir / "out").string();
  o.run.quiet = true;
  o.run.jobs = 2;
  TuningProcess process;
  std::vector<double> seen;
  SweepHooks hooks;
  hooks.evaluated = [&](const SweepStep& step) { seen.push_back(step.value); };
  const SweepOutcome out = RunSweep(o, process, hooks);
  ASSERT_EQ(out.points.size(), 2u);
  EXPECT_EQ(out.points[0].value, 6.0);
  EXPECT_EQ(out.points[1].value, 8.0);
  EXPECT_EQ(seen.size(), 2u);
  EXPECT_EQ(out.report.failed, 0u);
  EXPECT_FALSE(out.with_errors);
  EXPECT_TRUE(std::filesystem::exists(dir / "out" / "sweep.csv"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slamtune::tune
