#include "slamtune/slam/occupancy_grid.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

void OccupancyGridOptions::Validate() const {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw InputError(fmt::format("occupancy grid option resolution = {}: must be a positive finite number (m)",
                                 resolution));
  }
  if (min_pass_through < 0) {
    throw InputError(fmt::format("occupancy grid option min_pass_through = {}: must be >= 0", min_pass_through));
  }
  if (!(occupancy_threshold >= 0.0 && occupancy_threshold <= 1.0)) {
    throw InputError(
        fmt::format("occupancy grid option occupancy_threshold = {}: must lie in [0, 1]", occupancy_threshold));
  }
  if (max_cells < 1) throw InputError(fmt::format("occupancy grid option max_cells = {}: must be >= 1", max_cells));
}

Eigen::Vector2i OccupancyGrid::WorldToGrid(const Eigen::Vector2d& world) const {
  return {KartoRoundToInt((world.x() - origin_.x()) * scale_), KartoRoundToInt((world.y() - origin_.y()) * scale_)};
}

OccupancyGrid OccupancyGrid::FromScans(std::span<const LaserScan* const> scans, const OccupancyGridOptions& options) {
  for (const LaserScan* s : scans) SLAMTUNE_CHECK(s != nullptr);
  struct Deref {
    std::span<const LaserScan* const> s;
    std::size_t size() const { return s.size(); }
    const LaserScan& operator[](std::size_t i) const { return *s[i]; }
  };
  return Build(Deref{scans}, options);
}

OccupancyGrid OccupancyGrid::FromScans(std::span<const LaserScan> scans, const OccupancyGridOptions& options) {
  return Build(scans, options);
}

template <typename ScanRange>
OccupancyGrid OccupancyGrid::Build(const ScanRange& scans, const OccupancyGridOptions& options) {
  options.Validate();
  OccupancyGrid grid;
  grid.resolution_ = options.resolution;
  grid.scale_ = 1.0 / options.resolution;
  if (scans.size() == 0) return grid;

  // Extent (§8.1): union of the scans' boxes; Round(size * scale) cells per axis.
  Eigen::Vector2d box_min = Eigen::Vector2d::Constant(std::numeric_limits<double>::max());
  Eigen::Vector2d box_max = Eigen::Vector2d::Constant(-std::numeric_limits<double>::max());
  for (std::size_t i = 0; i < scans.size(); ++i) {
    box_min = box_min.cwiseMin(scans[i].bounding_box().min);
    box_max = box_max.cwiseMax(scans[i].bounding_box().max);
  }
  const double width = KartoRound((box_max.x() - box_min.x()) * grid.scale_);
  const double height = KartoRound((box_max.y() - box_min.y()) * grid.scale_);
  if (!(width * height <= static_cast<double>(options.max_cells))) {
    throw InputError(fmt::format(
        "occupancy grid of {} x {} cells ({:.1f} m x {:.1f} m at {} m) exceeds max_cells = {}; the trajectory "
        "has probably diverged",
        width, height, box_max.x() - box_min.x(), box_max.y() - box_min.y(), options.resolution, options.max_cells));
  }
  grid.width_ = static_cast<int>(width);
  grid.height_ = static_cast<int>(height);
  grid.origin_ = box_min;
  const std::size_t cells = static_cast<std::size_t>(grid.width_) * grid.height_;
  grid.pass_.assign(cells, 0);
  grid.hit_.assign(cells, 0);
  grid.summary_.scans = static_cast<int>(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) grid.AddScan(scans[i]);
  grid.UpdateStates(options);
  return grid;
}

void OccupancyGrid::TraceBeam(const Eigen::Vector2i& from, const Eigen::Vector2i& to) {
  std::uint32_t* pass = pass_.data();
  if (Contains(from.x(), from.y()) && Contains(to.x(), to.y())) {
    // Every traced cell lies in the box of the two ends, hence inside: no per-cell test.
    const int w = width_;
    TraceGridLine(from.x(), from.y(), to.x(), to.y(),
                  [pass, w](int x, int y) { ++pass[static_cast<std::size_t>(y) * w + x]; });
  } else {
    // Cells outside the grid are skipped; tracing goes on (§8.1).
    TraceGridLine(from.x(), from.y(), to.x(), to.y(), [this, pass](int x, int y) {
      if (Contains(x, y)) ++pass[Index(x, y)];
    });
  }
}

void OccupancyGrid::AddScan(const LaserScan& scan) {
  const LaserGeometry& g = scan.geometry();
  const Pose2 sensor = scan.SensorPose();
  const Eigen::Vector2d position(sensor.x, sensor.y);
  const Eigen::Vector2i from = WorldToGrid(position);
  const std::vector<double>& ranges = scan.ranges();
  const std::vector<Eigen::Vector2d>& points = scan.unfiltered_points();
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const double r = ranges[i];
    // §8.1 skip rules: below/at minRange, at/above maxRange (so +inf), NaN.
    if (r <= g.min_range || r >= g.max_range || std::isnan(r)) {
      ++summary_.beams_skipped;
      continue;
    }
    const bool end_valid = r < (g.range_threshold - kKartoTolerance);
    Eigen::Vector2d end = points[i];
    if (r >= g.range_threshold) {
      // Shorten to the threshold along the beam, as Karto does: s + (Rt / r) (p - s).
      const double ratio = g.range_threshold / r;
      end = {position.x() + ratio * (end.x() - position.x()), position.y() + ratio * (end.y() - position.y())};
      ++summary_.beams_shortened;
    }
    const Eigen::Vector2i to = WorldToGrid(end);
    TraceBeam(from, to);
    ++summary_.beams_traced;
    if (end_valid) {
      if (Contains(to.x(), to.y())) {
        // The end cell was passed by the trace too: a hit cell gets pass +2, hit +1.
        ++pass_[Index(to.x(), to.y())];
        ++hit_[Index(to.x(), to.y())];
        ++summary_.hits;
      } else {
        ++summary_.hits_outside;
      }
    }
  }
}

void OccupancyGrid::UpdateStates(const OccupancyGridOptions& options) {
  states_.assign(pass_.size(), CellState::kUnknown);
  const std::uint32_t min_pass = static_cast<std::uint32_t>(options.min_pass_through);
  for (std::size_t i = 0; i < pass_.size(); ++i) {
    // §8.1: strictly more than MinPassThrough passes, then hit/pass strictly above the threshold.
    if (pass_[i] > min_pass) {
      const double ratio = static_cast<double>(hit_[i]) / static_cast<double>(pass_[i]);
      if (ratio > options.occupancy_threshold) {
        states_[i] = CellState::kOccupied;
        ++summary_.occupied_cells;
      } else {
        states_[i] = CellState::kFree;
        ++summary_.free_cells;
        summary_.hits_in_free_cells += hit_[i];
      }
    } else {
      ++summary_.unknown_cells;
      summary_.hits_in_unknown_cells += hit_[i];
    }
  }
}

io::MapImage OccupancyGrid::ToMapImage() const {
  io::MapImage image;
  image.width = width_;
  image.height = height_;
  image.resolution = resolution_;
  image.origin = {origin_.x(), origin_.y(), 0.0};
  image.pixels.resize(states_.size());
  for (int y = 0; y < height_; ++y) {
    // Image row 0 is the map's top row (map_saver flips y, §8.3).
    std::uint8_t* row = image.pixels.data() + static_cast<std::size_t>(height_ - 1 - y) * width_;
    for (int x = 0; x < width_; ++x) {
      switch (states_[Index(x, y)]) {
        case CellState::kOccupied: row[x] = io::kMapOccupied; break;
        case CellState::kFree: row[x] = io::kMapFree; break;
        case CellState::kUnknown: row[x] = io::kMapUnknown; break;
      }
    }
  }
  return image;
}

}  // namespace slamtune::slam
