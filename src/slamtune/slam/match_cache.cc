#include "slamtune/slam/match_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <exception>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

std::uint64_t Bits(double v) { return KeyBits(v); }
void AppendPose(const Pose2& p, std::vector<std::uint64_t>* key) { AppendKeyPose(p, key); }

bool SameGeometry(const LaserGeometry& a, const LaserGeometry& b) {
  std::vector<std::uint64_t> ka;
  std::vector<std::uint64_t> kb;
  AppendGeometryKey(a, &ka);
  AppendGeometryKey(b, &kb);
  return ka == kb;
}

std::uint64_t Address(const LaserScan& s) { return reinterpret_cast<std::uintptr_t>(s.ranges_ptr().get()); }

// Bookkeeping of one entry besides its key words: map node, shared state of the future with
// its MatchResult, the readings holders.
constexpr std::size_t kEntryOverheadBytes = 256;

}  // namespace

void MatchCacheOptions::Validate() const {
  if (byte_budget == 0) throw InputError("match cache byte_budget = 0 is out of range: must be > 0");
}

std::string MatchCacheCounters::ToString() const {
  const std::uint64_t calls = hits + waits + misses;
  return fmt::format("match cache: {} hits, {} waits, {} misses (served {:.1f}% of {} matches), {} bypassed, "
                     "{} evictions, {} entries, {:.1f} MB",
                     hits, waits, misses, calls > 0 ? 100.0 * static_cast<double>(hits + waits) / calls : 0.0, calls,
                     bypassed, evictions, entries, static_cast<double>(bytes) / (1 << 20));
}

MatchCache::MatchCache(const MatchCacheOptions& options) : options_(options) { options_.Validate(); }

std::vector<std::uint64_t> MatchCache::KeyOf(MatchRole role, const ScanMatcherOptions& o, const LaserScan& scan,
                                             std::span<const LaserScan* const> base_scans, bool penalize,
                                             bool refine) {
  std::vector<std::uint64_t> key;
  if (!scan.geometry_ptr() || !scan.ranges_ptr()) return key;
  for (const LaserScan* b : base_scans) {
    if (b == nullptr || !b->geometry_ptr() || !b->ranges_ptr()) return key;
    if (b->geometry_ptr() != scan.geometry_ptr() && !SameGeometry(b->geometry(), scan.geometry())) return key;
  }
  key.reserve(32 + 5 * base_scans.size());
  key.push_back(static_cast<std::uint64_t>(role));
  // ScanMatcherOptions: every field but `threads` and `branch_and_bound` (result-independent).
  for (double v : {o.search_dimension, o.search_resolution, o.smear_deviation, o.range_threshold,
                   o.coarse_angle_offset, o.coarse_angle_resolution, o.fine_angle_step, o.distance_variance_penalty,
                   o.angle_variance_penalty, o.minimum_distance_penalty, o.minimum_angle_penalty}) {
    key.push_back(Bits(v));
  }
  key.push_back((o.use_response_expansion ? 1u : 0u) | (penalize ? 2u : 0u) | (refine ? 4u : 0u));
  AppendGeometryKey(scan.geometry(), &key);
  key.push_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(scan.log_index)));
  key.push_back(Address(scan));
  AppendPose(scan.corrected_pose(), &key);
  AppendPose(scan.SensorPose(), &key);
  key.push_back(base_scans.size());
  for (const LaserScan* b : base_scans) {
    key.push_back(static_cast<std::uint64_t>(static_cast<std::int64_t>(b->log_index)));
    key.push_back(Address(*b));
    AppendPose(b->corrected_pose(), &key);
  }
  return key;
}

MatchResult MatchCache::Match(MatchRole role, ScanMatcher& matcher, const LaserScan& scan,
                              std::span<const LaserScan* const> base_scans, bool penalize, bool refine) {
  std::vector<std::uint64_t> key = KeyOf(role, matcher.options(), scan, base_scans, penalize, refine);
  if (key.empty()) {
    {
      std::lock_guard lock(mutex_);
      ++counters_.bypassed;
    }
    return matcher.Match(scan, base_scans, penalize, refine);
  }
  std::promise<MatchResult> promise;
  std::uint64_t sequence = 0;
  {
    std::unique_lock lock(mutex_);
    auto it = entries_.find(key);
    if (it != entries_.end()) {
      std::shared_future<MatchResult> future = it->second.result;
      const bool ready = future.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
      ++(ready ? counters_.hits : counters_.waits);
      lock.unlock();
      return future.get();  // rethrows when the computing call failed
    }
    ++counters_.misses;
    Entry entry;
    entry.result = promise.get_future().share();
    // One holder per distinct owner: readings of one log all alias the log, so this is usually one.
    auto hold = [&entry](const std::shared_ptr<const std::vector<double>>& r) {
      for (const auto& held : entry.readings) {
        if (!held.owner_before(r) && !r.owner_before(held)) return;
      }
      entry.readings.push_back(r);
    };
    hold(scan.ranges_ptr());
    for (const LaserScan* b : base_scans) hold(b->ranges_ptr());
    entry.sequence = sequence = next_sequence_++;
    entry.bytes = key.capacity() * sizeof(std::uint64_t) + entry.readings.capacity() * sizeof(entry.readings[0]) + kEntryOverheadBytes;
    counters_.bytes += entry.bytes;
    entries_.emplace(std::move(key), std::move(entry));
    ++counters_.entries;
    if (counters_.bytes > options_.byte_budget) EvictOldestHalfLocked();
  }
  try {
    MatchResult result = matcher.Match(scan, base_scans, penalize, refine);
    promise.set_value(result);
    return result;
  } catch (...) {
    promise.set_exception(std::current_exception());
    // Forget the failed entry (if still held) so a later call computes again.
    std::lock_guard lock(mutex_);
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (it->second.sequence == sequence) {
        counters_.bytes -= it->second.bytes;
        --counters_.entries;
        entries_.erase(it);
        break;
      }
    }
    throw;
  }
}

void MatchCache::EvictOldestHalfLocked() {
  std::vector<std::uint64_t> sequences;
  sequences.reserve(entries_.size());
  for (const auto& [key, entry] : entries_) sequences.push_back(entry.sequence);
  const auto middle = sequences.begin() + static_cast<std::ptrdiff_t>(sequences.size() / 2);
  std::nth_element(sequences.begin(), middle, sequences.end());
  const std::uint64_t keep_from = sequences.empty() ? 0 : *middle;
  for (auto it = entries_.begin(); it != entries_.end();) {
    if (it->second.sequence < keep_from || entries_.size() == 1) {
      counters_.bytes -= it->second.bytes;
      --counters_.entries;
      ++counters_.evictions;
      it = entries_.erase(it);
    } else {
      ++it;
    }
  }
}

MatchCacheCounters MatchCache::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

}  // namespace slamtune::slam
