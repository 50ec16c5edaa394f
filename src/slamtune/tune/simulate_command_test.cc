#include "slamtune/tune/simulate_command.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::string SimulatedFileText(const std::string& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

TEST(ResolveSimulation, TheLaserOffsetFaultsAndWorldFaultsGoIntoTheSimulationOptions) {
  SimulateOptions options;
  options.simulation.odometry.faults.push_back(sim::ParseOdometryFault("jump,5,0.1,1"));
  options.laser_offset = {0.12, -0.04, 0.05};
  options.faults = {"spin,45,0.1,60", "reverse,80,2"};
  options.without_world_faults = true;
  const sim::SimulationOptions resolved = ResolveSimulation(options);
  EXPECT_EQ(resolved.laser_offset.x, 0.12);
  EXPECT_EQ(resolved.laser_offset.y, -0.04);
  EXPECT_EQ(resolved.laser_offset.theta, 0.05);
  EXPECT_FALSE(resolved.plant_world_faults);
  ASSERT_EQ(resolved.odometry.faults.size(), 3u);
  EXPECT_EQ(resolved.odometry.faults[0].kind, sim::OdometryFaultKind::kJump);
  EXPECT_EQ(resolved.odometry.faults[1].kind, sim::OdometryFaultKind::kSpin);
  EXPECT_EQ(resolved.odometry.faults[2].kind, sim::OdometryFaultKind::kReverse);

  const sim::SimulationOptions plain = ResolveSimulation(SimulateOptions{});
  EXPECT_TRUE(plain.plant_world_faults);
  EXPECT_EQ(plain.laser_offset.x, 0.0);
  EXPECT_TRUE(plain.odometry.faults.empty());
}

TEST(ResolveSimulation, MalformedOffsetsAndFaultsAreRefused) {
  SimulateOptions options;
  options.laser_offset = {0.1, 0.2};
  EXPECT_THAT([&] { ResolveSimulation(options); }, ThrowsMessage<InputError>(HasSubstr("--laser-offset")));
  options.laser_offset.clear();
  options.faults = {"wobble,1,2"};
  EXPECT_THAT([&] { ResolveSimulation(options); }, ThrowsMessage<InputError>(HasSubstr("wobble")));
}

TEST(SimulateAndWrite, WritesTheThreeFilesAndTheSameSeedGivesTheSameFiles) {
  const std::filesystem::path dir = testing::UniqueTempDir("simulate_command");
  SimulateOptions options;
  options.simulation.world = "hall";
  options.simulation.seed = 2;
  options.out = (dir / "a").string();
  const SimulateOutcome a = SimulateAndWrite(options);
  EXPECT_EQ(a.summary.world, "hall");
  EXPECT_EQ(a.summary.seed, 2u);
  EXPECT_GT(a.summary.scans, 100u);
  EXPECT_GE(a.seconds, 0.0);
  EXPECT_EQ(a.files.log, (dir / "a" / "hall.clf").string());
  for (const std::string& file : {a.files.log, a.files.relations, a.files.truth}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(file)) << file;
  }
  options.out = (dir / "b").string();
  const SimulateOutcome b = SimulateAndWrite(options);
  EXPECT_EQ(SimulatedFileText(a.files.log), SimulatedFileText(b.files.log));
  EXPECT_EQ(SimulatedFileText(a.files.truth), SimulatedFileText(b.files.truth));
  options.simulation.seed = 3;
  options.out = (dir / "c").string();
  EXPECT_NE(SimulatedFileText(a.files.log), SimulatedFileText(SimulateAndWrite(options).files.log));
  std::filesystem::remove_all(dir);
}

TEST(SimulateAndWrite, AFaultWorldPlantsItsFaultsUnlessLeftOut) {
  const std::filesystem::path dir = testing::UniqueTempDir("simulate_command");
  SimulateOptions options;
  options.simulation.world = "office-slip";
  options.out = dir.string();
  EXPECT_EQ(SimulateAndWrite(options).summary.odometry_faults.size(), 1u);
  options.without_world_faults = true;
  EXPECT_TRUE(SimulateAndWrite(options).summary.odometry_faults.empty());
  options.faults = {"jump,20,0.1,1"};
  const SimulateOutcome planted = SimulateAndWrite(options);
  ASSERT_EQ(planted.summary.odometry_faults.size(), 1u);
  EXPECT_THAT(planted.summary.odometry_faults[0], HasSubstr("jump"));
  std::filesystem::remove_all(dir);
}

TEST(SimulateAndWrite, TheOutputFolderAndTheOptionsAreRequiredToBeValid) {
  SimulateOptions options;
  options.simulation.world = "nowhere";
  EXPECT_THAT([&] { SimulateAndWrite(options); }, ThrowsMessage<InputError>(HasSubstr("--out: required")));
  const std::filesystem::path dir = testing::UniqueTempDir("simulate_command");
  options.out = dir.string();
  EXPECT_THAT([&] { SimulateAndWrite(options); }, ThrowsMessage<InputError>(HasSubstr("nowhere")));
  options.simulation.world = "office";
  options.simulation.speed_mps = -1;
  EXPECT_THAT([&] { SimulateAndWrite(options); }, ThrowsMessage<InputError>(HasSubstr("speed")));
  EXPECT_FALSE(std::filesystem::exists(dir / "office.clf"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slamtune::tune
