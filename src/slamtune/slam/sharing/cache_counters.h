// What one of the exact caches of slam/sharing has done so far, as its counters() report it: the
// solve and barycentre caches count the same things (match_cache.h counts more: waits, bypassed
// calls, interned scans).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace slamtune::slam {

struct CacheCounters {
  const char* cache = "";       // "solve cache", "barycentre cache"
  std::uint64_t hits = 0;       // served from an entry
  std::uint64_t misses = 0;     // computed by the caller
  std::uint64_t evictions = 0;  // entries dropped to stay within the budget
  std::size_t entries = 0;      // entries held now
  std::size_t bytes = 0;        // approximate bytes held now

  // One line: "solve cache: H hits, M misses, E evictions, N entries, B MB".
  std::string ToString() const;
};

}  // namespace slamtune::slam
