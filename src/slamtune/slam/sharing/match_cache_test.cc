#include "slamtune/slam/sharing/match_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/common/testing/same_bits.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::SameBits;

// A 6 m square room seen from (x, y): ranges of 181 beams over 180 degrees.
LaserScan RoomScan(const Pose2& pose, int log_index) {
  static const auto geometry = [] {
    LaserGeometry g;
    g.min_angle = -kPi / 2;
    g.angular_resolution = kPi / 180;
    g.num_readings = 181;
    g.max_range = 80.0;
    g.range_threshold = 12.0;
    return std::make_shared<const LaserGeometry>(g);
  }();
  auto ranges = std::make_shared<std::vector<double>>();
  for (int i = 0; i < geometry->num_readings; ++i) {
    const double a = pose.theta + geometry->min_angle + i * geometry->angular_resolution;
    const double c = std::cos(a);
    const double s = std::sin(a);
    double r = 1e9;
    if (c > 1e-9) r = std::min(r, (3.0 - pose.x) / c);
    if (c < -1e-9) r = std::min(r, (-3.0 - pose.x) / c);
    if (s > 1e-9) r = std::min(r, (3.0 - pose.y) / s);
    if (s < -1e-9) r = std::min(r, (-3.0 - pose.y) / s);
    ranges->push_back(r);
  }
  LaserScan scan(geometry, ranges, pose, 0.1 * log_index);
  scan.log_index = log_index;
  return scan;
}

// Mean, response and covariance, bit for bit.
bool SameBits(const MatchResult& a, const MatchResult& b) {
  if (!SameBits(a.mean, b.mean) || !SameBits(a.response, b.response)) return false;
  for (int k = 0; k < 9; ++k) {
    if (!SameBits(a.covariance.data()[k], b.covariance.data()[k])) return false;
  }
  return true;
}

// A scan of the room to match against three base scans, with the default matcher options.
struct ScanAndBases {
  LaserScan scan = RoomScan({0.05, -0.02, 0.01}, 3);
  std::vector<LaserScan> bases = {RoomScan({0, 0, 0}, 0), RoomScan({0.2, 0, 0}, 1), RoomScan({0.4, 0.1, 0}, 2)};
  std::vector<const LaserScan*> base_ptrs = {&bases[0], &bases[1], &bases[2]};
  ScanMatcherOptions options;

  // The sequential match of the scan against the bases through `cache`; `matcher` computes it on
  // a miss.
  MatchResult CachedMatch(MatchCache& cache, ScanMatcher& matcher, Penalize penalize, Refine refine) const {
    return cache.Match(MatchRole::kSequential, matcher, scan, base_ptrs, penalize, refine);
  }

  // The same match by a matcher of its own, without a cache: what every cached call must equal.
  MatchResult FreshMatch(Penalize penalize, Refine refine) const {
    ScanMatcher matcher(options);
    return matcher.Match(scan, base_ptrs, penalize, refine);
  }
};

TEST(MatchCacheOptions, RejectsAZeroBudget) {
  MatchCacheOptions o;
  o.byte_budget = 0;
  EXPECT_THROW(o.Validate(), InputError);
  EXPECT_THROW(MatchCache{o}, InputError);
}

// Near-chain calls: a proof that the response stays below the threshold is stored and served
// like a result (the proof is not asked for again), a real match is stored when the proof
// fails, and another threshold is another key.
TEST(MatchCache, MatchAboveStoresProofsAndMatchesPerThreshold) {
  ScanAndBases f;
  MatchCache cache;
  ScanMatcher matcher(f.options);
  int asked = 0;
  const auto cannot = [&] { return ++asked, false; };
  const auto can = [&] { return ++asked, true; };
  EXPECT_TRUE(
      IsProvenBelowThreshold(cache.MatchAbove(matcher, f.scan, f.base_ptrs, Penalize::kNo, Refine::kYes, 0.8, cannot)));
  EXPECT_TRUE(
      IsProvenBelowThreshold(cache.MatchAbove(matcher, f.scan, f.base_ptrs, Penalize::kNo, Refine::kYes, 0.8, can)));
  EXPECT_EQ(asked, 1);  // the second call was served the stored proof
  const MatchResult real = cache.MatchAbove(matcher, f.scan, f.base_ptrs, Penalize::kNo, Refine::kYes, 0.5, can);
  EXPECT_EQ(asked, 2);  // another threshold: another entry
  EXPECT_TRUE(SameBits(real, f.FreshMatch(Penalize::kNo, Refine::kYes)));
  EXPECT_TRUE(SameBits(real, cache.MatchAbove(matcher, f.scan, f.base_ptrs, Penalize::kNo, Refine::kYes, 0.5, cannot)));
  EXPECT_EQ(asked, 2);
  // Near-chain entries are apart from plain sequential ones with the same inputs.
  EXPECT_TRUE(SameBits(f.CachedMatch(cache, matcher, Penalize::kNo, Refine::kYes), real));
  EXPECT_EQ(cache.counters().misses, 3u);
  EXPECT_EQ(cache.counters().hits, 2u);
}

TEST(MatchCache, KeyChangesWithEveryResultAffectingInput) {
  ScanAndBases f;
  MatchCache cache;
  const auto key = [&](MatchRole role, const ScanMatcherOptions& o, const LaserScan& s,
                       const std::vector<const LaserScan*>& b, Penalize penalize,
                       Refine refine) { return cache.KeyOf(role, o, s, b, penalize, refine); };
  const auto base = key(MatchRole::kSequential, f.options, f.scan, f.base_ptrs, Penalize::kYes, Refine::kYes);
  ASSERT_FALSE(base.empty());
  EXPECT_NE(base, key(MatchRole::kLoop, f.options, f.scan, f.base_ptrs, Penalize::kYes, Refine::kYes));
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, f.scan, f.base_ptrs, Penalize::kNo, Refine::kYes));
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, f.scan, f.base_ptrs, Penalize::kYes, Refine::kNo));
  // Each result-affecting option changes the key; threads and branch_and_bound do not.
  std::vector<ScanMatcherOptions> changed(12, f.options);
  changed[0].search_dimension = 0.5;
  changed[1].search_resolution = 0.025;
  changed[2].smear_deviation = 0.04;
  changed[3].range_threshold = 11.0;
  changed[4].coarse_angle_offset = 0.3;
  changed[5].coarse_angle_resolution = 0.03;
  changed[6].fine_angle_step = 0.003;
  changed[7].distance_variance_penalty = 0.1;
  changed[8].angle_variance_penalty = 0.1;
  changed[9].minimum_distance_penalty = 0.4;
  changed[10].minimum_angle_penalty = 0.8;
  changed[11].use_response_expansion = true;
  for (const ScanMatcherOptions& o : changed) {
    EXPECT_NE(base, key(MatchRole::kSequential, o, f.scan, f.base_ptrs, Penalize::kYes, Refine::kYes));
  }
  ScanMatcherOptions speed = f.options;
  speed.threads = 3;
  speed.branch_and_bound = !speed.branch_and_bound;
  EXPECT_EQ(base, key(MatchRole::kSequential, speed, f.scan, f.base_ptrs, Penalize::kYes, Refine::kYes));
  // The laser geometry counts.
  LaserGeometry wider = f.scan.geometry();
  wider.max_range = 81.0;
  const auto wider_ptr = std::make_shared<const LaserGeometry>(wider);
  LaserScan other_laser(wider_ptr, f.scan.ranges_ptr(), f.scan.odometric_pose(), f.scan.time());
  other_laser.log_index = f.scan.log_index;
  other_laser.SetCorrectedPose(f.scan.corrected_pose());
  std::vector<LaserScan> other_bases;
  for (const LaserScan& b : f.bases) {
    other_bases.emplace_back(wider_ptr, b.ranges_ptr(), b.odometric_pose(), b.time());
    other_bases.back().log_index = b.log_index;
  }
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, other_laser,
                      {&other_bases[0], &other_bases[1], &other_bases[2]}, Penalize::kYes, Refine::kYes));
  // One ulp of the scan's pose, of a base pose, the base order and the log index all count.
  // (The copied bases carry the interning hint of the originals: a stale hint must not count.)
  LaserScan moved = f.scan;
  moved.SetSensorPose({std::nextafter(f.scan.SensorPose().x, 1.0), f.scan.SensorPose().y, f.scan.SensorPose().theta});
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, moved, f.base_ptrs, Penalize::kYes, Refine::kYes));
  std::vector<LaserScan> bases = f.bases;
  bases[1].SetSensorPose({0.2, 0, std::nextafter(0.0, 1.0)});
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, f.scan, {&bases[0], &bases[1], &bases[2]}, Penalize::kYes,
                      Refine::kYes));
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, f.scan, {f.base_ptrs[1], f.base_ptrs[0], f.base_ptrs[2]},
                      Penalize::kYes, Refine::kYes));
  LaserScan renumbered = f.scan;
  renumbered.log_index = 4;
  EXPECT_NE(base, key(MatchRole::kSequential, f.options, renumbered, f.base_ptrs, Penalize::kYes, Refine::kYes));
  // Same readings data, a copied scan: same key.
  const LaserScan copy = f.scan;
  EXPECT_EQ(base, key(MatchRole::kSequential, f.options, copy, f.base_ptrs, Penalize::kYes, Refine::kYes));
}

// Base scans of another laser (docs/engine.md §3.5) are keyed with their own geometry, not
// bypassed: the same geometry in another object gives the same key, another geometry another.
TEST(MatchCache, BaseScansOfAnotherLaserAreKeyedByTheirGeometry) {
  ScanAndBases f;
  MatchCache cache;
  const auto rebuilt = [&](const LaserGeometry& g) {
    const auto ptr = std::make_shared<const LaserGeometry>(g);
    std::vector<LaserScan> out;
    for (const LaserScan& b : f.bases) {
      out.emplace_back(ptr, b.ranges_ptr(), b.odometric_pose(), b.time());
      out.back().log_index = b.log_index;
    }
    return out;
  };
  const auto key = [&](const std::vector<LaserScan>& bases) {
    std::vector<const LaserScan*> ptrs;
    for (const LaserScan& b : bases) ptrs.push_back(&b);
    return cache.KeyOf(MatchRole::kSequential, f.options, f.scan, ptrs, Penalize::kYes, Refine::kYes);
  };
  LaserGeometry other = f.scan.geometry();
  other.angular_resolution *= 1.5;
  const auto other_key = key(rebuilt(other));
  ASSERT_FALSE(other_key.empty());
  EXPECT_EQ(other_key, key(rebuilt(other)));  // equal words in another object
  EXPECT_NE(other_key, key(rebuilt(f.scan.geometry())));
  LaserGeometry shorter = other;
  shorter.range_threshold = 11.0;
  EXPECT_NE(other_key, key(rebuilt(shorter)));
  // Mixed within one call: the first base of the matched scan's own laser.
  std::vector<LaserScan> mixed = rebuilt(other);
  mixed[0] = f.bases[0];
  EXPECT_NE(other_key, key(mixed));
  EXPECT_EQ(cache.counters().bypassed, 0u);
}

// Base scans are named by interned ids: half a word each, not six.
TEST(MatchCache, KeysAreCompact) {
  std::vector<LaserScan> bases;
  for (int i = 0; i < 70; ++i) bases.push_back(RoomScan({0.01 * i, 0, 0}, i));
  std::vector<const LaserScan*> ptrs;
  for (const LaserScan& b : bases) ptrs.push_back(&b);
  const LaserScan scan = RoomScan({0.7, 0, 0}, 70);
  MatchCache cache;
  const auto key = cache.KeyOf(MatchRole::kSequential, ScanMatcherOptions{}, scan, ptrs, Penalize::kYes, Refine::kYes);
  EXPECT_EQ(key.size(), 10u + 35u);
  EXPECT_EQ(cache.counters().interned, 70u);
  // The same call again, and through copies of the scans: the same key, no new ids.
  std::vector<LaserScan> copies = bases;
  std::vector<const LaserScan*> copy_ptrs;
  for (const LaserScan& b : copies) copy_ptrs.push_back(&b);
  EXPECT_EQ(key,
            cache.KeyOf(MatchRole::kSequential, ScanMatcherOptions{}, scan, copy_ptrs, Penalize::kYes, Refine::kYes));
  EXPECT_EQ(cache.counters().interned, 70u);
}

// Ids freed by eviction are reused for other scans; keys stay exact: a scan interned under a
// reused id never matches an entry made for the scan that held the id before.
TEST(MatchCache, ReusedIdsNeverServeAnotherScansResult) {
  ScanAndBases f;
  MatchCacheOptions o;
  o.byte_budget = 1;  // every finished entry is evicted, freeing its ids
  MatchCache cache(o);
  ScanMatcher reference(f.options);
  ScanMatcher matcher(f.options);
  std::vector<LaserScan> bases = f.bases;  // keeps the hints of earlier rounds: stale, or reused ids
  for (int round = 0; round < 3; ++round) {
    for (LaserScan& b : bases) {
      const Pose2 p = b.corrected_pose();
      b.SetCorrectedPose({p.x + 0.01 * round, p.y, p.theta});
    }
    const std::vector<const LaserScan*> ptrs = {&bases[0], &bases[1], &bases[2]};
    const MatchResult expected = reference.Match(f.scan, ptrs, Penalize::kYes, Refine::kYes);
    EXPECT_TRUE(
        SameBits(cache.Match(MatchRole::kSequential, matcher, f.scan, ptrs, Penalize::kYes, Refine::kYes), expected));
  }
  const MatchCacheCounters c = cache.counters();
  EXPECT_EQ(c.misses, 3u);
  EXPECT_EQ(c.interned, 0u);
  EXPECT_EQ(c.bytes, 0u);
}

TEST(MatchCache, HitReturnsTheMatchersResult) {
  ScanAndBases f;
  const MatchResult expected = f.FreshMatch(Penalize::kYes, Refine::kYes);
  MatchCache cache;
  ScanMatcher a(f.options);
  ScanMatcher b(f.options);
  EXPECT_TRUE(SameBits(f.CachedMatch(cache, a, Penalize::kYes, Refine::kYes), expected));
  EXPECT_TRUE(SameBits(f.CachedMatch(cache, b, Penalize::kYes, Refine::kYes), expected));
  // Another flag combination is another entry.
  EXPECT_TRUE(SameBits(f.CachedMatch(cache, b, Penalize::kNo, Refine::kNo), f.FreshMatch(Penalize::kNo, Refine::kNo)));
  const MatchCacheCounters c = cache.counters();
  EXPECT_EQ(c.misses, 2u);
  EXPECT_EQ(c.hits, 1u);
  EXPECT_EQ(c.waits, 0u);
  EXPECT_EQ(c.entries, 2u);
  EXPECT_GT(c.bytes, 0u);
}

TEST(MatchCache, ConcurrentRequestsForOneKeyComputeOnce) {
  ScanAndBases f;
  const MatchResult expected = f.FreshMatch(Penalize::kYes, Refine::kYes);
  MatchCache cache;
  constexpr int kThreads = 4;
  std::vector<MatchResult> results(kThreads);
  std::vector<std::thread> threads;
  for (int t = 0; t < kThreads; ++t) {
    threads.emplace_back([&, t] {
      ScanMatcher matcher(f.options);
      results[t] = f.CachedMatch(cache, matcher, Penalize::kYes, Refine::kYes);
    });
  }
  for (std::thread& t : threads) t.join();
  for (const MatchResult& r : results) EXPECT_TRUE(SameBits(r, expected));
  const MatchCacheCounters c = cache.counters();
  EXPECT_EQ(c.misses, 1u);
  EXPECT_EQ(c.hits + c.waits, static_cast<std::uint64_t>(kThreads - 1));
}

TEST(MatchCache, EvictionNeverChangesResults) {
  ScanAndBases f;
  MatchCacheOptions o;
  o.byte_budget = 1;  // every insertion evicts
  MatchCache cache(o);
  ScanMatcher matcher(f.options);
  for (int round = 0; round < 2; ++round) {
    for (Penalize penalize : {Penalize::kNo, Penalize::kYes}) {
      EXPECT_TRUE(
          SameBits(f.CachedMatch(cache, matcher, penalize, Refine::kYes), f.FreshMatch(penalize, Refine::kYes)));
    }
  }
  const MatchCacheCounters c = cache.counters();
  EXPECT_EQ(c.misses, 4u);
  EXPECT_EQ(c.evictions, 4u);
  EXPECT_EQ(c.entries, 0u);
  EXPECT_EQ(c.interned, 0u);
  EXPECT_EQ(c.bytes, 0u);
}

// Eviction drops the least recently used entries: a hit keeps an old entry.
TEST(MatchCache, EvictionKeepsRecentlyUsedEntries) {
  ScanAndBases f;
  ScanMatcher matcher(f.options);
  std::size_t two_entries = 0;
  {
    MatchCache probe;
    f.CachedMatch(probe, matcher, Penalize::kNo, Refine::kNo);
    f.CachedMatch(probe, matcher, Penalize::kYes, Refine::kNo);
    two_entries = probe.counters().bytes;
  }
  MatchCacheOptions o;
  o.byte_budget = two_entries + 8;  // a third entry evicts
  MatchCache cache(o);
  f.CachedMatch(cache, matcher, Penalize::kNo, Refine::kNo);   // A
  f.CachedMatch(cache, matcher, Penalize::kYes, Refine::kNo);  // B
  f.CachedMatch(cache, matcher, Penalize::kNo, Refine::kNo);   // A used again
  f.CachedMatch(cache, matcher, Penalize::kNo, Refine::kYes);  // C: evicts B
  MatchCacheCounters c = cache.counters();
  EXPECT_EQ(c.misses, 3u);
  EXPECT_EQ(c.hits, 1u);
  EXPECT_GE(c.evictions, 1u);
  f.CachedMatch(cache, matcher, Penalize::kNo, Refine::kNo);  // A: still there
  EXPECT_EQ(cache.counters().hits, 2u);
  f.CachedMatch(cache, matcher, Penalize::kYes, Refine::kNo);  // B: gone
  EXPECT_EQ(cache.counters().misses, 4u);
}

// Two runs of the same log sharing a cache: the second is served entirely from it and both
// equal a run without the cache, bit for bit.
TEST(MatchCache, LogRunsWithAndWithoutTheCacheAreIdentical) {
  sim::SimulationOptions so;
  so.world = "office";
  auto log = std::make_shared<io::LaserLog>(sim::Simulate(so).log);
  log->scans.resize(std::min<std::size_t>(log->scans.size(), 120));
  const MapperParams params;
  const RunResult plain = RunLog(log, params);
  SharedWork shared;
  shared.match_cache = std::make_shared<MatchCache>();
  for (int run = 0; run < 2; ++run) {
    LogRunner runner(log, params, shared);
    runner.RunToEnd();
    const auto trajectory = runner.Trajectory();
    ASSERT_EQ(trajectory.size(), plain.trajectory.size());
    for (std::size_t i = 0; i < trajectory.size(); ++i) {
      ASSERT_EQ(trajectory[i].pose, plain.trajectory[i].pose) << "scan " << i << " run " << run;
    }
  }
  const MatchCacheCounters c = shared.match_cache->counters();
  EXPECT_GT(c.misses, 10u);
  EXPECT_EQ(c.hits, c.misses);  // the second run repeated every call of the first
  EXPECT_EQ(c.bypassed, 0u);
}

}  // namespace
}  // namespace slamtune::slam
