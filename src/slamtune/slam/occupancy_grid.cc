#include "slamtune/slam/occupancy_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

void OccupancyGridOptions::Validate() const {
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    throw InputError(
        fmt::format("occupancy grid option resolution = {}: must be a positive finite number (m)", resolution));
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
  grid.min_pass_through_ = static_cast<std::uint32_t>(options.min_pass_through);
  grid.occupancy_threshold_ = options.occupancy_threshold;
  grid.tiles_x_ = (grid.width_ + kTileMask) >> kTileShift;
  grid.tiles_y_ = (grid.height_ + kTileMask) >> kTileShift;
  grid.tile_of_.assign(static_cast<std::size_t>(grid.tiles_x_) * grid.tiles_y_, nullptr);
  grid.summary_.scans = static_cast<int>(scans.size());
  for (std::size_t i = 0; i < scans.size(); ++i) grid.AddScan(scans[i]);
  grid.Summarise();
  return grid;
}

OccupancyGrid::CellCounts* OccupancyGrid::NewTile() {
  // Value-initialised: every count starts at zero.
  tiles_.push_back(std::make_unique<CellCounts[]>(kTileCells));
  return tiles_.back().get();
}

const OccupancyGrid::CellCounts& OccupancyGrid::counts(int x, int y) const {
  SLAMTUNE_CHECK_MSG(Contains(x, y), "occupancy grid cell out of range");
  static const CellCounts kNone;
  const CellCounts* tile = tile_of_[static_cast<std::size_t>(y >> kTileShift) * tiles_x_ + (x >> kTileShift)];
  return tile == nullptr ? kNone : tile[((y & kTileMask) << kTileShift) | (x & kTileMask)];
}

void OccupancyGrid::TraceBeam(const Eigen::Vector2i& from, const Eigen::Vector2i& to) {
  if (Contains(from.x(), from.y()) && Contains(to.x(), to.y())) {
    // Every traced cell lies in the box of the two ends, hence inside: no per-cell test.
    TraceGridLine(from.x(), from.y(), to.x(), to.y(), [this](int x, int y) { ++MutableCounts(x, y).pass; });
  } else {
    // Cells outside the grid are skipped; tracing goes on (§8.1).
    TraceGridLine(from.x(), from.y(), to.x(), to.y(), [this](int x, int y) {
      if (Contains(x, y)) ++MutableCounts(x, y).pass;
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
        CellCounts& end_cell = MutableCounts(to.x(), to.y());
        ++end_cell.pass;
        ++end_cell.hit;
        ++summary_.hits;
      } else {
        ++summary_.hits_outside;
      }
    }
  }
}

CellState OccupancyGrid::StateOf(const CellCounts& c) const {
  // §8.1: strictly more than MinPassThrough passes, then hit/pass strictly above the threshold.
  if (c.pass <= min_pass_through_) return CellState::kUnknown;
  const double ratio = static_cast<double>(c.hit) / static_cast<double>(c.pass);
  return ratio > occupancy_threshold_ ? CellState::kOccupied : CellState::kFree;
}

void OccupancyGrid::Summarise() {
  // Cells of unreached tiles, and the cells of edge tiles beyond the grid, have no counts:
  // unknown without hits. Only the known classes need counting.
  for (const Tile& tile : tiles_) {
    for (std::size_t i = 0; i < kTileCells; ++i) {
      const CellCounts& c = tile[i];
      switch (StateOf(c)) {
        case CellState::kOccupied: ++summary_.occupied_cells; break;
        case CellState::kFree:
          ++summary_.free_cells;
          summary_.hits_in_free_cells += c.hit;
          break;
        case CellState::kUnknown: summary_.hits_in_unknown_cells += c.hit; break;
      }
    }
  }
  summary_.unknown_cells = static_cast<std::int64_t>(width_) * height_ - summary_.occupied_cells - summary_.free_cells;
}

io::MapImage OccupancyGrid::ToMapImage() const {
  io::MapImage image;
  image.width = width_;
  image.height = height_;
  image.resolution = resolution_;
  image.origin = {origin_.x(), origin_.y(), 0.0};
  image.pixels.assign(static_cast<std::size_t>(width_) * height_, io::kMapUnknown);
  for (int ty = 0; ty < tiles_y_; ++ty) {
    for (int tx = 0; tx < tiles_x_; ++tx) {
      const CellCounts* tile = tile_of_[static_cast<std::size_t>(ty) * tiles_x_ + tx];
      if (tile == nullptr) continue;
      const int x0 = tx << kTileShift, y0 = ty << kTileShift;
      const int x1 = std::min(width_, x0 + kTileSide), y1 = std::min(height_, y0 + kTileSide);
      for (int y = y0; y < y1; ++y) {
        // Image row 0 is the map's top row (map_saver flips y, §8.3).
        std::uint8_t* row = image.pixels.data() + static_cast<std::size_t>(height_ - 1 - y) * width_;
        const CellCounts* counts = tile + (static_cast<std::size_t>(y & kTileMask) << kTileShift);
        for (int x = x0; x < x1; ++x) {
          switch (StateOf(counts[x & kTileMask])) {
            case CellState::kOccupied: row[x] = io::kMapOccupied; break;
            case CellState::kFree: row[x] = io::kMapFree; break;
            case CellState::kUnknown: break;
          }
        }
      }
    }
  }
  return image;
}

}  // namespace slamtune::slam
