// A cache of back-end solves shared by many SLAM runs of one log (docs/engine.md §7.1):
// runs that differ only in loop-closure parameters and made the same decisions so far hold the
// same pose graph, so when one of them closes a loop its CorrectPoses solve repeats another
// run's verbatim. The first run computes it; the others copy its optimised node values. On a
// run whose scan matches all come from the MatchCache, the solves are about half of the time.
//
// Exactness, as in match_cache.h: an entry is keyed by everything the solve depends on,
// compared word for word (the hash only picks the bucket): the back-end's identity (its kind
// and every option, PoseGraphSolver::Identity()), the bits of every node value, and
// every edge's source, target, measurement and information bits in order. An entry holds the
// optimised node values and SolveSummary (its wall_s is the caller's to set) and, when the
// caller gives them, the barycentres of the scans at those poses, so that a run taking the
// stored solve need not recompute every scan's point readout to find them (slam/laser_scan.h); the
// mapper then appends the laser geometry's words to the key. Like the MatchCache, a SolveCache
// must only be shared by runs of the same log.
//
// Thread-safe. Two runs making the same solve at once may both compute it (same result).
// Memory is bounded by a byte budget; when it would be exceeded the least recently used half
// of the entries is dropped (a hit counts as a use: the solves of the log's shared prefix,
// made first and used by every run, must not go first). Whether an entry was kept changes
// only the time, never a result.
#pragma once

#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "slamtune/common/key_words.h"
#include "slamtune/common/pose2.h"
#include "slamtune/slam/backend/pose_graph_solver.h"
#include "slamtune/slam/pose_graph.h"
#include "slamtune/slam/sharing/cache_counters.h"

namespace slamtune::slam {

class SolveCache {
 public:
  // byte_budget > 0 (InputError otherwise).
  explicit SolveCache(std::size_t byte_budget = std::size_t{256} << 20);
  SolveCache(const SolveCache&) = delete;
  SolveCache& operator=(const SolveCache&) = delete;

  struct Solved {
    SolveSummary summary;
    std::vector<Pose2> nodes;        // after the solve
    std::vector<Pose2> barycenters;  // of the scans at `nodes`, or empty
  };

  // `solver` is the back-end's PoseGraphSolver::Identity(); nodes before the solve.
  static std::vector<std::uint64_t> KeyOf(const std::string& solver, std::span<const Pose2> nodes,
                                          std::span<const Edge> edges);
  // The stored solve of `key`, if any (counted as a hit or a miss).
  std::optional<Solved> Find(const std::vector<std::uint64_t>& key);
  void Store(std::vector<std::uint64_t> key, Solved solved);
  CacheCounters counters() const;

 private:
  struct Entry {
    Solved solved;
    std::uint64_t sequence = 0;  // last use, for eviction
    std::size_t bytes = 0;
  };
  void EvictLeastRecentlyUsedHalfLocked();

  std::size_t byte_budget_;
  mutable std::mutex mutex_;
  std::unordered_map<std::vector<std::uint64_t>, Entry, KeyWordsHash> entries_;
  std::uint64_t next_sequence_ = 0;
  CacheCounters counters_{"solve cache"};
};

}  // namespace slamtune::slam
