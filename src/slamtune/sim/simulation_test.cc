#include "slamtune/sim/simulation.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/sim/world_catalog.h"

namespace slamtune::sim {
namespace {

// One simulation per world and seed, shared by the tests of this file.
const Simulation& Cached(const std::string& world, uint64_t seed = 1) {
  static std::map<std::pair<std::string, uint64_t>, Simulation> cache;
  auto it = cache.find({world, seed});
  if (it == cache.end()) {
    SimulationOptions options;
    options.world = world;
    options.seed = seed;
    it = cache.emplace(std::make_pair(world, seed), Simulate(options)).first;
  }
  return it->second;
}

std::string AsCarmen(const Simulation& sim) {
  std::ostringstream out;
  io::WriteCarmenLog(out, sim.log);
  return out.str();
}

TEST(Simulate, DefaultWorldHasAModestSize) {
  const Simulation& sim = Cached("office");
  const SimulationSummary& s = sim.summary;
  EXPECT_EQ(s.world, "office");
  EXPECT_GE(s.scans, 1000u);
  EXPECT_LE(s.scans, 3000u);
  EXPECT_GE(s.path_length_m, 100.0);
  EXPECT_LE(s.path_length_m, 300.0);
  EXPECT_EQ(sim.log.scans.size(), s.scans);
  EXPECT_EQ(sim.truth.size(), s.scans);
  // ODOM every 0.05 m, laser every 0.1 m (0.5 m/s at 5 Hz).
  EXPECT_NEAR(static_cast<double>(s.odometry_records), 2.0 * s.scans, 2.0);
  EXPECT_EQ(s.readings, 181 * s.scans);
}

TEST(Simulate, SameSeedSameBytesDifferentSeedDifferent) {
  SimulationOptions options;
  options.world = "corridor";
  options.seed = 42;
  const Simulation a = Simulate(options), b = Simulate(options);
  options.seed = 43;
  const Simulation c = Simulate(options);
  EXPECT_EQ(AsCarmen(a), AsCarmen(b));
  EXPECT_NE(AsCarmen(a), AsCarmen(c));
  ASSERT_EQ(a.relations.size(), b.relations.size());
  for (std::size_t i = 0; i < a.relations.size(); ++i) EXPECT_EQ(a.relations[i].delta, b.relations[i].delta);
  // The true path is the world's, whatever the seed; only the sensors' noise changes.
  ASSERT_EQ(a.truth.size(), c.truth.size());
  EXPECT_EQ(a.truth.back().pose, c.truth.back().pose);
  EXPECT_NE(a.log.scans.back().laser_pose, c.log.scans.back().laser_pose);
}

TEST(Simulate, TimestampsAreMicrosecondsAtTheLaserRate) {
  const Simulation& sim = Cached("office");
  for (std::size_t k = 0; k < sim.log.scans.size(); ++k) {
    const double t = sim.log.scans[k].ipc_time;
    ASSERT_EQ(t, sim.truth[k].time);
    ASSERT_EQ(t, std::round(t * 1e6) / 1e6);
    if (k > 0) {
      ASSERT_NEAR(t - sim.log.scans[k - 1].ipc_time, 0.2, 1e-6);
    }
  }
  EXPECT_EQ(sim.log.scans.front().ipc_time, 100.0);
}

TEST(Simulate, FlaserPosesAreTheOdometryAtTheScan) {
  const Simulation& sim = Cached("office");
  std::map<double, Pose2> odometry;
  for (const io::OdomRecord& r : sim.log.odometry) odometry[r.ipc_time] = r.pose;
  std::size_t matched = 0;
  for (const io::LaserScanRecord& scan : sim.log.scans) {
    ASSERT_EQ(scan.laser_pose, scan.robot_pose);
    EXPECT_EQ(scan.laser_offset, Pose2{});
    EXPECT_EQ(scan.kind, io::RecordKind::kFlaser);
    EXPECT_DOUBLE_EQ(scan.angle_min, -kPi / 2);
    EXPECT_DOUBLE_EQ(scan.angle_increment, kPi / 180);
    if (auto it = odometry.find(scan.ipc_time); it != odometry.end()) {
      EXPECT_EQ(it->second, scan.laser_pose);
      ++matched;
    }
  }
  EXPECT_EQ(matched, sim.log.scans.size());  // every scan instant is also an ODOM instant
  EXPECT_EQ(sim.log.params.at(kMaxRangeParam), "30");
  EXPECT_EQ(sim.log.no_return_value, 30.0);
}

// With a mounting offset the laser looks from robot (+) offset: the scan's laser pose is its
// odometric robot pose composed with the offset, and the truth is the true laser pose.
TEST(Simulate, LaserOffsetPlacesTheLaserOffTheBase) {
  SimulationOptions options;
  options.world = "corridor";
  options.laser_offset = Pose2{0.3, 0.1, -0.2};
  const Simulation sim = Simulate(options);
  const Simulation& plain = Cached("corridor");
  ASSERT_EQ(sim.log.scans.size(), plain.log.scans.size());
  for (std::size_t k = 0; k < sim.log.scans.size(); ++k) {
    const io::LaserScanRecord& scan = sim.log.scans[k];
    ASSERT_EQ(scan.robot_pose, plain.log.scans[k].robot_pose);  // odometry does not depend on the laser
    const Pose2 expected = Compose(scan.robot_pose, options.laser_offset);
    ASSERT_NEAR(scan.laser_pose.x, expected.x, 1e-11);
    ASSERT_NEAR(scan.laser_pose.y, expected.y, 1e-11);
    ASSERT_NEAR(scan.laser_pose.theta, expected.theta, 1e-11);
    ASSERT_EQ(scan.laser_offset, Between(scan.robot_pose, scan.laser_pose));
  }
  // The scans see the world from the offset laser, not from the base.
  EXPECT_NE(sim.log.scans[10].ranges, plain.log.scans[10].ranges);
  EXPECT_EQ(sim.log.params.at("robot_frontlaser_offset"), "0.3");
  SimulationOptions bad;
  bad.laser_offset = Pose2{0, 0, 4.0};
  EXPECT_THROW(Simulate(bad), InputError);
}

TEST(Simulate, RelationsAreRelativeTruePoses) {
  for (const char* world : {"office", "hall"}) {
    const Simulation& sim = Cached(world);
    std::map<double, Pose2> truth;
    for (const io::TimedPose& p : sim.truth) truth[p.time] = p.pose;
    ASSERT_GT(sim.relations.size(), 100u);
    for (const io::Relation& r : sim.relations) {
      ASSERT_TRUE(truth.count(r.t1) && truth.count(r.t2)) << world;
      const Pose2 expected = Between(truth[r.t1], truth[r.t2]);
      ASSERT_NEAR(r.delta.x, expected.x, 1e-12);
      ASSERT_NEAR(r.delta.y, expected.y, 1e-12);
      ASSERT_NEAR(r.delta.theta, expected.theta, 1e-12);
    }
  }
}

TEST(Simulate, PathRevisitsPlacesLongAfterwards) {
  for (const WorldInfo& world : ListWorlds()) {
    const std::string& info = world.name;
    const Simulation& sim = Cached(info);
    std::size_t far_in_time = 0;
    for (const io::Relation& r : sim.relations) {
      if (r.t2 - r.t1 >= 60.0 && std::hypot(r.delta.x, r.delta.y) <= 1.0) ++far_in_time;
    }
    EXPECT_GE(far_in_time, 20u) << info;
    EXPECT_GE(sim.summary.longest_revisit_gap_s, 150.0) << info;
  }
}

TEST(Simulate, OdometryDriftsMetresOnTheHall) {
  const SimulationSummary& s = Cached("hall").summary;
  EXPECT_GT(s.final_position_error_m, 2.0);
  EXPECT_GT(s.max_position_error_m, 3.0);
  EXPECT_GT(s.max_heading_error_rad, DegToRad(5.0));
  // ... while locally it stays faithful: 2 s relations agree with odometry within centimetres.
  const Simulation& sim = Cached("hall");
  std::map<double, Pose2> odometry;
  for (const io::LaserScanRecord& scan : sim.log.scans) odometry[scan.ipc_time] = scan.laser_pose;
  for (const io::Relation& r : sim.relations) {
    if (r.t2 - r.t1 > 2.5) continue;
    const Pose2 measured = Between(odometry[r.t1], odometry[r.t2]);
    EXPECT_NEAR(measured.x, r.delta.x, 0.1);
    EXPECT_NEAR(measured.y, r.delta.y, 0.1);
  }
}

TEST(Simulate, LaserStreamDoesNotMoveTheOdometry) {
  SimulationOptions options;
  options.world = "corridor";
  const Simulation a = Simulate(options);
  options.laser.beams = 361;
  options.laser.range_noise_m = 0.02;
  const Simulation b = Simulate(options);
  ASSERT_EQ(a.log.odometry.size(), b.log.odometry.size());
  EXPECT_EQ(a.log.odometry.back().pose, b.log.odometry.back().pose);
  EXPECT_EQ(b.log.scans.front().ranges.size(), 361u);
}

// A planted fault changes the odometry only from where it starts: the log before it, the
// true path and the laser readings are those of the world without it, bit for bit.
TEST(Simulate, PlantedFaultActsWhereAndOnlyWhereConfigured) {
  const Simulation& plain = Cached("office");
  const Simulation& faulty = Cached("office-jump");
  ASSERT_EQ(faulty.odometry.faults.size(), 1u);
  const OdometryFault& fault = faulty.odometry.faults[0];
  EXPECT_EQ(fault.kind, OdometryFaultKind::kJump);
  ASSERT_EQ(plain.log.odometry.size(), faulty.log.odometry.size());
  ASSERT_EQ(plain.log.scans.size(), faulty.log.scans.size());
  const double start_time = plain.log.odometry.front().ipc_time;
  std::size_t first_changed = plain.log.odometry.size();
  for (std::size_t i = 0; i < plain.log.odometry.size(); ++i) {
    if (!(plain.log.odometry[i].pose == faulty.log.odometry[i].pose)) {
      first_changed = i;
      break;
    }
  }
  // Travel (0.5 m/s) at the first changed record: just past the fault's start.
  const double travelled = (faulty.log.odometry[first_changed].ipc_time - start_time) * 0.5;
  EXPECT_GT(travelled, fault.start_m);
  EXPECT_LE(travelled, fault.start_m + 0.06);
  // After the fault the odometry is 1 m further along, give or take the noise.
  const Pose2& a = plain.log.odometry.back().pose;
  const Pose2& b = faulty.log.odometry.back().pose;
  EXPECT_NEAR(std::hypot(a.x - b.x, a.y - b.y), fault.magnitude, 0.3);
  for (std::size_t k = 0; k < plain.log.scans.size(); ++k) {
    ASSERT_EQ(plain.truth[k].pose, faulty.truth[k].pose);
    ASSERT_EQ(plain.log.scans[k].ranges, faulty.log.scans[k].ranges);
  }
  EXPECT_EQ(plain.relations.size(), faulty.relations.size());
  EXPECT_TRUE(plain.odometry.faults.empty());
  EXPECT_TRUE(plain.summary.odometry_faults.empty());
  ASSERT_EQ(faulty.summary.odometry_faults.size(), 1u);
  EXPECT_THAT(faulty.summary.Report(), ::testing::HasSubstr("planted odometry fault: jump at 20 m over 0.1 m"));
}

// The healthy twin of a fault world: the world's own faults left out, the user's kept.
TEST(Simulate, WithoutWorldFaultsTheFaultWorldDrivesItsRouteWithPlainOdometry) {
  SimulationOptions options;
  options.world = "office-jump";
  options.plant_world_faults = false;
  const Simulation twin = Simulate(options);
  const Simulation& plain = Cached("office");
  EXPECT_TRUE(twin.odometry.faults.empty());
  EXPECT_TRUE(twin.summary.odometry_faults.empty());
  ASSERT_EQ(twin.log.odometry.size(), plain.log.odometry.size());
  EXPECT_EQ(twin.log.odometry.back().pose, plain.log.odometry.back().pose);
  OdometryFault spin;
  spin.kind = OdometryFaultKind::kSpin;
  spin.start_m = 30.0;
  spin.length_m = 0.1;
  spin.magnitude = 0.5;
  options.odometry.faults = {spin};
  EXPECT_EQ(Simulate(options).odometry.faults.size(), 1u);
}

// The large building runs for at least 15 minutes at the defaults (0.5 m/s, 5 Hz), and its broken
// variant without its planted faults is the building's log, bit for bit.
TEST(Simulate, BuildingRunsFifteenMinutesAndItsBrokenVariantWithoutFaultsIsTheBuilding) {
  const Simulation& building = Cached("building");
  EXPECT_GE(building.summary.duration_s, 15.0 * 60.0);
  EXPECT_GE(building.summary.scans, 4000u);
  EXPECT_LE(building.summary.scans, 4800u);
  EXPECT_TRUE(building.odometry.faults.empty());
  SimulationOptions options;
  options.world = "building-broken";
  options.plant_world_faults = false;
  const Simulation twin = Simulate(options);
  EXPECT_TRUE(twin.odometry.faults.empty());
  EXPECT_EQ(AsCarmen(twin), AsCarmen(building));
  EXPECT_EQ(twin.relations.size(), building.relations.size());
  const Simulation& broken = Cached("building-broken");
  ASSERT_EQ(broken.odometry.faults.size(), 2u);
  EXPECT_NE(AsCarmen(broken), AsCarmen(building));
  ASSERT_EQ(broken.log.scans.size(), building.log.scans.size());
  for (std::size_t k = 0; k < building.log.scans.size(); ++k) {
    ASSERT_EQ(broken.log.scans[k].ranges, building.log.scans[k].ranges);
  }
}

TEST(Simulate, FaultsOfTheOptionsComeBeforeTheWorldsAndAreDeterministic) {
  SimulationOptions options;
  options.world = "office-slip";
  OdometryFault reverse;
  reverse.kind = OdometryFaultKind::kReverse;
  reverse.start_m = 100.0;
  reverse.length_m = 1.0;
  options.odometry.faults = {reverse};
  const Simulation a = Simulate(options), b = Simulate(options);
  ASSERT_EQ(a.odometry.faults.size(), 2u);
  EXPECT_EQ(a.odometry.faults[0].kind, OdometryFaultKind::kReverse);
  EXPECT_EQ(a.odometry.faults[1].kind, OdometryFaultKind::kSpin);
  EXPECT_EQ(AsCarmen(a), AsCarmen(b));
  EXPECT_NE(AsCarmen(a), AsCarmen(Cached("office-slip")));
  // A jump and its opposite cancel exactly: the world's log without its fault.
  options.world = "office-jump";
  OdometryFault undo = Cached("office-jump").odometry.faults[0];
  undo.magnitude = -undo.magnitude;
  options.odometry.faults = {undo};
  EXPECT_EQ(AsCarmen(Simulate(options)), AsCarmen(Cached("office")));
}

TEST(SimulationOptions, ValidateNamesFieldValueAndRule) {
  SimulationOptions options;
  EXPECT_NO_THROW(options.Validate());
  options.world = "moon";
  EXPECT_THAT([&] { options.Validate(); }, ::testing::ThrowsMessage<InputError>(
                                               ::testing::HasSubstr("world = 'moon': must be one of office, hall")));
  options = SimulationOptions();
  options.scan_rate_hz = 0;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("scan_rate_hz = 0: must be in (0, 100]")));
  options = SimulationOptions();
  options.laser.beams = 0;
  EXPECT_THAT([&] { Simulate(options); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("laser beams = 0")));
  options = SimulationOptions();
  options.odometry.faults.resize(2);
  options.odometry.faults[1].length_m = -1.0;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("odometry faults[1] (spin) length_m = -1")));
  options = SimulationOptions();
  options.max_scans = 100;
  EXPECT_THAT([&] { Simulate(options); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("max_scans = 100")));
}

}  // namespace
}  // namespace slamtune::sim
