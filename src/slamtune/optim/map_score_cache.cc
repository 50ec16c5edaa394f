#include "slamtune/optim/map_score_cache.h"

#include <fmt/format.h>

#include <bit>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

std::uint64_t Bits(double v) { return std::bit_cast<std::uint64_t>(v); }

// A marker word (so geometry words cannot be mistaken for a scan's), then every field.
void AppendGeometry(const slam::LaserGeometry& g, std::vector<std::uint64_t>* key) {
  key->push_back(0x67656f6d65747279ULL);  // "geometry"
  key->push_back(Bits(g.min_angle));
  key->push_back(Bits(g.angular_resolution));
  key->push_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(g.num_readings)));
  key->push_back(Bits(g.min_range));
  key->push_back(Bits(g.max_range));
  key->push_back(Bits(g.range_threshold));
  key->push_back(Bits(g.offset.x));
  key->push_back(Bits(g.offset.y));
  key->push_back(Bits(g.offset.theta));
}

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

std::size_t MapScoreCache::KeyHash::operator()(const std::vector<std::uint64_t>& key) const {
  std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.size();
  for (std::uint64_t w : key) {
    h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h ^= h >> 31;
    h *= 0xbf58476d1ce4e5b9ULL;
  }
  return static_cast<std::size_t>(h);
}

std::vector<std::uint64_t> MapScoreCache::KeyOf(const slam::OccupancyGridOptions& grid,
                                                std::span<const slam::LaserScan> scans) {
  std::vector<std::uint64_t> key;
  key.reserve(16 + scans.size() * 4);
  key.push_back(Bits(grid.resolution));
  key.push_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(grid.min_pass_through)));
  key.push_back(Bits(grid.occupancy_threshold));
  key.push_back(scans.size());
  const slam::LaserGeometry* shared = nullptr;
  for (const slam::LaserScan& s : scans) {
    // The geometry's words once, again only where a scan has another geometry object.
    if (&s.geometry() != shared) {
      shared = &s.geometry();
      AppendGeometry(*shared, &key);
    }
    key.push_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(s.log_index)));
    key.push_back(Bits(s.corrected_pose().x));
    key.push_back(Bits(s.corrected_pose().y));
    key.push_back(Bits(s.corrected_pose().theta));
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
