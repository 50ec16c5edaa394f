#include "slamtune/slam/sharing/cache_counters.h"

#include <fmt/format.h>

namespace slamtune::slam {

std::string CacheCounters::ToString() const {
  return fmt::format("{}: {} hits, {} misses, {} evictions, {} entries, {:.1f} MB", cache, hits, misses, evictions,
                     entries, static_cast<double>(bytes) / (1 << 20));
}

}  // namespace slamtune::slam
