#include "slamtune/slam/sharing/cache_counters.h"

#include <gtest/gtest.h>

namespace slamtune::slam {
namespace {

TEST(CacheCounters, ToStringNamesTheCacheAndItsCountsOnOneLine) {
  CacheCounters c;
  c.cache = "solve cache";
  c.hits = 7;
  c.misses = 3;
  c.evictions = 1;
  c.entries = 9;
  c.bytes = std::size_t{3} << 19;
  EXPECT_EQ(c.ToString(), "solve cache: 7 hits, 3 misses, 1 evictions, 9 entries, 1.5 MB");
}

}  // namespace
}  // namespace slamtune::slam
