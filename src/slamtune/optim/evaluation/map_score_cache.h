// Map scores shared by the SLAM runs of one evaluation context: runs whose loop-closure
// decisions coincide end in bit-identical final poses, so their maps, map metrics and
// ground-truth errors are the same. After its SLAM run, an evaluation looks its final state up
// here; on a hit it skips the occupancy grid (Karto's ray tracing of every reading, §8), the
// three metrics and the relation errors, which together cost about half of a run whose scan
// matches were all served by the MatchCache.
//
// Exactness, as in slam/sharing/match_cache.h: an entry is keyed by everything the scores depend on,
// compared word for word (the hash only picks the bucket): the occupancy-grid options
// (resolution, min_pass_through, occupancy_threshold), the bits of the laser geometry (angles,
// min/max range, range threshold, offset), and for each processed scan its log index and the
// bits of its corrected pose. The map is built from exactly these (§8), and the trajectory of
// every log scan from these and the log's odometry (slam/log_runner.h). Loop-closure
// parameters are deliberately not in the key: runs with other r, g, p, q whose decisions made
// the same final state share its scores, which is the point. The log, its relations and the
// metric options are fixed per context; use one cache per SlamEvaluationContext.
//
// Thread-safe. Two runs finishing the same state at once may both compute it (same values).
// Memory is bounded by a byte budget; when it would be exceeded, new entries are not stored.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamtune/common/key_words.h"
#include "slamtune/metrics/gt_error.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/occupancy_grid.h"

namespace slamtune::optim {

struct MapScores {
  metrics::MapQuality quality;
  slam::OccupancyGridSummary grid;  // the counts behind the map (hits the map does not back)
  metrics::GtError error;           // default (relations_used 0) without relations
  // The map the context's fixed scans draw along the run's path (metrics/trajectory_map.h); zero
  // counts when the context has none.
  slam::OccupancyGridSummary drawn;
};

struct MapScoreCacheCounters {
  std::uint64_t hits = 0;
  std::uint64_t misses = 0;
  std::uint64_t not_stored = 0;  // misses not kept because of the budget
  std::size_t entries = 0;
  std::size_t bytes = 0;

  // One line: "map score cache: H hits, M misses, N entries, B MB".
  std::string ToString() const;
};

class MapScoreCache {
 public:
  // byte_budget > 0 (InputError otherwise).
  explicit MapScoreCache(std::size_t byte_budget = std::size_t{128} << 20);
  MapScoreCache(const MapScoreCache&) = delete;
  MapScoreCache& operator=(const MapScoreCache&) = delete;

  static std::vector<std::uint64_t> KeyOf(const slam::OccupancyGridOptions& grid,
                                          std::span<const slam::LaserScan> scans);

  std::optional<MapScores> Find(const std::vector<std::uint64_t>& key);
  void Insert(std::vector<std::uint64_t> key, const MapScores& scores);
  MapScoreCacheCounters counters() const;

 private:
  std::size_t byte_budget_;
  mutable std::mutex mutex_;
  std::unordered_map<std::vector<std::uint64_t>, MapScores, KeyWordsHash> entries_;
  MapScoreCacheCounters counters_;
};

}  // namespace slamtune::optim
