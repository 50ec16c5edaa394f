#include "slamtune/optim/evaluation/map_score_cache.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace slamtune::optim {
namespace {

std::vector<slam::LaserScan> Scans(int n) {
  auto geometry = std::make_shared<slam::LaserGeometry>();
  geometry->min_angle = -1.0;
  geometry->angular_resolution = 1.0;
  geometry->num_readings = 3;
  auto ranges = std::make_shared<const std::vector<double>>(std::vector<double>{1.0, 2.0, 3.0});
  std::vector<slam::LaserScan> scans;
  for (int i = 0; i < n; ++i) {
    scans.emplace_back(geometry, ranges, Pose2{0.1 * i, 0.0, 0.0}, 1.0 * i);
    scans.back().log_index = 2 * i;
  }
  return scans;
}

MapScores Scores(double eta) {
  MapScores s;
  s.quality.occupied_ratio = eta;
  s.error.relations_used = 7;
  return s;
}

TEST(MapScoreCache, KeyNamesEveryPoseBitGridOptionAndGeometry) {
  const slam::OccupancyGridOptions params;
  std::vector<slam::LaserScan> scans = Scans(4);
  const auto key = MapScoreCache::KeyOf(params, scans);
  EXPECT_EQ(key, MapScoreCache::KeyOf(params, scans));

  std::vector<slam::LaserScan> moved = scans;
  const Pose2 p = moved[2].corrected_pose();
  moved[2].SetCorrectedPose({std::nextafter(p.x, 1.0), p.y, p.theta});  // one ulp
  EXPECT_NE(key, MapScoreCache::KeyOf(params, moved));

  std::vector<slam::LaserScan> renumbered = scans;
  renumbered[1].log_index = 3;
  EXPECT_NE(key, MapScoreCache::KeyOf(params, renumbered));

  EXPECT_NE(key, MapScoreCache::KeyOf(params, std::vector<slam::LaserScan>(scans.begin(), scans.end() - 1)));

  slam::OccupancyGridOptions finer = params;
  finer.resolution = 0.025;
  EXPECT_NE(key, MapScoreCache::KeyOf(finer, scans));
  slam::OccupancyGridOptions passes = params;
  passes.min_pass_through = params.min_pass_through + 1;
  EXPECT_NE(key, MapScoreCache::KeyOf(passes, scans));

  // Same poses, a laser with another range threshold: other points, another key.
  auto other = std::make_shared<slam::LaserGeometry>(scans[0].geometry());
  other->range_threshold = 2.5;
  std::vector<slam::LaserScan> rethresholded;
  for (const auto& s : scans) {
    rethresholded.emplace_back(other, s.ranges_ptr(), s.odometric_pose(), s.time());
    rethresholded.back().log_index = s.log_index;
  }
  EXPECT_NE(key, MapScoreCache::KeyOf(params, rethresholded));
}

TEST(MapScoreCache, FindsWhatWasInsertedAndCounts) {
  MapScoreCache cache;
  const auto key = MapScoreCache::KeyOf(slam::OccupancyGridOptions{}, Scans(3));
  EXPECT_FALSE(cache.Find(key).has_value());
  cache.Insert(key, Scores(0.25));
  cache.Insert(key, Scores(0.5));  // already there: kept as first stored
  const auto found = cache.Find(key);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(found->quality.occupied_ratio, 0.25);
  EXPECT_EQ(found->error.relations_used, 7u);
  const MapScoreCacheCounters c = cache.counters();
  EXPECT_EQ(c.hits, 1u);
  EXPECT_EQ(c.misses, 1u);
  EXPECT_EQ(c.entries, 1u);
  EXPECT_GT(c.bytes, key.size() * sizeof(std::uint64_t));
}

TEST(MapScoreCache, BudgetStopsStoringButNeverServesWrongScores) {
  MapScoreCache cache(1);  // one byte: nothing fits
  const auto key = MapScoreCache::KeyOf(slam::OccupancyGridOptions{}, Scans(3));
  cache.Insert(key, Scores(0.25));
  EXPECT_FALSE(cache.Find(key).has_value());
  EXPECT_EQ(cache.counters().not_stored, 1u);
  EXPECT_EQ(cache.counters().entries, 0u);
  EXPECT_THROW(MapScoreCache(0), std::exception);
}

}  // namespace
}  // namespace slamtune::optim
