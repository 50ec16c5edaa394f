#include "slamtune/optim/evaluation/map_score_cache.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

// Map node, vector header and the scores' strings, roughly.
constexpr std::size_t kEntryOverheadBytes = 512;

}  // namespace

std::string MapScoreCacheCounters::ToString() const {
  return fmt::format("map score cache: {} hits, {} misses ({} not stored), {} entries, {:.1f} MB", hits, misses,
                     not_stored, entries, static_cast<double>(bytes) / (1 << 20));
}

MapScoreCache::MapScoreCache(std::size_t byte_budget) : byte_budget_(byte_budget) {
  if (byte_budget_ == 0) throw InputError("map score cache byte_budget = 0 is out of range: must be > 0");
}

std::vector<std::uint64_t> MapScoreCache::KeyOf(const slam::OccupancyGridOptions& grid,
                                                std::span<const slam::LaserScan> scans) {
  std::vector<std::uint64_t> key;
  key.reserve(16 + scans.size() * 5);
  key.push_back(KeyBits(grid.resolution));
  key.push_back(KeyInt(grid.min_pass_through));
  key.push_back(KeyBits(grid.occupancy_threshold));
  key.push_back(scans.size());
  const slam::LaserGeometry* shared = nullptr;
  for (const slam::LaserScan& s : scans) {
    // A flag word per scan: 1 and the geometry's words where it differs from the previous one's.
    const bool new_geometry = &s.geometry() != shared;
    key.push_back(new_geometry ? 1 : 0);
    if (new_geometry) {
      shared = &s.geometry();
      slam::AppendGeometryKey(*shared, &key);
    }
    key.push_back(KeyInt(s.log_index));
    AppendKeyPose(s.corrected_pose(), &key);
  }
  return key;
}

std::optional<MapScores> MapScoreCache::Find(const std::vector<std::uint64_t>& key) {
  std::lock_guard guard(mutex_);
  const auto it = entries_.find(key);
  if (it == entries_.end()) {
    ++counters_.misses;
    return std::nullopt;
  }
  ++counters_.hits;
  return it->second;
}

void MapScoreCache::Insert(std::vector<std::uint64_t> key, const MapScores& scores) {
  const std::size_t bytes = key.size() * sizeof(std::uint64_t) + sizeof(MapScores) + kEntryOverheadBytes;
  std::lock_guard guard(mutex_);
  if (entries_.count(key) != 0) return;
  if (counters_.bytes + bytes > byte_budget_) {
    ++counters_.not_stored;
    return;
  }
  entries_.emplace(std::move(key), scores);
  counters_.bytes += bytes;
  counters_.entries = entries_.size();
}

MapScoreCacheCounters MapScoreCache::counters() const {
  std::lock_guard guard(mutex_);
  return counters_;
}

}  // namespace slamtune::optim
