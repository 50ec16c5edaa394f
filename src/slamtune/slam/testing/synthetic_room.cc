#include "slamtune/slam/testing/synthetic_room.h"

#include <cmath>
#include <limits>

namespace slamtune::slam::testing {
namespace {

void AddBox(std::vector<WallSegment>* walls, double x0, double y0, double x1, double y1) {
  walls->push_back({{x0, y0}, {x1, y0}});
  walls->push_back({{x1, y0}, {x1, y1}});
  walls->push_back({{x1, y1}, {x0, y1}});
  walls->push_back({{x0, y1}, {x0, y0}});
}

// Distance along the ray o + t d (|d| = 1) to segment ab, or +inf.
double RayHit(const Eigen::Vector2d& o, const Eigen::Vector2d& d, const WallSegment& s) {
  const Eigen::Vector2d e = s.b - s.a;
  const double denom = d.x() * e.y() - d.y() * e.x();
  if (std::fabs(denom) < 1e-12) return std::numeric_limits<double>::infinity();
  const Eigen::Vector2d w = s.a - o;
  const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
  const double u = (w.x() * d.y() - w.y() * d.x()) / denom;
  if (t <= 1e-9 || u < 0.0 || u > 1.0) return std::numeric_limits<double>::infinity();
  return t;
}

}  // namespace

std::vector<WallSegment> AsymmetricRoom() {
  std::vector<WallSegment> walls;
  AddBox(&walls, 0.0, 0.0, 10.0, 8.0);        // outer walls
  walls.push_back({{6.0, 0.0}, {6.0, 3.5}});  // inner wall from the bottom
  AddBox(&walls, 2.0, 5.0, 3.2, 5.6);         // box
  AddBox(&walls, 7.5, 5.5, 8.1, 6.9);         // box
  AddBox(&walls, 3.9, 2.0, 4.2, 2.3);         // pillar
  walls.push_back({{0.0, 6.5}, {1.2, 8.0}});  // slanted corner
  return walls;
}

std::shared_ptr<const LaserGeometry> CarmenLikeLaser(int beams) {
  auto g = std::make_shared<LaserGeometry>();
  g->min_angle = -kPi / 2;
  g->angular_resolution = kPi / beams;
  g->num_readings = beams;
  g->min_range = 0.0;
  g->max_range = 81.83;
  g->range_threshold = 12.0;
  return g;
}

LaserScan CastScan(const std::vector<WallSegment>& walls, const std::shared_ptr<const LaserGeometry>& laser,
                   const Pose2& sensor_pose, double no_return) {
  auto ranges = std::make_shared<std::vector<double>>(static_cast<std::size_t>(laser->num_readings));
  const Eigen::Vector2d o(sensor_pose.x, sensor_pose.y);
  for (int i = 0; i < laser->num_readings; ++i) {
    const double a = sensor_pose.theta + laser->min_angle + i * laser->angular_resolution;
    const Eigen::Vector2d d(std::cos(a), std::sin(a));
    double best = std::numeric_limits<double>::infinity();
    for (const WallSegment& s : walls) best = std::min(best, RayHit(o, d, s));
    (*ranges)[static_cast<std::size_t>(i)] = std::isfinite(best) ? best : no_return;
  }
  return LaserScan(laser, std::move(ranges), sensor_pose, 0.0);
}

LaserScan AsymmetricRoomScan(const Pose2& sensor_pose) {
  static const std::vector<WallSegment> room = AsymmetricRoom();
  static const std::shared_ptr<const LaserGeometry> laser = CarmenLikeLaser();
  return CastScan(room, laser, sensor_pose);
}

}  // namespace slamtune::slam::testing
