// Ray casting against 2D line-segment walls, accelerated by a uniform grid.
//
// The simulated laser casts ~181 rays per scan for a few thousand scans, so each ray must be
// cheap. Every segment is listed in each grid cell it crosses; a ray walks the cells it
// passes through in order (Amanatides & Woo 1987, "A fast voxel traversal algorithm for ray
// tracing", Eurographics) and stops at the first cell whose exit lies beyond the nearest hit
// found so far. The result is the exact nearest intersection, the same as testing every wall.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <optional>
#include <vector>

namespace slamtune::sim {

// A wall: the closed segment from a to b (metres, world frame).
struct Segment {
  Eigen::Vector2d a{0, 0};
  Eigen::Vector2d b{0, 0};
};

// Distance t >= 0 along the unit ray origin + t * direction to `segment`, if they meet.
// Rays parallel to the segment (including collinear ones) do not hit it: a wall seen exactly
// edge-on has no area to reflect from.
std::optional<double> IntersectRay(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                                   const Segment& segment);

class RayCaster {
 public:
  // `cell_size` (m, > 0) trades memory for work per cell; about the length of a short wall.
  explicit RayCaster(std::vector<Segment> segments, double cell_size = 1.0);

  // Distance from `origin` to the nearest wall along heading `angle` (rad, world frame), or
  // nullopt when no wall lies within `max_range` (m).
  std::optional<double> Cast(const Eigen::Vector2d& origin, double angle, double max_range) const;

  const std::vector<Segment>& segments() const { return segments_; }
  int cells_x() const { return nx_; }
  int cells_y() const { return ny_; }

 private:
  std::vector<Segment> segments_;
  double cell_size_;
  Eigen::Vector2d min_{0, 0};  // lower-left corner of the grid
  int nx_ = 0;
  int ny_ = 0;
  // Compressed cell lists: segments of cell c are cell_items_[cell_start_[c] .. cell_start_[c+1]).
  std::vector<std::size_t> cell_start_;
  std::vector<int> cell_items_;
};

}  // namespace slamtune::sim
