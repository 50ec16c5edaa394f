#include "slamtune/slam/sharing/barycenter_cache.h"

#include <algorithm>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// The key, the entry and the hash node with its cached hash.
constexpr std::size_t kEntryBytes = sizeof(std::array<std::uint64_t, kGeometryKeyWords + 4>) + sizeof(Pose2) + 8 + 32;

}  // namespace

BarycenterCache::BarycenterCache(std::size_t byte_budget) : byte_budget_(byte_budget) {
  if (byte_budget_ == 0) throw InputError("barycentre cache byte_budget = 0 is out of range: must be > 0");
}

BarycenterCache::Key BarycenterCache::KeyOf(const LaserScan& scan) {
  Key key;
  const auto geometry = GeometryKeyWords(scan.geometry());
  std::copy(geometry.begin(), geometry.end(), key.begin());
  const Pose2& p = scan.corrected_pose();
  key[kGeometryKeyWords] = static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(scan.ranges_ptr().get()));
  key[kGeometryKeyWords + 1] = KeyBits(p.x);
  key[kGeometryKeyWords + 2] = KeyBits(p.y);
  key[kGeometryKeyWords + 3] = KeyBits(p.theta);
  return key;
}

void BarycenterCache::Provide(LaserScan& scan) {
  if (scan.barycenter_known()) return;
  const Key key = KeyOf(scan);
  {
    std::lock_guard guard(mutex_);
    auto it = entries_.find(key);
    if (it != entries_.end()) {
      ++counters_.hits;
      it->second.sequence = next_sequence_++;  // recently used: evicted last
      scan.SetBarycenter(it->second.barycenter);
      return;
    }
    ++counters_.misses;
  }
  // Computed outside the lock; two threads computing the same key store the same value.
  const Pose2 barycenter = scan.barycenter();
  std::lock_guard guard(mutex_);
  if (kEntryBytes > byte_budget_ || entries_.count(key) != 0) return;
  if (counters_.bytes + kEntryBytes > byte_budget_) EvictLeastRecentlyUsedHalfLocked();
  const std::uint64_t address = key[kGeometryKeyWords];
  if (readings_.find(address) == readings_.end()) readings_.emplace(address, scan.ranges_ptr());
  entries_.emplace(key, Entry{barycenter, next_sequence_++});
  counters_.bytes += kEntryBytes;
  counters_.entries = entries_.size();
}

void BarycenterCache::EvictLeastRecentlyUsedHalfLocked() {
  counters_.evictions += EvictLeastRecentlyUsedHalf(
      entries_, [](const Entry&) { return kEntryBytes; }, &counters_.bytes);
  counters_.entries = entries_.size();
}

CacheCounters BarycenterCache::counters() const {
  std::lock_guard guard(mutex_);
  return counters_;
}

}  // namespace slamtune::slam
