#include "slamtune/sim/simulation_files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/carmen/carmen_reader.h"

namespace slamtune::sim {
namespace {

namespace fs = std::filesystem;

class SimulationFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("slamtune_sim_files_" + std::to_string(getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  static std::string Slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
  }

  fs::path dir_;
};

TEST_F(SimulationFilesTest, WritesThreeFilesThatReadBackAsSimulated) {
  SimulationOptions options;  // office, seed 1, SICK-like laser
  const Simulation sim = Simulate(options);
  const SimulationFiles files = WriteSimulation((dir_ / "out").string(), sim, options);
  EXPECT_EQ(files.log, (dir_ / "out" / "office.clf").string());
  EXPECT_EQ(files.relations, (dir_ / "out" / "office.relations").string());
  EXPECT_EQ(files.truth, (dir_ / "out" / "office.truth.txt").string());

  // The log, through the project's reader: same scans, 181 readings at 1 degree from -90.
  const io::LaserLog log = io::ReadCarmenLog(files.log);
  ASSERT_EQ(log.scans.size(), sim.log.scans.size());
  EXPECT_EQ(log.odometry.size(), sim.log.odometry.size());
  EXPECT_EQ(log.record_counts.at("FLASER"), sim.log.scans.size());
  EXPECT_EQ(log.no_return_rule, "PARAM laser_front_laser_max_range");
  EXPECT_EQ(log.no_return_value, 30.0);
  EXPECT_EQ(log.time_backward_steps, 0u);
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    const io::LaserScanRecord &read = log.scans[k], &made = sim.log.scans[k];
    ASSERT_EQ(read.ranges.size(), 181u);
    ASSERT_EQ(read.ranges, made.ranges) << "scan " << k;
    ASSERT_EQ(read.ipc_time, made.ipc_time);
    ASSERT_DOUBLE_EQ(read.angle_min, -kPi / 2);
    ASSERT_DOUBLE_EQ(read.angle_increment, DegToRad(1.0));
    ASSERT_EQ(read.laser_pose, made.laser_pose);  // the in-memory log is the file's, exactly
    ASSERT_EQ(read.robot_pose, made.robot_pose);
    ASSERT_EQ(read.logger_time, made.logger_time);
    ASSERT_EQ(read.no_returns, made.no_returns);
  }
  for (std::size_t j = 0; j < log.odometry.size(); ++j) {
    const io::OdomRecord &read = log.odometry[j], &made = sim.log.odometry[j];
    ASSERT_EQ(read.pose, made.pose);
    ASSERT_EQ(read.ipc_time, made.ipc_time);
    ASSERT_EQ(read.tv, made.tv);
    ASSERT_EQ(read.rv, made.rv);
  }
  EXPECT_EQ(log.total_readings, sim.log.total_readings);
  EXPECT_EQ(log.total_no_returns, sim.log.total_no_returns);

  // Relations: timestamps name scans exactly; deltas are exact.
  std::set<double> scan_times;
  for (const auto& scan : log.scans) scan_times.insert(scan.ipc_time);
  const auto relations = io::ReadRelations(files.relations);
  ASSERT_EQ(relations.size(), sim.relations.size());
  for (std::size_t i = 0; i < relations.size(); ++i) {
    ASSERT_TRUE(scan_times.count(relations[i].t1) && scan_times.count(relations[i].t2)) << "relation " << i;
    ASSERT_EQ(relations[i].delta, sim.relations[i].delta);
  }

  // Truth: one true laser pose per scan, at the scan's time.
  const auto truth = io::ReadTrajectory(files.truth);
  ASSERT_EQ(truth.size(), log.scans.size());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    ASSERT_EQ(truth[k].time, log.scans[k].ipc_time);
    ASSERT_NEAR(truth[k].pose.x, sim.truth[k].pose.x, 1e-6);
    ASSERT_NEAR(truth[k].pose.theta, sim.truth[k].pose.theta, 1e-8);
  }

  // The header says what was simulated and names the no-return PARAM.
  const std::string text = Slurp(files.log);
  EXPECT_THAT(text, ::testing::HasSubstr("# simulated by slamtune: world office (seed 1)"));
  EXPECT_THAT(text, ::testing::HasSubstr("\nPARAM laser_front_laser_max_range 30 slamtune 0\n"));
}

TEST_F(SimulationFilesTest, SameSeedSameBytes) {
  SimulationOptions options;
  options.world = "hall";
  options.seed = 5;
  WriteSimulation((dir_ / "a").string(), Simulate(options), options);
  WriteSimulation((dir_ / "b").string(), Simulate(options), options);
  options.seed = 6;
  WriteSimulation((dir_ / "c").string(), Simulate(options), options);
  for (const char* name : {"hall.clf", "hall.relations", "hall.truth.txt"}) {
    EXPECT_EQ(Slurp((dir_ / "a" / name).string()), Slurp((dir_ / "b" / name).string())) << name;
  }
  EXPECT_NE(Slurp((dir_ / "a" / "hall.clf").string()), Slurp((dir_ / "c" / "hall.clf").string()));
  // The truth does not depend on the seed; the relations neither.
  EXPECT_EQ(Slurp((dir_ / "a" / "hall.truth.txt").string()), Slurp((dir_ / "c" / "hall.truth.txt").string()));
}

TEST_F(SimulationFilesTest, WideLaserIsWrittenAsRobotLaser1) {
  SimulationOptions options;
  options.world = "corridor";
  options.laser.fov_deg = 270.0;
  options.laser.beams = 541;
  options.laser.max_range_m = 20.0;
  const Simulation sim = Simulate(options);
  const SimulationFiles files = WriteSimulation(dir_.string(), sim, options);
  const io::LaserLog log = io::ReadCarmenLog(files.log);
  ASSERT_EQ(log.scans.size(), sim.log.scans.size());
  EXPECT_EQ(log.record_counts.at("ROBOTLASER1"), sim.log.scans.size());
  EXPECT_EQ(log.no_return_value, 20.0);
  const io::LaserScanRecord& scan = log.scans.front();
  EXPECT_EQ(scan.ranges.size(), 541u);
  EXPECT_DOUBLE_EQ(scan.angle_min, -DegToRad(135.0));
  EXPECT_DOUBLE_EQ(scan.angle_increment, DegToRad(0.5));
  EXPECT_EQ(scan.ranges, sim.log.scans.front().ranges);
}

// A ROS-like robot: laser mounted off the base, float32 values, 1/512 m readings. The log holds
// both poses and the offset PARAMs, and every value reads back bit for bit.
TEST_F(SimulationFilesTest, OffsetFloat32LaserReadsBackBitForBit) {
  SimulationOptions options;
  options.speed_mps = 1.0;
  options.scan_rate_hz = 3.0;
  options.laser_offset = Pose2{0.12, -0.04, 0.05};
  options.laser.float32_values = true;
  options.laser.range_resolution_m = 1.0 / 512;
  const Simulation sim = Simulate(options);
  const SimulationFiles files = WriteSimulation(dir_.string(), sim, options);
  const io::LaserLog log = io::ReadCarmenLog(files.log);
  ASSERT_EQ(log.scans.size(), sim.log.scans.size());
  EXPECT_EQ(log.record_counts.at("ROBOTLASER1"), sim.log.scans.size());  // float32 angles are not FLASER's
  EXPECT_EQ(log.params.at("robot_frontlaser_offset"), "0.12");
  EXPECT_EQ(log.params.at("robot_frontlaser_side_offset"), "-0.04");
  EXPECT_EQ(log.params.at("robot_frontlaser_angular_offset"), "0.05");
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    const io::LaserScanRecord &read = log.scans[k], &made = sim.log.scans[k];
    ASSERT_EQ(read.ranges, made.ranges) << "scan " << k;
    ASSERT_EQ(read.laser_pose, made.laser_pose) << "scan " << k;
    ASSERT_EQ(read.robot_pose, made.robot_pose) << "scan " << k;
    ASSERT_EQ(read.laser_offset, made.laser_offset) << "scan " << k;
    ASSERT_EQ(read.angle_min, made.angle_min);
    ASSERT_EQ(read.angle_increment, made.angle_increment);
    for (double r : read.ranges) ASSERT_EQ(r, static_cast<double>(static_cast<float>(r)));
    ASSERT_NEAR(read.laser_offset.x, 0.12, 1e-9);
    ASSERT_NEAR(read.laser_offset.y, -0.04, 1e-9);
    ASSERT_NEAR(read.laser_offset.theta, 0.05, 1e-9);
  }
  EXPECT_EQ(log.scans.front().angle_min, static_cast<double>(static_cast<float>(-kPi / 2)));
}

TEST_F(SimulationFilesTest, UnwritableFolderIsAnInputError) {
  std::ofstream(dir_.string() + "_file") << "x";  // a file where the folder should go
  SimulationOptions options;
  options.world = "corridor";
  EXPECT_THROW(WriteSimulation(dir_.string() + "_file", Simulate(options), options), InputError);
  fs::remove(dir_.string() + "_file");
}

}  // namespace
}  // namespace slamtune::sim
