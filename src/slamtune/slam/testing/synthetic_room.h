// Test helpers of the scan matcher and the occupancy grid: a small indoor world made of wall
// segments, a CARMEN-like 180-beam laser, and exact ray-cast scans at chosen poses, so that a
// test knows the true pose of every scan.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam::testing {

struct WallSegment {
  Eigen::Vector2d a;
  Eigen::Vector2d b;
};

// A 10 m x 8 m room (corner at the origin) with an inner wall, two boxes and a pillar, so
// that no pose is ambiguous.
std::vector<WallSegment> AsymmetricRoom();

// `beams` beams over 180 degrees starting at -90 degrees (1 degree steps for 180 beams), the
// CARMEN FLASER convention; max_range 81.83 (intel's no-return value), threshold 12 m.
std::shared_ptr<const LaserGeometry> CarmenLikeLaser(int beams = 180);

// Ray-casts a scan at `sensor_pose` (zero laser offset, so it is also the robot pose): each
// reading is the distance to the nearest wall, or `no_return` when no wall is hit.
LaserScan CastScan(const std::vector<WallSegment>& walls, const std::shared_ptr<const LaserGeometry>& laser,
                   const Pose2& sensor_pose, double no_return = 81.83);

// CastScan() in AsymmetricRoom() with CarmenLikeLaser(), the scene most matcher tests use. All
// these scans share one geometry object, as the scans of one laser do.
LaserScan AsymmetricRoomScan(const Pose2& sensor_pose);

}  // namespace slamtune::slam::testing
