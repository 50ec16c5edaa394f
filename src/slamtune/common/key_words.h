// Exact cache keys as vectors of 64-bit words, shared by the caches that let SLAM runs reuse each
// other's work (slam/sharing/match_cache.h, slam/sharing/solve_cache.h, optim/evaluation/map_score_cache.h). A key
// holds the bits of everything a result depends on and is compared word for word; KeyWordsHash only picks a bucket, so
// a collision costs time, never a wrong result.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune {

inline std::uint64_t KeyBits(double v) { return std::bit_cast<std::uint64_t>(v); }
inline std::uint64_t KeyInt(std::int64_t v) { return static_cast<std::uint64_t>(v); }

inline void AppendKeyPose(const Pose2& p, std::vector<std::uint64_t>* key) {
  key->push_back(KeyBits(p.x));
  key->push_back(KeyBits(p.y));
  key->push_back(KeyBits(p.theta));
}

// Length first, so that consecutive strings cannot run into each other.
inline void AppendKeyString(const std::string& s, std::vector<std::uint64_t>* key) {
  key->push_back(s.size());
  for (char c : s) key->push_back(static_cast<unsigned char>(c));
}

struct KeyWordsHash {
  std::size_t operator()(std::span<const std::uint64_t> key) const {
    // 64-bit mix per word (splitmix64 finaliser constants).
    std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ key.size();
    for (std::uint64_t w : key) {
      h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
      h ^= h >> 31;
      h *= 0xbf58476d1ce4e5b9ULL;
      h ^= h >> 29;
    }
    return static_cast<std::size_t>(h);
  }
  std::size_t operator()(const std::vector<std::uint64_t>& key) const { return (*this)(std::span(key)); }
  template <std::size_t N>
  std::size_t operator()(const std::array<std::uint64_t, N>& key) const {
    return (*this)(std::span<const std::uint64_t>(key));
  }
};

// Least-recently-used eviction of half a cache: given the last-use sequence numbers of the
// entries that may go, the cut below which they are dropped (the median; with one entry, past
// it, so that eviction always frees something). Takes the numbers by value (reorders them).
inline std::uint64_t LeastRecentlyUsedHalfCut(std::vector<std::uint64_t> last_uses) {
  if (last_uses.size() <= 1) return last_uses.empty() ? 0 : last_uses[0] + 1;
  const auto middle = last_uses.begin() + static_cast<std::ptrdiff_t>(last_uses.size() / 2);
  std::nth_element(last_uses.begin(), middle, last_uses.end());
  return *middle;
}

// Drops the least recently used half of `entries` (a map whose values carry their last use as
// `sequence`), subtracting bytes_of(value) of each dropped entry from *bytes. Returns how many
// were dropped.
template <typename Map, typename BytesOf>
std::size_t EvictLeastRecentlyUsedHalf(Map& entries, BytesOf bytes_of, std::size_t* bytes) {
  std::vector<std::uint64_t> last_uses;
  last_uses.reserve(entries.size());
  for (const auto& kv : entries) last_uses.push_back(kv.second.sequence);
  if (last_uses.empty()) return 0;
  const std::uint64_t cut = LeastRecentlyUsedHalfCut(std::move(last_uses));
  std::size_t dropped = 0;
  for (auto it = entries.begin(); it != entries.end();) {
    if (it->second.sequence < cut) {
      *bytes -= bytes_of(it->second);
      ++dropped;
      it = entries.erase(it);
    } else {
      ++it;
    }
  }
  return dropped;
}

}  // namespace slamtune
