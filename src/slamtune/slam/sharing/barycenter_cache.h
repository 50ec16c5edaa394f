// A cache of scan barycentres (docs/engine.md §2.2) shared by many SLAM runs of one log.
// The mapper reads a scan's reference pose, its barycentre, right after the sequential match
// (§3.2 step 8) and again after AddEdges moves it (§5.3 step 4). A run whose matches and solves
// come from the MatchCache and SolveCache still computes a point readout (one sin/cos per beam)
// for each of these, and that was most of what remained of such a run. Runs that made the same
// decisions so far put the same scan at the same pose, so the barycentre repeats.
//
// Exactness, as in match_cache.h: an entry is keyed by everything LaserScan's readout reads,
// compared word for word: the laser geometry's words (GeometryKeyWords), the address of the
// scan's immutable readings (held by the cache, so the address cannot be reused while it lives)
// and the bits of the corrected pose. The scan checks a provided barycentre against its own
// when it later computes its readout (slam/laser_scan.h), so a wrong entry would fail loudly.
//
// Thread-safe. Memory is bounded by a byte budget; when it would be exceeded the least recently
// used half of the entries is dropped (a hit counts as a use). Whether an entry was kept
// changes only the time, never a result.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamtune/common/key_words.h"
#include "slamtune/common/pose2.h"
#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/sharing/cache_counters.h"

namespace slamtune::slam {

class BarycenterCache {
 public:
  // byte_budget > 0 (InputError otherwise).
  explicit BarycenterCache(std::size_t byte_budget = std::size_t{64} << 20);
  BarycenterCache(const BarycenterCache&) = delete;
  BarycenterCache& operator=(const BarycenterCache&) = delete;

  // Makes the barycentre of `scan` at its current corrected pose known: given to the scan from
  // the cache (LaserScan::SetBarycenter) when an earlier call saw the same scan at the same pose,
  // otherwise computed by the scan and stored. A scan whose barycentre is already known is left
  // as it is.
  void Provide(LaserScan& scan);
  CacheCounters counters() const;

 private:
  struct Entry {
    Pose2 barycenter;
    std::uint64_t sequence = 0;  // last use, for eviction
  };
  // Geometry words, readings address, corrected pose: fixed size, so a lookup allocates nothing.
  using Key = std::array<std::uint64_t, kGeometryKeyWords + 4>;
  static Key KeyOf(const LaserScan& scan);
  void EvictLeastRecentlyUsedHalfLocked();

  std::size_t byte_budget_;
  mutable std::mutex mutex_;
  std::unordered_map<Key, Entry, KeyWordsHash> entries_;
  std::map<std::uint64_t, std::shared_ptr<const std::vector<double>>> readings_;  // by address
  std::uint64_t next_sequence_ = 0;
  CacheCounters counters_{"barycentre cache"};
};

}  // namespace slamtune::slam
