// The map a run's trajectory draws with a fixed set of the log's scans: every scan after
// `min_travel_m` of odometric travel or `min_turn_rad` of turning since the previous one, each
// placed at the run's pose for it (slam::LogRunner::Trajectory: a node's pose, any other scan
// the preceding node's pose composed with the odometry since it), drawn by Karto's occupancy
// grid rule (docs/engine.md §8.1) with the laser ranges and cell size of one fixed parameter
// set (the search's base).
//
// Why: the map a run saves is drawn from its nodes only, at its own resolution and ranges, so
// its counts change with the node spacing the search varies: sparser nodes draw fewer wall
// cells and look cleaner while their maps are worse (docs/metrics.md, "Where u_h, n_c and n_e
// fail"). The same scans at the same settings for every run leave only the trajectory to
// differ, so the amount of wall they draw and the share of their end points the map overrules
// compare runs whatever their node spacing.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/occupancy_grid.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::metrics {

struct TrajectoryMapOptions {
  double min_travel_m = 0.10;  // m of odometric travel between drawn scans
  double min_turn_rad = 0.10;  // rad of odometric turning between drawn scans

  // Throws InputError naming the field: both finite and >= 0.
  void Validate() const;
};

class TrajectoryMap {
 public:
  // Chooses the drawn scans from `log`'s odometry; `base` gives the ranges (laser range
  // settings) and the grid (resolution, min_pass_through, occupancy_threshold). Each scan is
  // drawn with its Karto laser (slam::LasersOf: the first scan's, or with --beams per-geometry
  // its beam geometry's); scans whose reading count differs from their laser's are not drawn
  // (the mapper skips them too).
  TrajectoryMap(std::shared_ptr<const io::LaserLog> log, const slam::MapperParams& base,
                const TrajectoryMapOptions& options = {});

  // Log indices of the scans drawn, ascending.
  const std::vector<std::size_t>& scan_indices() const { return indices_; }

  // Draws the chosen scans at the poses of `trajectory` (one sensor pose per log scan, in log
  // order, as LogRunner::Trajectory gives). Checks the trajectory's length.
  slam::OccupancyGrid Draw(std::span<const io::TimedPose> trajectory) const;

 private:
  std::shared_ptr<const io::LaserLog> log_;
  std::shared_ptr<const slam::LogLasers> lasers_;
  slam::OccupancyGridOptions grid_;
  std::vector<std::size_t> indices_;
};

}  // namespace slamtune::metrics
