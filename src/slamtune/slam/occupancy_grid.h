// Karto's occupancy grid (docs/engine.md §8.1-§8.3): the map a slam_karto / slam_toolbox
// user would save, computed once from the final scan poses. Every beam is traced from the
// sensor cell to its end cell with Karto's integer line variant, counting passes; end points
// closer than the range threshold also count a hit (a hit cell gets pass +2, hit +1). A cell
// is known once it has more than MinPassThrough passes, and occupied when hit/pass exceeds
// OccupancyThreshold. The map metrics read the result through io::MapImage (occupied 0,
// free 254, unknown 205, image row 0 = top row), exactly the pixels map_saver would write.
//
// Speed matters (one map per SLAM run, thousands of runs per optimisation): counts are kept
// in 64 x 64-cell tiles allocated when a beam first reaches them, so a map whose box is
// mostly never seen (a long building, a broken trajectory) costs the cells its beams cross,
// not its area; lines whose two ends are inside the grid are traced without per-cell bounds
// checks, and nothing is allocated per beam. Cells of tiles no beam reached have no passes:
// unknown, as Karto's zero counts make them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "slamtune/io/map_image.h"
#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam {

struct OccupancyGridOptions {
  double resolution = 0.05;          // m per cell (slam_karto / slam_toolbox `resolution`)
  int min_pass_through = 2;          // a cell is known only with strictly more passes than this
  double occupancy_threshold = 0.1;  // known cell is occupied iff hit/pass > this, else free
  // Refuse maps larger than this many cells (a diverged trajectory would otherwise try to
  // allocate gigabytes); 1e8 cells is 500 m x 500 m at 5 cm.
  std::int64_t max_cells = 100'000'000;

  // Throws InputError naming the field: resolution must be finite and > 0, min_pass_through
  // >= 0, occupancy_threshold in [0, 1], max_cells >= 1.
  void Validate() const;
};

// Karto's internal cell codes (§1.1).
enum class CellState : std::uint8_t { kUnknown = 0, kOccupied = 100, kFree = 255 };

// What building the map did, and why cells ended as they did.
struct OccupancyGridSummary {
  int scans = 0;
  std::int64_t beams_traced = 0;     // beams drawn (possibly shortened)
  std::int64_t beams_skipped = 0;    // r <= minRange, r >= maxRange or NaN: not drawn (§8.1)
  std::int64_t beams_shortened = 0;  // r >= rangeThreshold: drawn up to the threshold, no hit
  std::int64_t hits = 0;             // end points counted as hits
  std::int64_t hits_outside = 0;     // valid end points outside the grid (max-edge quirk, §8.1)
  std::int64_t occupied_cells = 0;
  std::int64_t free_cells = 0;
  std::int64_t unknown_cells = 0;
  // End points the map contradicts: hits counted in cells that end free (more beams passed
  // through them than the occupancy threshold allows a wall) or unknown. In a consistent map
  // almost every hit lands on a wall; where a broken trajectory draws one wall into the free
  // space another pass saw, its hits are overruled, whatever the map's extent.
  std::int64_t hits_in_free_cells = 0;
  std::int64_t hits_in_unknown_cells = 0;
};

// Visits the cells of Karto's line tracing between two grid cells (§8.1): if |dy| > |dx| the
// axes swap, the ends are ordered so the major coordinate increases, and the k-th cell
// (k = 0 .. dx) is (x0 + k, y0 + step floor((2k dy + dx) / (2 dx))), swapped back if steep.
// `visit(x, y)` is called once per cell, start and end included.
template <typename Visit>
void TraceGridLine(int x0, int y0, int x1, int y1, Visit&& visit) {
  const bool steep = std::abs(y1 - y0) > std::abs(x1 - x0);
  if (steep) {
    std::swap(x0, y0);
    std::swap(x1, y1);
  }
  if (x0 > x1) {
    std::swap(x0, x1);
    std::swap(y0, y1);
  }
  const int dx = x1 - x0;
  const int dy = std::abs(y1 - y0);
  const int step = y0 < y1 ? 1 : -1;
  // remainder = (2k dy + dx) mod 2dx, kept incrementally; dy <= dx, so the minor coordinate
  // advances at most once per step.
  int remainder = dx;
  int y = y0;
  for (int x = x0; x <= x1; ++x) {
    if (steep) {
      visit(y, x);
    } else {
      visit(x, y);
    }
    remainder += 2 * dy;
    if (remainder >= 2 * dx) {
      remainder -= 2 * dx;
      y += step;
    }
  }
}

class OccupancyGrid {
 public:
  // §8.1 CreateFromScans: extent = union of the scans' bounding boxes (sensor position and
  // filtered points at their current poses), width/height = Round(size / resolution), origin
  // = box minimum; then every scan in order. No scans gives an empty 0 x 0 grid. Throws
  // InputError for invalid options or a map larger than options.max_cells.
  static OccupancyGrid FromScans(std::span<const LaserScan* const> scans, const OccupancyGridOptions& options);
  static OccupancyGrid FromScans(std::span<const LaserScan> scans, const OccupancyGridOptions& options);

  int width() const { return width_; }
  int height() const { return height_; }
  double resolution() const { return resolution_; }
  // World position of cell (0, 0)'s centre: the box minimum corner.
  const Eigen::Vector2d& origin() const { return origin_; }
  // Round((w - origin) / resolution) per axis, as a multiplication by 1/resolution (§1.2).
  Eigen::Vector2i WorldToGrid(const Eigen::Vector2d& world) const;
  bool Contains(int x, int y) const { return x >= 0 && x < width_ && y >= 0 && y < height_; }

  CellState state(int x, int y) const { return StateOf(counts(x, y)); }
  std::uint32_t pass_count(int x, int y) const { return counts(x, y).pass; }
  std::uint32_t hit_count(int x, int y) const { return counts(x, y).hit; }
  const OccupancyGridSummary& summary() const { return summary_; }
  // Tiles some beam reached: the cells stored are 4096 times this (tests check that the tiles
  // no beam reached are not stored).
  int allocated_tiles() const { return static_cast<int>(tiles_.size()); }

  // The map as map_saver writes it (§8.3): occupied 0, free 254, unknown 205; image row 0 is
  // map row height-1; origin (box min x, box min y, 0); resolution as built.
  io::MapImage ToMapImage() const;

 private:
  struct CellCounts {
    std::uint32_t pass = 0;
    std::uint32_t hit = 0;
  };
  static constexpr int kTileShift = 6;  // tiles of 64 x 64 cells (32 KB of counts)
  static constexpr int kTileSide = 1 << kTileShift;
  static constexpr int kTileMask = kTileSide - 1;
  static constexpr std::size_t kTileCells = static_cast<std::size_t>(kTileSide) * kTileSide;
  using Tile = std::unique_ptr<CellCounts[]>;

  OccupancyGrid() = default;
  template <typename ScanRange>
  static OccupancyGrid Build(const ScanRange& scans, const OccupancyGridOptions& options);
  void AddScan(const LaserScan& scan);
  void TraceBeam(const Eigen::Vector2i& from, const Eigen::Vector2i& to);
  void Summarise();
  CellState StateOf(const CellCounts& c) const;
  // Counts of an in-grid cell, allocating its tile on first use.
  CellCounts& MutableCounts(int x, int y) {
    CellCounts*& tile = tile_of_[static_cast<std::size_t>(y >> kTileShift) * tiles_x_ + (x >> kTileShift)];
    if (tile == nullptr) tile = NewTile();
    return tile[((y & kTileMask) << kTileShift) | (x & kTileMask)];
  }
  // Counts of an in-grid cell (checked); zero in a tile no beam reached.
  const CellCounts& counts(int x, int y) const;
  CellCounts* NewTile();

  int width_ = 0;
  int height_ = 0;
  double resolution_ = 0.05;
  double scale_ = 20.0;
  Eigen::Vector2d origin_{0, 0};
  std::uint32_t min_pass_through_ = 2;
  double occupancy_threshold_ = 0.1;
  int tiles_x_ = 0;
  int tiles_y_ = 0;
  // Row-major over tiles; null where no beam has reached. The tiles themselves are owned by
  // tiles_ (in allocation order) so that moving the grid keeps every pointer valid.
  std::vector<CellCounts*> tile_of_;
  std::vector<Tile> tiles_;
  OccupancyGridSummary summary_;
};

}  // namespace slamtune::slam
