// A cache of scan-match results shared by many SLAM runs of one log (docs/engine.md §4.2,
// §5.3, §6.1): runs that differ only in loop-closure parameters (r, g, p, q) build identical
// state until their decisions differ, so they repeat the same MatchScan calls verbatim. The
// first run to make a call computes it; the others reuse the result.
//
// Exactness: an entry is keyed by EVERYTHING the result depends on, compared word for word
// (the hash only picks the bucket, so a collision can never return a wrong result):
//   - the matcher role and every ScanMatcherOptions field that affects results (all but
//     `threads` and `branch_and_bound`, which are documented as result-independent),
//   - the penalize / refine flags and the matched scan's laser geometry,
//   - the matched scan: log index, address of its (immutable, shared) readings, the bits of
//     its corrected and sensor poses,
//   - the base scans in order: log index, readings address, the bits of the corrected pose
//     and the laser geometry of each (a base scan may be another laser's, docs/engine.md §3.5).
// Compact keys: the first group (the same for every call of a run) is interned once as a
// header id, each distinct geometry as a geometry id, and each base scan's six words as a
// 32-bit id, so a key is about ten words plus half a word per base scan instead of six words
// per base scan (a running buffer of 70 scans: ~45 words, not ~430). A scan id names its words
// exactly while any entry refers to it (reference counts; an id is reused only after its last
// entry is dropped), and a scan remembers its id as a hint that is checked against the interned
// words before use. Geometry ids, like header ids, stay for the cache's life and are not counted
// in its bytes (a run has one per laser; at most 65 536 are held, beyond which calls with a new
// geometry bypass the cache).
// The cache holds every readings buffer it has keyed, so an address in a key cannot be reused
// by other data while the cache lives. A cache must only be shared by runs of the same log:
// log indices of different logs mean different scans (the readings address tells them apart anyway).
//
// Concurrency: thread-safe. Concurrent requests for the same key compute once: the first
// caller computes, the others wait for its result. Memory is bounded by a byte budget; when
// exceeded, the least recently used half of the finished entries is dropped (with the
// interned scan ids only they used); a hit counts as a use, so the matches of the log's prefix that
// every run repeats stay while one-off matches after runs diverge go. Whether an entry was
// evicted changes only the time, never a result.
#pragma once

#include <array>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamtune/common/key_words.h"
#include "slamtune/slam/laser_scan.h"
#include "slamtune/slam/matching/scan_matcher.h"

namespace slamtune::slam {

// Which of the mapper's matchers made the call (§3.2 step 7, §5.3 step 3, §6.1).
// kNearChain: a sequential-matcher call whose result the mapper keeps only above a response
// threshold (MatchAbove); its entries may hold "proven below" instead of a match.
enum class MatchRole : std::uint8_t { kSequential = 0, kLoop = 1, kNearChain = 2 };

struct MatchCacheOptions {
  std::size_t byte_budget = std::size_t{512} << 20;  // bytes of keys + results kept; > 0

  // Throws InputError naming the field when byte_budget is 0.
  void Validate() const;
};

struct MatchCacheCounters {
  std::uint64_t hits = 0;       // served from a finished entry
  std::uint64_t misses = 0;     // computed by the caller
  std::uint64_t waits = 0;      // served by waiting for another thread computing the same key
  std::uint64_t bypassed = 0;   // calls whose inputs cannot be keyed exactly (computed, not stored)
  std::uint64_t evictions = 0;  // entries dropped to stay within the budget
  std::size_t entries = 0;      // entries held now
  std::size_t interned = 0;     // interned base-scan ids held now
  std::size_t bytes = 0;        // approximate bytes held now (keys + results + bookkeeping)

  // One line: "match cache: H hits, W waits, M misses (served X% of C matches), ..., B MB".
  std::string ToString() const;
};

class MatchCache {
 public:
  // Validates `options` (InputError).
  explicit MatchCache(const MatchCacheOptions& options = {});
  MatchCache(const MatchCache&) = delete;
  MatchCache& operator=(const MatchCache&) = delete;

  // The result of matcher.Match(scan, base_scans, penalize, refine) made by `matcher` in role
  // `role`: from the cache when the same call was made before, otherwise computed with
  // `matcher` on the calling thread and stored. The matcher itself is not shared.
  MatchResult Match(MatchRole role, ScanMatcher& matcher, const LaserScan& scan,
                    std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine);

  // A near-chain match (role kNearChain; §5.3 step 3), which the caller keeps only when its
  // response exceeds `threshold`. On a miss `may_exceed()` is asked first; when it says the
  // response cannot exceed the threshold (an exact proof, slam/matching/fast_matching/response_bound.h), the match is
  // not computed and ProvenBelowThreshold() is stored and returned instead. The threshold's bits are part of the key,
  // so a stored proof is only served to calls with the same threshold.
  MatchResult MatchAbove(ScanMatcher& matcher, const LaserScan& scan, std::span<const LaserScan* const> base_scans,
                         Penalize penalize, Refine refine, double threshold, const std::function<bool()>& may_exceed);

  MatchCacheCounters counters() const;
  const MatchCacheOptions& options() const { return options_; }

  // The key words of a call as this cache would file it (exposed for tests; ids are this
  // cache's, so keys of two caches do not compare); empty when the call cannot be keyed
  // exactly. Base scans it interns for the first time stay interned until the cache is destroyed.
  std::vector<std::uint64_t> KeyOf(MatchRole role, const ScanMatcherOptions& options, const LaserScan& scan,
                                   std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine);

 private:
  // (log index, readings address, corrected pose x, y, theta bits, geometry id) of a base scan.
  using ScanWords = std::array<std::uint64_t, 6>;
  using GeometryWords = std::array<std::uint64_t, kGeometryKeyWords>;
  struct Entry {
    MatchResult result;
    bool ready = false;          // false while the first caller computes it
    std::uint64_t sequence = 0;  // last use, for eviction
    std::size_t bytes = 0;
  };
  static constexpr std::uint32_t kFreeId = 0xffffffffu;  // refs_ value of an unused id

  // `extra` words (e.g. a threshold's bits) join the header.
  std::vector<std::uint64_t> KeyLocked(MatchRole role, const ScanMatcherOptions& options, const LaserScan& scan,
                                       std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine,
                                       std::span<const std::uint64_t> extra = {});
  // The lookup of Match and MatchAbove: a stored result, or `compute()` run once and stored.
  MatchResult Find(MatchRole role, const ScanMatcherOptions& options, const LaserScan& scan,
                   std::span<const LaserScan* const> base_scans, Penalize penalize, Refine refine,
                   std::span<const std::uint64_t> extra, const std::function<MatchResult()>& compute);
  // The id of a geometry's words, interned for the cache's life; kFreeId when the table is full.
  std::uint32_t GeometryIdLocked(const LaserGeometry& geometry);
  std::uint32_t InternLocked(const LaserScan& scan, std::uint32_t geometry_id);
  void HoldReadingsLocked(const LaserScan& scan);
  // Adds `delta` (+1 / -1) to the reference count of every base id in `key`; ids left
  // without references are freed.
  void ReferenceIdsLocked(const std::vector<std::uint64_t>& key, int delta);
  void EraseLocked(std::unordered_map<std::vector<std::uint64_t>, Entry, KeyWordsHash>::iterator it);
  void EvictLeastRecentlyUsedHalfLocked();

  MatchCacheOptions options_;
  mutable std::mutex mutex_;
  std::condition_variable computed_;  // signalled when an entry becomes ready or is dropped
  std::unordered_map<std::vector<std::uint64_t>, Entry, KeyWordsHash> entries_;
  std::unordered_map<std::vector<std::uint64_t>, std::uint32_t, KeyWordsHash> headers_;
  std::unordered_map<GeometryWords, std::uint32_t, KeyWordsHash> geometry_ids_;
  std::unordered_map<ScanWords, std::uint32_t, KeyWordsHash> scan_ids_;
  std::vector<ScanWords> id_words_;  // by id
  std::vector<std::uint32_t> refs_;  // by id: entries referring to it, or kFreeId
  std::vector<std::uint32_t> free_ids_;
  std::map<std::uint64_t, std::shared_ptr<const std::vector<double>>> readings_;  // by address
  std::uint64_t next_sequence_ = 0;
  MatchCacheCounters counters_;
};

}  // namespace slamtune::slam
