#include "slamtune/slam/barycenter_cache.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// Geometry (9 words), readings address, corrected pose (3 words).
constexpr std::size_t kKeyWords = 13;
// Key words, the vector's header, the entry and the hash node.
constexpr std::size_t kEntryBytes = kKeyWords * sizeof(std::uint64_t) + 24 + sizeof(Pose2) + 8 + 64;

}  // namespace

std::string BarycenterCacheCounters::ToString() const {
  return fmt::format("barycentre cache: {} hits, {} misses, {} evictions, {} entries, {:.1f} MB", hits, misses,
                     evictions, entries, static_cast<double>(bytes) / (1 << 20));
}

BarycenterCache::BarycenterCache(std::size_t byte_budget) : byte_budget_(byte_budget) {
  if (byte_budget_ == 0) throw InputError("barycentre cache byte_budget = 0 is out of range: must be > 0");
}

std::vector<std::uint64_t> BarycenterCache::KeyOf(const LaserScan& scan) {
  std::vector<std::uint64_t> key;
  key.reserve(kKeyWords);
  AppendGeometryKey(scan.geometry(), &key);
  key.push_back(static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(scan.ranges_ptr().get())));
  AppendKeyPose(scan.corrected_pose(), &key);
  SLAMTUNE_CHECK(key.size() == kKeyWords);
  return key;
}

void BarycenterCache::Provide(LaserScan& scan) {
  if (scan.barycenter_known()) return;
  std::vector<std::uint64_t> key = KeyOf(scan);
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
  const auto address = key[kKeyWords - 4];
  if (readings_.find(address) == readings_.end()) readings_.emplace(address, scan.ranges_ptr());
  entries_.emplace(std::move(key), Entry{barycenter, next_sequence_++});
  counters_.bytes += kEntryBytes;
  counters_.entries = entries_.size();
}

void BarycenterCache::EvictLeastRecentlyUsedHalfLocked() {
  counters_.evictions += EvictLeastRecentlyUsedHalf(entries_, [](const Entry&) { return kEntryBytes; }, &counters_.bytes);
  counters_.entries = entries_.size();
}

BarycenterCacheCounters BarycenterCache::counters() const {
  std::lock_guard guard(mutex_);
  return counters_;
}

}  // namespace slamtune::slam
