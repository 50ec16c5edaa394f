// slam_toolbox's pose graph over robot poses (MapperParams::robot_pose_graph) against
// slam_karto's over sensor poses, on a simulated drive with the laser off the base.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <memory>

#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam {
namespace {

std::shared_ptr<const io::LaserLog> Drive(const Pose2& offset, std::size_t scans) {
  sim::SimulationOptions o;
  o.world = "office";
  o.speed_mps = 1.0;
  o.scan_rate_hz = 3.0;
  o.laser_offset = offset;
  io::LaserLog log = sim::Simulate(o).log;
  if (scans > 0 && log.scans.size() > scans) log.scans.resize(scans);
  return std::make_shared<const io::LaserLog>(std::move(log));
}

MapperParams ToolboxParams(bool robot_pose_graph) {
  MapperParams p = MapperParams::Preset("slam_toolbox");
  p.robot_pose_graph = robot_pose_graph;
  return p;
}

// Before the first solve both graphs hold the same matches; each robot-graph edge is the
// sensor-graph edge seen from the robot frames: z = (S1 (-) O) (-) ((S1 (+) z_s) (-) O).
TEST(RobotPoseGraph, EdgesAreTheSensorEdgesExpressedBetweenRobotPoses) {
  const Pose2 offset{0.3, -0.1, 0.2};
  const auto log = Drive(offset, 120);
  MapperParams sensor_params = ToolboxParams(false), robot_params = ToolboxParams(true);
  sensor_params.do_loop_closing = robot_params.do_loop_closing = false;  // no solve: the same poses
  LogRunner sensor(log, sensor_params), robot(log, robot_params);
  sensor.RunToEnd();
  robot.RunToEnd();
  ASSERT_EQ(sensor.mapper().solver_runs().size(), 0u);
  const auto& se = sensor.mapper().graph().edges();
  const auto& re = robot.mapper().graph().edges();
  ASSERT_EQ(se.size(), re.size());
  ASSERT_GT(se.size(), 60u);
  for (std::size_t k = 0; k < se.size(); ++k) {
    ASSERT_EQ(se[k].source, re[k].source);
    ASSERT_EQ(se[k].target, re[k].target);
    const Pose2 s1 = sensor.mapper().scans()[se[k].source].SensorPose();
    const Pose2 predicted = Between(RobotPoseFromSensor(s1, offset),
                                    RobotPoseFromSensor(Compose(s1, se[k].constraint.measurement), offset));
    EXPECT_NEAR(re[k].constraint.measurement.x, predicted.x, 1e-12) << k;
    EXPECT_NEAR(re[k].constraint.measurement.y, predicted.y, 1e-12) << k;
    EXPECT_NEAR(re[k].constraint.measurement.theta, predicted.theta, 1e-12) << k;
    // The lever arm: with the laser off the base the two measurements differ.
    if (se[k].constraint.measurement.theta != 0.0) {
      EXPECT_NE(re[k].constraint.measurement.x, se[k].constraint.measurement.x) << k;
    }
  }
}

TEST(RobotPoseGraph, WholeRunDiffersWithAnOffsetAndIsBitForBitTheSameWithout) {
  const auto off = Drive(Pose2{0.3, -0.1, 0.2}, 0);
  const RunResult a = RunLog(off, ToolboxParams(false)), b = RunLog(off, ToolboxParams(true));
  ASSERT_GE(a.summary.loop_closures.size(), 1u);
  bool differ = false;
  for (std::size_t k = 0; k < a.trajectory.size(); ++k) differ = differ || a.trajectory[k].pose != b.trajectory[k].pose;
  EXPECT_TRUE(differ);

  const auto centred = Drive(Pose2{}, 0);
  const RunResult c = RunLog(centred, ToolboxParams(false)), d = RunLog(centred, ToolboxParams(true));
  ASSERT_GE(c.summary.loop_closures.size(), 1u);
  EXPECT_EQ(c.summary.edges, d.summary.edges);
  ASSERT_EQ(c.trajectory.size(), d.trajectory.size());
  for (std::size_t k = 0; k < c.trajectory.size(); ++k) ASSERT_EQ(c.trajectory[k].pose, d.trajectory[k].pose) << k;
}

}  // namespace
}  // namespace slamtune::slam
