#include "slamtune/slam/sharing/solve_cache.h"

#include <algorithm>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// Map node, the stored summary's strings, vector headers.
constexpr std::size_t kSolveEntryOverheadBytes = 256;

}  // namespace

SolveCache::SolveCache(std::size_t byte_budget) : byte_budget_(byte_budget) {
  if (byte_budget_ == 0) throw InputError("solve cache byte_budget = 0 is out of range: must be > 0");
}

std::vector<std::uint64_t> SolveCache::KeyOf(const std::string& solver, std::span<const Pose2> nodes,
                                             std::span<const Edge> edges) {
  std::vector<std::uint64_t> key;
  key.reserve(8 + solver.size() + nodes.size() * 3 + edges.size() * 14);
  AppendKeyString(solver, &key);
  key.push_back(nodes.size());
  for (const Pose2& p : nodes) AppendKeyPose(p, &key);
  key.push_back(edges.size());
  for (const Edge& e : edges) {
    key.push_back(KeyInt(e.source));
    key.push_back(KeyInt(e.target));
    AppendKeyPose(e.constraint.measurement, &key);
    for (int r = 0; r < 3; ++r) {
      for (int c = 0; c < 3; ++c) key.push_back(KeyBits(e.constraint.information(r, c)));
    }
  }
  return key;
}

std::optional<SolveCache::Solved> SolveCache::Find(const std::vector<std::uint64_t>& key) {
  std::lock_guard guard(mutex_);
  auto it = entries_.find(key);
  if (it == entries_.end()) {
    ++counters_.misses;
    return std::nullopt;
  }
  ++counters_.hits;
  it->second.sequence = next_sequence_++;  // recently used: evicted last
  return it->second.solved;
}

void SolveCache::Store(std::vector<std::uint64_t> key, Solved solved) {
  Entry entry;
  entry.bytes = key.size() * sizeof(std::uint64_t) + (solved.nodes.size() + solved.barycenters.size()) * sizeof(Pose2) +
                kSolveEntryOverheadBytes;
  entry.solved = std::move(solved);
  std::lock_guard guard(mutex_);
  if (entry.bytes > byte_budget_ || entries_.count(key) != 0) return;
  if (counters_.bytes + entry.bytes > byte_budget_) EvictLeastRecentlyUsedHalfLocked();
  entry.sequence = next_sequence_++;
  counters_.bytes += entry.bytes;
  entries_.emplace(std::move(key), std::move(entry));
  counters_.entries = entries_.size();
}

void SolveCache::EvictLeastRecentlyUsedHalfLocked() {
  counters_.evictions += EvictLeastRecentlyUsedHalf(
      entries_, [](const Entry& entry) { return entry.bytes; }, &counters_.bytes);
  counters_.entries = entries_.size();
}

CacheCounters SolveCache::counters() const {
  std::lock_guard guard(mutex_);
  return counters_;
}

}  // namespace slamtune::slam
