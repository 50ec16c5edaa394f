#include "slamtune/slam/sharing/match_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <exception>
#include <iterator>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

std::uint64_t Bits(double v) { return KeyBits(v); }
void AppendPose(const Pose2& p, std::vector<std::uint64_t>* key) { AppendKeyPose(p, key); }

std::uint64_t Address(const LaserScan& s) { return reinterpret_cast<std::uintptr_t>(s.ranges_ptr().get()); }

// Header words = everything but the scans: [role, options..., flags, geometry...].
constexpr std::size_t kMaxHeaders = std::size_t{1} << 16;
constexpr std::size_t kMaxGeometries = std::size_t{1} << 16;
// Key layout after the header id: matched scan (log index, address, corrected and sensor pose
// bits), the base count, then the base ids two to a word.
constexpr std::size_t kBaseIdsOffset = 10;

// Approximate bookkeeping beside the key words: map node, bucket and the MatchResult of an
// entry; map node, bucket and the by-id words and count of an interned scan.
constexpr std::size_t kMatchEntryOverheadBytes = 224;
constexpr std::size_t kInternedBytes = 152;

}  // namespace

void MatchCacheOptions::Validate() const {
  if (byte_budget == 0) throw InputError("match cache byte_budget = 0 is out of range: must be > 0");
}

std::string MatchCacheCounters::ToString() const {
  const std::uint64_t calls = hits + waits + misses;
  return fmt::format(
      "match cache: {} hits, {} waits, {} misses (served {:.1f}% of {} matches), {} bypassed, "
      "{} evictions, {} entries, {} interned scans, {:.1f} MB",
      hits, waits, misses, calls > 0 ? 100.0 * static_cast<double>(hits + waits) / calls : 0.0, calls, bypassed,
      evictions, entries, interned, static_cast<double>(bytes) / (1 << 20));
}

MatchCache::MatchCache(const MatchCacheOptions& options) : options_(options) { options_.Validate(); }

std::vector<std::uint64_t> MatchCache::KeyOf(MatchRole role, const ScanMatcherOptions& options, const LaserScan& scan,
                                             std::span<const LaserScan* const> base_scans, Penalize penalize,
                                             Refine refine) {
  std::lock_guard lock(mutex_);
  return KeyLocked(role, options, scan, base_scans, penalize, refine);
}

void MatchCache::HoldReadingsLocked(const LaserScan& scan) {
  const std::uint64_t address = Address(scan);
  if (readings_.find(address) == readings_.end()) readings_.emplace(address, scan.ranges_ptr());
}

std::uint32_t MatchCache::GeometryIdLocked(const LaserGeometry& geometry) {
  const GeometryWords words = GeometryKeyWords(geometry);
  auto it = geometry_ids_.find(words);
  if (it != geometry_ids_.end()) return it->second;
  if (geometry_ids_.size() >= kMaxGeometries) return kFreeId;
  return geometry_ids_.emplace(words, static_cast<std::uint32_t>(geometry_ids_.size())).first->second;
}

std::uint32_t MatchCache::InternLocked(const LaserScan& scan, std::uint32_t geometry_id) {
  const Pose2& p = scan.corrected_pose();
  const ScanWords words = {KeyInt(scan.log_index), Address(scan), Bits(p.x), Bits(p.y), Bits(p.theta), geometry_id};
  const std::uint32_t hint = scan.match_key_hint();
  if (hint < id_words_.size() && refs_[hint] != kFreeId && id_words_[hint] == words) return hint;
  auto it = scan_ids_.find(words);
  if (it == scan_ids_.end()) {
    std::uint32_t id = 0;
    if (!free_ids_.empty()) {
      id = free_ids_.back();
      free_ids_.pop_back();
      id_words_[id] = words;
      refs_[id] = 0;
    } else {
      SLAMTUNE_CHECK_MSG(id_words_.size() < kFreeId, "match cache: 2^32 - 1 interned scans");
      id = static_cast<std::uint32_t>(id_words_.size());
      id_words_.push_back(words);
      refs_.push_back(0);
    }
    it = scan_ids_.emplace(words, id).first;
    HoldReadingsLocked(scan);
    ++counters_.interned;
    counters_.bytes += kInternedBytes;
  }
  scan.set_match_key_hint(it->second);
  return it->second;
}

std::vector<std::uint64_t> MatchCache::KeyLocked(MatchRole role, const ScanMatcherOptions& o, const LaserScan& scan,
                                                 std::span<const LaserScan* const> base_scans, Penalize penalize,
                                                 Refine refine, std::span<const std::uint64_t> extra) {
  std::vector<std::uint64_t> key;
  if (!scan.geometry_ptr() || !scan.ranges_ptr()) return key;
  // The base scans' geometry ids, looked up once per geometry object (usually one or two).
  std::vector<std::uint32_t> geometry_ids;
  geometry_ids.reserve(base_scans.size());
  const LaserGeometry* last = nullptr;
  for (const LaserScan* b : base_scans) {
    if (b == nullptr || !b->geometry_ptr() || !b->ranges_ptr()) return key;
    if (&b->geometry() != last) {
      last = &b->geometry();
      geometry_ids.push_back(GeometryIdLocked(*last));
      if (geometry_ids.back() == kFreeId) return key;  // bypass: the geometry table is full
    } else {
      geometry_ids.push_back(geometry_ids.back());
    }
  }
  std::vector<std::uint64_t> header;
  header.reserve(32);
  header.push_back(static_cast<std::uint64_t>(role));
  // ScanMatcherOptions: every field but `threads` and `branch_and_bound` (result-independent).
  for (double v : {o.search_dimension, o.search_resolution, o.smear_deviation, o.range_threshold, o.coarse_angle_offset,
                   o.coarse_angle_resolution, o.fine_angle_step, o.distance_variance_penalty, o.angle_variance_penalty,
                   o.minimum_distance_penalty, o.minimum_angle_penalty}) {
    header.push_back(Bits(v));
  }
  header.push_back((o.use_response_expansion ? 1u : 0u) | (penalize == Penalize::kYes ? 2u : 0u) |
                   (refine == Refine::kYes ? 4u : 0u));
  AppendGeometryKey(scan.geometry(), &header);
  header.insert(header.end(), extra.begin(), extra.end());
  auto h = headers_.find(header);
  if (h == headers_.end()) {
    if (headers_.size() >= kMaxHeaders) return key;  // bypass: the header table is full
    h = headers_.emplace(std::move(header), static_cast<std::uint32_t>(headers_.size())).first;
  }
  key.reserve(kBaseIdsOffset + (base_scans.size() + 1) / 2);
  key.push_back(h->second);
  key.push_back(KeyInt(scan.log_index));
  key.push_back(Address(scan));
  AppendPose(scan.corrected_pose(), &key);
  AppendPose(scan.SensorPose(), &key);
  key.push_back(base_scans.size());
  for (std::size_t i = 0; i < base_scans.size(); i += 2) {
    std::uint64_t word = InternLocked(*base_scans[i], geometry_ids[i]);
    if (i + 1 < base_scans.size()) {
      word |= static_cast<std::uint64_t>(InternLocked(*base_scans[i + 1], geometry_ids[i + 1])) << 32;
    }
    key.push_back(word);
  }
  return key;
}

void MatchCache::ReferenceIdsLocked(const std::vector<std::uint64_t>& key, int delta) {
  const std::size_t n = key[kBaseIdsOffset - 1];
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t word = key[kBaseIdsOffset + i / 2];
    const auto id = static_cast<std::uint32_t>(i % 2 == 0 ? word : word >> 32);
    SLAMTUNE_CHECK_MSG(id < refs_.size() && refs_[id] != kFreeId, "match cache: key names a free id");
    if (delta > 0) {
      ++refs_[id];
    } else if (--refs_[id] == 0) {
      scan_ids_.erase(id_words_[id]);
      refs_[id] = kFreeId;
      free_ids_.push_back(id);
      --counters_.interned;
      counters_.bytes -= kInternedBytes;
    }
  }
}

void MatchCache::EraseLocked(std::unordered_map<std::vector<std::uint64_t>, Entry, KeyWordsHash>::iterator it) {
  ReferenceIdsLocked(it->first, -1);
  counters_.bytes -= it->second.bytes;
  --counters_.entries;
  entries_.erase(it);
}

MatchResult MatchCache::Match(MatchRole role, ScanMatcher& matcher, const LaserScan& scan,
                              std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine) {
  SLAMTUNE_CHECK_MSG(role != MatchRole::kNearChain, "match cache: near-chain matches go through MatchAbove");
  return Find(role, matcher.options(), scan, base_scans, penalize, refine, {},
              [&] { return matcher.Match(scan, base_scans, penalize, refine); });
}

MatchResult MatchCache::MatchAbove(ScanMatcher& matcher, const LaserScan& scan,
                                   std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine,
                                   double threshold, const std::function<bool()>& may_exceed) {
  const std::uint64_t extra[] = {Bits(threshold)};
  return Find(MatchRole::kNearChain, matcher.options(), scan, base_scans, penalize, refine, extra, [&] {
    return may_exceed() ? matcher.Match(scan, base_scans, penalize, refine) : ProvenBelowThreshold();
  });
}

MatchResult MatchCache::Find(MatchRole role, const ScanMatcherOptions& options, const LaserScan& scan,
                             std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine,
                             std::span<const std::uint64_t> extra, const std::function<MatchResult()>& compute) {
  std::unique_lock lock(mutex_);
  std::vector<std::uint64_t> key;
  bool waited = false;
  for (;;) {
    // Rebuilt after every wait: ids may be freed and reused while the lock is released.
    key = KeyLocked(role, options, scan, base_scans, penalize, refine, extra);
    if (key.empty()) {
      ++counters_.bypassed;
      lock.unlock();
      return compute();
    }
    auto it = entries_.find(key);
    if (it == entries_.end()) break;
    if (it->second.ready) {
      ++(waited ? counters_.waits : counters_.hits);
      it->second.sequence = next_sequence_++;  // recently used: evicted last
      return it->second.result;
    }
    waited = true;
    computed_.wait(lock);
  }
  ++counters_.misses;
  ReferenceIdsLocked(key, +1);
  HoldReadingsLocked(scan);  // base scans' readings are held when they are interned
  Entry entry;
  entry.sequence = next_sequence_++;
  entry.bytes = key.capacity() * sizeof(std::uint64_t) + kMatchEntryOverheadBytes;
  counters_.bytes += entry.bytes;
  ++counters_.entries;
  // Element addresses survive rehashing, and an unfinished entry is never evicted.
  auto inserted = entries_.emplace(std::move(key), entry).first;
  const std::vector<std::uint64_t>* own_key = &inserted->first;
  Entry* own = &inserted->second;
  if (counters_.bytes > options_.byte_budget) EvictLeastRecentlyUsedHalfLocked();
  lock.unlock();
  try {
    MatchResult result = compute();
    lock.lock();
    own->result = result;
    own->ready = true;
    computed_.notify_all();
    if (counters_.bytes > options_.byte_budget) EvictLeastRecentlyUsedHalfLocked();
    return result;
  } catch (...) {
    // Forget the failed entry so that waiters and later calls compute again.
    if (!lock.owns_lock()) lock.lock();
    const std::vector<std::uint64_t> failed = *own_key;
    EraseLocked(entries_.find(failed));
    computed_.notify_all();
    throw;
  }
}

void MatchCache::EvictLeastRecentlyUsedHalfLocked() {
  std::vector<std::uint64_t> last_uses;
  last_uses.reserve(entries_.size());
  for (const auto& [key, entry] : entries_) {
    if (entry.ready) last_uses.push_back(entry.sequence);
  }
  if (last_uses.empty()) return;
  const std::uint64_t cut = LeastRecentlyUsedHalfCut(std::move(last_uses));
  for (auto it = entries_.begin(); it != entries_.end();) {
    auto next = std::next(it);
    if (it->second.ready && it->second.sequence < cut) {
      ++counters_.evictions;
      EraseLocked(it);
    }
    it = next;
  }
}

MatchCacheCounters MatchCache::counters() const {
  std::lock_guard lock(mutex_);
  return counters_;
}

}  // namespace slamtune::slam
