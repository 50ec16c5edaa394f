#include "slamtune/tune/carmen_export.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/fixtures.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

std::string ExportedFileText(const std::filesystem::path& path) {
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

class CarmenExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::UniqueTempDir("carmen_export");
    sim::SimulationOptions world;
    world.seed = 7;
    simulation_ = sim::Simulate(world);
    io::WriteCarmenLog((dir_ / "office.clf").string(), simulation_.log);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  FaultOptions Fault(const std::vector<std::string>& faults) const {
    FaultOptions options;
    options.log = (dir_ / "office.clf").string();
    options.out = (dir_ / "faulted.clf").string();
    options.faults = faults;
    options.quiet = true;
    return options;
  }

  std::filesystem::path dir_;
  sim::Simulation simulation_;
};

TEST_F(CarmenExportTest, ARecordingIsWrittenAsTheScansSlamtuneReads) {
  ConvertOptions options;
  options.log = testing::FixturePath("recordings/office_zstd.mcap");
  options.out = (dir_ / "drive.clf").string();
  options.quiet = true;
  const CarmenExport exported = ConvertToCarmen(options);
  EXPECT_EQ(exported.written.scans, 655u);
  EXPECT_EQ(exported.written.robotlaser1, 655u);
  EXPECT_EQ(exported.non_finite_readings, 0u);
  const io::LaserLog original = ReadLog(options.log, options.input);
  const io::LaserLog back = io::ReadLaserLog(options.out, {});
  ASSERT_EQ(back.scans.size(), original.scans.size());
  EXPECT_EQ(back.scans[10].ranges.size(), original.scans[10].ranges.size());
  EXPECT_EQ(back.scans[10].ranges[90], original.scans[10].ranges[90]);
  const std::string text = ExportedFileText(options.out);
  EXPECT_NE(text.find("\n# converted by slamtune from " + options.log + "\n"), std::string::npos);
  EXPECT_EQ(DescribeExport(exported, "drive.clf"),
            "655 scans, " + std::to_string(exported.written.odometry) + " ODOM records; wrote drive.clf");
}

TEST_F(CarmenExportTest, NonFiniteReadingsAreWrittenAsTheMaxRangeAndCounted) {
  ConvertOptions options;
  options.log = testing::FixturePath("recordings/fault_inf_nan.mcap");
  options.out = (dir_ / "inf_nan.clf").string();
  options.quiet = true;
  const CarmenExport exported = ConvertToCarmen(options);
  EXPECT_GT(exported.non_finite_readings, 0u);
  EXPECT_THAT(DescribeExport(exported, "x.clf"),
              HasSubstr(", " + std::to_string(exported.non_finite_readings) +
                        " non-finite readings written as the max range; wrote x.clf"));
}

TEST_F(CarmenExportTest, ConvertRefusesAFolderBeforeReadingTheLog) {
  ConvertOptions options;
  options.log = (dir_ / "missing.clf").string();
  options.out = dir_.string();
  EXPECT_THAT([&] { ConvertToCarmen(options); }, ThrowsMessage<InputError>(HasSubstr("--out is a folder")));
}

TEST_F(CarmenExportTest, FaultsArePlantedInTheOdometryAndTheReadingsKept) {
  const FaultOptions options = Fault({"spin,10,0.1,60", "jump,30,0.1,1"});
  const FaultOutcome outcome = PlantFaultsAndWrite(options);
  ASSERT_EQ(outcome.planted.faults.size(), 2u);
  EXPECT_EQ(outcome.planted.faults[0].fault.kind, sim::OdometryFaultKind::kSpin);
  EXPECT_EQ(outcome.planted.faults[1].fault.kind, sim::OdometryFaultKind::kJump);
  EXPECT_GT(outcome.planted.travel_m, 30.0);
  ASSERT_TRUE(outcome.planted.faults[0].first_scan.has_value());
  EXPECT_EQ(outcome.exported.written.scans, simulation_.log.scans.size());

  const io::LaserLog original = io::ReadLaserLog(options.log, {});
  const io::LaserLog back = io::ReadLaserLog(options.out, {});
  ASSERT_EQ(back.scans.size(), original.scans.size());
  const std::size_t first = *outcome.planted.faults[0].first_scan;
  EXPECT_EQ(back.scans[first].ranges, original.scans[first].ranges);
  EXPECT_NEAR(back.scans[first].ipc_time, original.scans[first].ipc_time, 1e-6);
  EXPECT_NEAR(back.scans[first - 1].robot_pose.x, original.scans[first - 1].robot_pose.x, 1e-9);
  const Pose2 after = back.scans.back().robot_pose, before = original.scans.back().robot_pose;
  EXPECT_GT(std::hypot(after.x - before.x, after.y - before.y), 0.5);
  const std::string text = ExportedFileText(options.out);
  EXPECT_NE(text.find("\n# odometry faults planted by slamtune into " + options.log + ", located by"),
            std::string::npos);
  EXPECT_NE(text.find("\n# planted: " + outcome.planted.faults[1].Describe() + "\n"), std::string::npos);
}

TEST_F(CarmenExportTest, FaultRefusesMissingOrMalformedFaults) {
  EXPECT_THAT([&] { PlantFaultsAndWrite(Fault({})); }, ThrowsMessage<InputError>(HasSubstr("--fault: required")));
  EXPECT_THAT([&] { PlantFaultsAndWrite(Fault({"wobble,5,3"})); }, ThrowsMessage<InputError>(HasSubstr("wobble")));
  EXPECT_THAT([&] { PlantFaultsAndWrite(Fault({"reverse,5000,3"})); }, ThrowsMessage<InputError>(HasSubstr("5000")));
  EXPECT_FALSE(std::filesystem::exists(dir_ / "faulted.clf"));
}

TEST_F(CarmenExportTest, FaultChecksItsOutputBeforeReadingTheLog) {
  FaultOptions options = Fault({"reverse,5,3"});
  options.log = (dir_ / "missing.clf").string();
  options.out = dir_.string();
  EXPECT_THAT([&] { PlantFaultsAndWrite(options); }, ThrowsMessage<InputError>(HasSubstr("--out is a folder")));
  options.out = (dir_ / "no_folder" / "x.clf").string();
  EXPECT_THAT([&] { PlantFaultsAndWrite(options); },
              ThrowsMessage<InputError>(HasSubstr("the folder " + (dir_ / "no_folder").string() + " does not exist")));
}

}  // namespace
}  // namespace slamtune::tune
