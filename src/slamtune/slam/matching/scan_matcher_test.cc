#include "slamtune/slam/matching/scan_matcher.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/slam/matching/reference_scan_matcher.h"
#include "slamtune/slam/testing/log_slice.h"
#include "slamtune/slam/testing/synthetic_room.h"

namespace slamtune::slam {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

ScanMatcherOptions SequentialOptions() { return {}; }  // slam_karto defaults (§4.1 first row)

// slam_karto's loop matcher (§4.1 second row).
ScanMatcherOptions LoopOptions() {
  return {.search_dimension = 8.0, .search_resolution = 0.05, .smear_deviation = 0.03};
}

// slam_toolbox's sequential matcher (§4.1 third row), with its penalties and response expansion.
ScanMatcherOptions ToolboxOptions() {
  return {.search_dimension = 0.5,
          .smear_deviation = 0.1,
          .range_threshold = 20.0,
          .distance_variance_penalty = 0.25,
          .angle_variance_penalty = 1.0,
          .use_response_expansion = true};
}

// Base scans along a short path ending 0.2 m before `truth`, and the scan taken at `truth`
// but placed at truth + perturbation.
struct Scene {
  std::vector<LaserScan> base;
  LaserScan scan;
  std::vector<const LaserScan*> base_ptrs() const {
    std::vector<const LaserScan*> p;
    for (const LaserScan& s : base) p.push_back(&s);
    return p;
  }
};

Scene MakeScene(const Pose2& truth, const Pose2& perturbation, int num_base = 5,
                const std::vector<testing::WallSegment>& walls = testing::AsymmetricRoom(), double no_return = 81.83) {
  const auto laser = testing::CarmenLikeLaser();
  Scene scene{{}, testing::CastScan(walls, laser, truth, no_return)};
  for (int i = num_base; i >= 1; --i) {
    const Pose2 p{truth.x - 0.2 * i * std::cos(truth.theta), truth.y - 0.2 * i * std::sin(truth.theta),
                  truth.theta - 0.02 * i};
    scene.base.push_back(testing::CastScan(walls, laser, p, no_return));
  }
  scene.scan.SetSensorPose({truth.x + perturbation.x, truth.y + perturbation.y, truth.theta + perturbation.theta});
  return scene;
}

void ExpectIdentical(const MatchResult& a, const MatchResult& b) {
  EXPECT_EQ(a.mean.x, b.mean.x);
  EXPECT_EQ(a.mean.y, b.mean.y);
  EXPECT_EQ(a.mean.theta, b.mean.theta);
  EXPECT_EQ(a.response, b.response);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) EXPECT_EQ(a.covariance(i, j), b.covariance(i, j)) << i << "," << j;
  }
}

TEST(ScanMatcherOptions, ValidateNamesFieldValueAndRule) {
  ScanMatcherOptions o;
  EXPECT_NO_THROW(o.Validate());
  EXPECT_NO_THROW(LoopOptions().Validate());
  EXPECT_NO_THROW(ToolboxOptions().Validate());
  o.search_dimension = 0.31;  // 31 cells: odd
  EXPECT_THAT([&] { o.Validate(); },
              ThrowsMessage<InputError>(HasSubstr("search_dimension / search_resolution = 0.31 / 0.01")));
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("even integer")));
  o.search_dimension = 0.305;  // not an integer
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("even integer")));
  o = {};
  o.smear_deviation = 0.001;
  EXPECT_THAT([&] { o.Validate(); },
              ThrowsMessage<InputError>(HasSubstr("smear_deviation = 0.001: must lie in [0.5, 10]")));
  o = {};
  o.search_resolution = -0.01;
  EXPECT_THAT([&] { o.Validate(); },
              ThrowsMessage<InputError>(HasSubstr("search_resolution = -0.01: must be a positive")));
  o = {};
  o.threads = 0;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("threads = 0")));
  o = {};
  o.minimum_angle_penalty = 1.5;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("minimum_angle_penalty = 1.5")));
  o = {};
  o.search_resolution = 0.001;
  o.search_dimension = 0.3;
  o.smear_deviation = 0.003;
  o.range_threshold = 80;
  EXPECT_THAT([&] { o.Validate(); }, ThrowsMessage<InputError>(HasSubstr("more than 2^31")));
  EXPECT_THROW(ScanMatcher{o}, InputError);
}

TEST(ScanMatcher, SequentialRecoversAKnownOffset) {
  const Pose2 truth{4.5, 3.7, 0.4};
  Scene scene = MakeScene(truth, {0.05, -0.03, 0.05});
  ScanMatcher matcher(SequentialOptions());
  const MatchResult r = matcher.Match(scene.scan, scene.base_ptrs(), Penalize::kYes, Refine::kYes);
  EXPECT_NEAR(r.mean.x, truth.x, 0.01);
  EXPECT_NEAR(r.mean.y, truth.y, 0.01);
  EXPECT_NEAR(r.mean.theta, truth.theta, 0.0035);
  EXPECT_GT(r.response, 0.8);
  EXPECT_LE(r.response, 1.0);
  // Positional floor 0.1 (2 rho)^2 scaled by 1/best; the heading variance is the fine one.
  EXPECT_GE(r.covariance(0, 0), 0.1 * 0.02 * 0.02);
  EXPECT_GE(r.covariance(1, 1), 0.1 * 0.02 * 0.02);
  EXPECT_LT(r.covariance(0, 0), 0.01);
  EXPECT_LT(r.covariance(2, 2), 0.001);
}

TEST(ScanMatcher, LoopMatcherRecoversOffsetsWithinACell) {
  const Pose2 truth{3.0, 4.0, -0.6};
  const Pose2 perturbations[] = {{0.05, -0.03, 0.05}, {0.3, -0.2, 2 * 0.0349066}, {1.5, -1.2, 0.2}};
  ScanMatcher matcher(LoopOptions());
  for (const Pose2& d : perturbations) {
    SCOPED_TRACE(ToString(d));
    Scene scene = MakeScene(truth, d, 10);
    const MatchResult r = matcher.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kNo);
    EXPECT_LE(std::fabs(r.mean.x - truth.x), 0.05 + 1e-9);
    EXPECT_LE(std::fabs(r.mean.y - truth.y), 0.05 + 1e-9);
    EXPECT_LE(std::fabs(r.mean.theta - truth.theta), 0.0349066 / 2 + 1e-9);
    EXPECT_GT(r.response, 0.3);
    // No refinement: the heading variance stays 4 (coarse step)^2.
    EXPECT_DOUBLE_EQ(r.covariance(2, 2), 4 * 0.0349066 * 0.0349066);
    EXPECT_GE(r.covariance(0, 0), 0.1 * 0.1 * 0.1);
  }
}

// The base is the scan itself, so at the true pose nearly every point scores 100. The loop
// configuration is used because its coarse lattice contains the search centre (the
// sequential one, 31 cells sampled every second cell from the edge, does not).
TEST(ScanMatcher, ResponseDividesByAllBeamsIncludingInvalidOnes) {
  const Pose2 truth{5.0, 2.0, 1.2};
  Scene scene = MakeScene(truth, {0, 0, 0});
  const LaserScan* self[] = {&scene.scan};
  ScanMatcher matcher(LoopOptions());
  const MatchResult full = matcher.Match(scene.scan, self, Penalize::kNo, Refine::kNo);
  EXPECT_NEAR(full.mean.x, truth.x, 1e-9);
  EXPECT_NEAR(full.mean.y, truth.y, 1e-9);
  EXPECT_GT(full.response, 0.95);
  // The same readings with the second half NaN: those beams are INVALID but still count in
  // the divisor, so the response halves instead of staying near 1.
  std::vector<double> ranges = scene.scan.ranges();
  for (std::size_t i = ranges.size() / 2; i < ranges.size(); ++i) ranges[i] = std::nan("");
  LaserScan half(scene.scan.geometry_ptr(), std::make_shared<const std::vector<double>>(ranges), truth, 0.0);
  const MatchResult r = matcher.Match(half, self, Penalize::kNo, Refine::kNo);
  EXPECT_NEAR(r.mean.x, truth.x, 1e-9);
  EXPECT_LE(r.response, 0.5);
  EXPECT_GT(r.response, 0.45);
}

TEST(ScanMatcher, PenaltiesAreMeasuredFromTheSearchCentre) {
  const Pose2 truth{4.0, 5.0, 0.1};
  // Start 0.1 m off in x (one lattice step of the loop matcher): the coarse pass finds the
  // truth 0.1 m from its centre, where the distance penalty is 1 - 0.2 * 0.1^2 / 0.09 and the
  // heading penalty 1.
  Scene scene = MakeScene(truth, {0, 0, 0});
  const LaserScan base_copy = scene.scan;
  const LaserScan* base[] = {&base_copy};
  scene.scan.SetSensorPose({truth.x + 0.1, truth.y, truth.theta});
  ScanMatcher matcher(LoopOptions());
  const MatchResult plain = matcher.Match(scene.scan, base, Penalize::kNo, Refine::kNo);
  const MatchResult penalised = matcher.Match(scene.scan, base, Penalize::kYes, Refine::kNo);
  EXPECT_NEAR(plain.mean.x, truth.x, 1e-9);
  EXPECT_NEAR(penalised.mean.x, truth.x, 1e-9);
  EXPECT_GT(plain.response, 0.95);
  EXPECT_NEAR(penalised.response, plain.response * (1.0 - 0.2 * 0.1 * 0.1 / 0.09), 1e-9);
  // Refining centres the fine pass on the coarse result: no offset there, no penalty.
  const MatchResult refined = matcher.Match(scene.scan, base, Penalize::kYes, Refine::kYes);
  EXPECT_NEAR(refined.mean.x, truth.x, 1e-9);
  EXPECT_NEAR(refined.response, plain.response, 1e-9);
}

TEST(ScanMatcher, NoOverlapKeepsTheGuessWithMaxVariance) {
  const Pose2 truth{4.0, 5.0, 0.1};
  Scene scene = MakeScene(truth, {0, 0, 0});
  Scene far = MakeScene({4.0, 5.0, 0.1}, {0, 0, 0});
  for (LaserScan& s : far.base) {
    const Pose2 p = s.SensorPose();
    s.SetSensorPose({p.x + 100.0, p.y, p.theta});  // base scans moved far away
  }
  ScanMatcher matcher(SequentialOptions());
  const MatchResult r = matcher.Match(scene.scan, far.base_ptrs(), Penalize::kYes, Refine::kYes);
  EXPECT_EQ(r.response, 0.0);
  EXPECT_NEAR(r.mean.x, truth.x, 1e-12);
  EXPECT_NEAR(r.mean.y, truth.y, 1e-12);
  // The fine headings are not quite symmetric (10 x 0.0034907 != 0.0349066): all tie, and
  // their mean is 2e-7 off the centre.
  EXPECT_NEAR(r.mean.theta, truth.theta, 1e-6);
  EXPECT_EQ(r.covariance(0, 0), 500.0);
  EXPECT_EQ(r.covariance(1, 1), 500.0);
  EXPECT_DOUBLE_EQ(r.covariance(2, 2), 1000 * 0.0034907 * 0.0034907);
  const MatchResult coarse = matcher.Match(scene.scan, far.base_ptrs(), Penalize::kYes, Refine::kNo);
  EXPECT_DOUBLE_EQ(coarse.covariance(2, 2), 4 * 0.0349066 * 0.0349066);
}

TEST(ScanMatcher, ScanWithoutReadingsReturnsItsPose) {
  auto laser = std::make_shared<LaserGeometry>();
  laser->num_readings = 0;
  const LaserScan empty(laser, std::make_shared<const std::vector<double>>(), Pose2{1, 2, 0.3}, 0.0);
  Scene scene = MakeScene({4.0, 5.0, 0.1}, {0, 0, 0});
  ScanMatcher matcher(SequentialOptions());
  const MatchResult r = matcher.Match(empty, scene.base_ptrs(), Penalize::kYes, Refine::kYes);
  EXPECT_EQ(r.mean, (Pose2{1, 2, 0.3}));
  EXPECT_EQ(r.response, 0.0);
  EXPECT_EQ(r.covariance(0, 0), 500.0);
  EXPECT_EQ(r.covariance(1, 1), 500.0);
  EXPECT_DOUBLE_EQ(r.covariance(2, 2), 4 * 0.0349066 * 0.0349066);
}

TEST(ScanMatcher, ResponseExpansionWidensTheHeadingSearch) {
  // Only two pillars are visible; with the scan turned by 0.7 rad no heading within
  // +-0.349 rad overlaps, so the coarse response is 0 and expansion (+20 degrees per try) is
  // needed.
  std::vector<testing::WallSegment> pillar;
  // 0.2 m pillars 3.5 m away at bearings 0 and -1.5 rad: a residual turn of 0.35 rad moves
  // them 1.2 m, beyond the +-0.25 m window plus the 0.2 m smear.
  for (const Eigen::Vector2d& c : {Eigen::Vector2d(3.5, 0.0), Eigen::Vector2d(0.2476, -3.4912)}) {
    const Eigen::Vector2d a = c + Eigen::Vector2d(-0.1, -0.1), b = c + Eigen::Vector2d(0.1, 0.1);
    pillar.push_back({{a.x(), a.y()}, {b.x(), a.y()}});
    pillar.push_back({{b.x(), a.y()}, {b.x(), b.y()}});
    pillar.push_back({{b.x(), b.y()}, {a.x(), b.y()}});
    pillar.push_back({{a.x(), b.y()}, {a.x(), a.y()}});
  }
  const Pose2 truth{0.0, 0.0, 0.0};
  // No-returns as +inf (INVALID): finite far readings could wrap onto the pillars (§4.5).
  Scene scene = MakeScene(truth, {0.0, 0.0, 0.7}, 3, pillar, std::numeric_limits<double>::infinity());
  ScanMatcherOptions o = ToolboxOptions();
  o.use_response_expansion = false;
  ScanMatcher without(o);
  const MatchResult r0 = without.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kYes);
  EXPECT_EQ(r0.response, 0.0) << ToString(r0.mean);
  o.use_response_expansion = true;
  ScanMatcher with(o);
  const MatchResult r1 = with.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kYes);
  EXPECT_GT(r1.response, 0.01);
  EXPECT_NEAR(r1.mean.theta, truth.theta, 0.01);
  ReferenceScanMatcher reference(o);
  ExpectIdentical(r1, reference.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kYes));
}

TEST(ScanMatcher, CopyThenMatchGivesIdenticalResults) {
  Scene first = MakeScene({4.5, 3.7, 0.4}, {0.05, -0.03, 0.05});
  Scene second = MakeScene({7.0, 2.0, 2.0}, {-0.04, 0.06, -0.1});
  ScanMatcher a(SequentialOptions());
  a.Match(first.scan, first.base_ptrs(), Penalize::kYes, Refine::kYes);
  ScanMatcher b = a;
  ScanMatcher c(LoopOptions());
  c = a;
  const MatchResult ra = a.Match(second.scan, second.base_ptrs(), Penalize::kYes, Refine::kYes);
  const MatchResult rb = b.Match(second.scan, second.base_ptrs(), Penalize::kYes, Refine::kYes);
  const MatchResult rc = c.Match(second.scan, second.base_ptrs(), Penalize::kYes, Refine::kYes);
  ExpectIdentical(ra, rb);
  ExpectIdentical(ra, rc);
  ScanMatcher moved = std::move(b);
  ExpectIdentical(ra, moved.Match(second.scan, second.base_ptrs(), Penalize::kYes, Refine::kYes));
}

TEST(ScanMatcher, ReusedGridsGiveTheResultsOfAFreshMatcher) {
  Scene first = MakeScene({4.5, 3.7, 0.4}, {0.05, -0.03, 0.05});
  Scene second = MakeScene({7.0, 2.0, 2.0}, {-0.04, 0.06, -0.1});
  ScanMatcher used(LoopOptions());
  used.Match(first.scan, first.base_ptrs(), Penalize::kNo, Refine::kNo);
  ScanMatcher fresh(LoopOptions());
  ExpectIdentical(used.Match(second.scan, second.base_ptrs(), Penalize::kNo, Refine::kNo),
                  fresh.Match(second.scan, second.base_ptrs(), Penalize::kNo, Refine::kNo));
}

TEST(ScanMatcher, ThreadCountDoesNotChangeResults) {
  Scene scene = MakeScene({3.0, 4.0, -0.6}, {0.7, -0.4, 0.1}, 10);
  ScanMatcherOptions one = LoopOptions();
  one.branch_and_bound = false;  // the exhaustive search is the one spread over threads
  ScanMatcherOptions two = one;
  two.threads = 2;
  ScanMatcher a(one), b(two);
  ExpectIdentical(a.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kNo),
                  b.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kNo));
  ExpectIdentical(a.Match(scene.scan, scene.base_ptrs(), Penalize::kYes, Refine::kYes),
                  b.Match(scene.scan, scene.base_ptrs(), Penalize::kYes, Refine::kYes));
}

TEST(ScanMatcher, BranchAndBoundDoesNotChangeResults) {
  ScanMatcherOptions exhaustive = LoopOptions();
  exhaustive.branch_and_bound = false;
  ScanMatcher pruned(LoopOptions()), full(exhaustive);
  const Pose2 perturbations[] = {{0.0, 0.0, 0.0}, {0.7, -0.4, 0.1}, {-2.5, 1.8, -0.3}, {3.9, 3.9, 0.34}};
  for (const Pose2& d : perturbations) {
    SCOPED_TRACE(ToString(d));
    Scene scene = MakeScene({3.0, 4.0, -0.6}, d, 10);
    ExpectIdentical(pruned.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kNo),
                    full.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kNo));
    ExpectIdentical(pruned.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kYes),
                    full.Match(scene.scan, scene.base_ptrs(), Penalize::kNo, Refine::kYes));
  }
}

// The fast matcher must give the plain transcription's numbers bit for bit.
TEST(ScanMatcher, MatchesReferenceMatcherOnSyntheticScenes) {
  struct Config {
    const char* name;
    ScanMatcherOptions options;
    Penalize penalize;
    Refine refine;
  };
  const Config configs[] = {{"sequential", SequentialOptions(), Penalize::kYes, Refine::kYes},
                            {"near chain", SequentialOptions(), Penalize::kNo, Refine::kYes},
                            {"loop coarse", LoopOptions(), Penalize::kNo, Refine::kNo},
                            {"toolbox", ToolboxOptions(), Penalize::kYes, Refine::kYes}};
  const Pose2 perturbations[] = {{0.0, 0.0, 0.0}, {0.05, -0.03, 0.05}, {-0.11, 0.07, -0.2}, {0.6, 0.9, 0.3}};
  for (const Config& c : configs) {
    ScanMatcher fast(c.options);
    ReferenceScanMatcher reference(c.options);
    for (const Pose2& d : perturbations) {
      SCOPED_TRACE(std::string(c.name) + " " + ToString(d));
      Scene scene = MakeScene({6.5, 5.0, 2.8}, d, 6);
      // Some invalid readings in the matched scan.
      std::vector<double> ranges = scene.scan.ranges();
      for (std::size_t i = 0; i < ranges.size(); i += 23) ranges[i] = std::numeric_limits<double>::infinity();
      ranges[5] = std::nan("");
      LaserScan scan(scene.scan.geometry_ptr(), std::make_shared<const std::vector<double>>(ranges),
                     scene.scan.SensorPose(), 0.0);
      ExpectIdentical(fast.Match(scan, scene.base_ptrs(), c.penalize, c.refine),
                      reference.Match(scan, scene.base_ptrs(), c.penalize, c.refine));
    }
  }
}

// Real data: intel's no-return readings (81.83 m) exercise the linear-index wrap (§4.5).
TEST(ScanMatcher, MatchesReferenceMatcherOnIntelSlice) {
  const std::string path = testing::DatasetPath("intel.clf.gz");
  if (path.empty()) GTEST_SKIP() << "intel.clf.gz not found under SLAMTUNE_DATASETS_DIR";
  const std::vector<LaserScan> scans = testing::ReadLogSlice(path, 120);
  ASSERT_EQ(scans.size(), 120u);
  ScanMatcher sequential(SequentialOptions());
  ReferenceScanMatcher sequential_reference(SequentialOptions());
  ScanMatcher loop(LoopOptions());
  ReferenceScanMatcher loop_reference(LoopOptions());
  for (std::size_t i = 20; i < scans.size(); i += 20) {
    std::vector<const LaserScan*> base;
    for (std::size_t j = i - 20; j < i; j += 2) base.push_back(&scans[j]);
    SCOPED_TRACE("scan " + std::to_string(i));
    ExpectIdentical(sequential.Match(scans[i], base, Penalize::kYes, Refine::kYes),
                    sequential_reference.Match(scans[i], base, Penalize::kYes, Refine::kYes));
    ExpectIdentical(loop.Match(scans[i], base, Penalize::kNo, Refine::kNo),
                    loop_reference.Match(scans[i], base, Penalize::kNo, Refine::kNo));
  }
}

}  // namespace
}  // namespace slamtune::slam
