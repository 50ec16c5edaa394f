#include "slamtune/slam/front_end_evidence.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

using ::testing::HasSubstr;

SequentialMatchStep Step(int i, double response, bool edge = false) {
  SequentialMatchStep s;
  s.log_index = 10 * i;
  s.time = 0.5 * i;
  s.response = response;
  s.at_window_edge = edge;
  return s;
}

std::vector<SequentialMatchStep> Steady(int n) {
  std::vector<SequentialMatchStep> steps;
  for (int i = 0; i < n; ++i) steps.push_back(Step(i, 0.8 + 0.01 * (i % 5)));
  return steps;
}

TEST(StepOf, JudgesTheMatchAgainstTheWindowAndTheHeadingRange) {
  MapperParams params;  // window 0.3 m, rho 0.01 m, +-0.349 rad in steps of 0.0349 rad
  ProcessResult r;
  r.sequential_response = 0.7;
  r.sequential_guess = {1.0, 2.0, 0.1};
  r.sequential_mean = {1.05, 1.98, 0.12};
  r.sequential_covariance = Eigen::Matrix3d::Identity() * 0.0004;
  SequentialMatchStep s = StepOf(r, 7, 3.5, params);
  EXPECT_EQ(s.log_index, 7);
  EXPECT_NEAR(s.dx, 0.05, 1e-12);
  EXPECT_NEAR(s.dy, -0.02, 1e-12);
  EXPECT_NEAR(s.dtheta, 0.02, 1e-12);
  EXPECT_NEAR(s.sigma_xy, 0.02, 1e-12);
  EXPECT_FALSE(s.at_window_edge);
  EXPECT_FALSE(s.at_heading_edge);
  r.sequential_mean = {1.0, 2.0 - 0.14, 0.1 - 0.33};
  s = StepOf(r, 7, 3.5, params);
  EXPECT_TRUE(s.at_window_edge);
  EXPECT_TRUE(s.at_heading_edge);
  params.correlation_search_space_dimension = 1.2;  // a wider window holds the same correction
  EXPECT_FALSE(StepOf(r, 7, 3.5, params).at_window_edge);
}

TEST(StepOf, ReadsThePrincipalDeviationsOfTheCovarianceWhateverItsAxes) {
  MapperParams params;
  ProcessResult r;
  r.sequential_response = 0.9;
  r.sequential_guess = {3.0, 4.0, 0.0};
  r.sequential_mean = {3.01, 4.0, 0.0};
  // 0.1 m along the diagonal x = y, 0.01 m across it.
  const double c = std::sqrt(0.5);
  Eigen::Matrix2d rotation;
  rotation << c, -c, c, c;
  const Eigen::Matrix2d xy = rotation * Eigen::Vector2d(0.01, 0.0001).asDiagonal() * rotation.transpose();
  r.sequential_covariance = Eigen::Matrix3d::Identity();
  r.sequential_covariance.topLeftCorner<2, 2>() = xy;
  const SequentialMatchStep s = StepOf(r, 1, 0.2, params);
  EXPECT_NEAR(s.sigma_xy, 0.1, 1e-12);
  EXPECT_NEAR(s.sigma_minor, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(s.x, 3.01);
  EXPECT_DOUBLE_EQ(s.y, 4.0);
  EXPECT_TRUE(IsDegenerate(s, {}));  // ratio 10 >= 5
}

// n matches 0.5 m apart along x, each seeing the corridor's walls only (sigma 0.08 m along, 0.01 across).
std::vector<SequentialMatchStep> Corridor(int n) {
  std::vector<SequentialMatchStep> steps = Steady(n);
  for (int i = 0; i < n; ++i) {
    steps[i].x = 0.5 * i;
    steps[i].sigma_xy = 0.08;
    steps[i].sigma_minor = 0.01;
  }
  return steps;
}

TEST(AssessFrontEnd, ALongDegenerateCorridorPointsAtTheFrontEnd) {
  const FrontEndEvidence e = AssessFrontEnd(Corridor(81));  // 40 m
  EXPECT_EQ(e.degenerate, 81);
  ASSERT_EQ(e.degenerate_stretches.size(), 1u);
  EXPECT_NEAR(e.degenerate_stretches[0].length_m, 40.0, 1e-9);
  EXPECT_EQ(e.degenerate_stretches[0].first_log_index, 0);
  EXPECT_EQ(e.degenerate_stretches[0].last_log_index, 800);
  EXPECT_DOUBLE_EQ(e.degenerate_stretches[0].max_anisotropy, 8.0);
  EXPECT_EQ(e.breaks, 0);
  EXPECT_TRUE(e.points_at_front_end());
  EXPECT_THAT(e.Summary(), HasSubstr("1 stretch where the scans saw structure in one direction only"));
  EXPECT_THAT(e.Summary(), HasSubstr("scans 0-800, 0.0-40.0 s into the log: 40 m"));
}

TEST(AssessFrontEnd, AShortDegenerateRunOrAnIsotropicMatchIsNoEvidence) {
  EXPECT_FALSE(AssessFrontEnd(Corridor(61)).points_at_front_end());  // 30 m < 35 m
  auto steps = Corridor(81);
  for (auto& s : steps) s.sigma_minor = 0.02;  // ratio 4 < 5
  const FrontEndEvidence e = AssessFrontEnd(steps);
  EXPECT_EQ(e.degenerate, 0);
  EXPECT_FALSE(e.points_at_front_end());
}

TEST(AssessFrontEnd, AFewOrdinaryMatchesDoNotSplitADegenerateStretchButManyDo) {
  auto steps = Corridor(101);                                 // 50 m
  for (int i = 50; i < 53; ++i) steps[i].sigma_minor = 0.08;  // 3 ordinary matches: within max_gap
  ASSERT_EQ(AssessFrontEnd(steps).degenerate_stretches.size(), 1u);
  for (int i = 45; i < 58; ++i) steps[i].sigma_minor = 0.08;  // a junction: 2 x ~22 m, each too short
  EXPECT_TRUE(AssessFrontEnd(steps).degenerate_stretches.empty());
}

TEST(AssessFrontEnd, ASteadyRunShowsNothing) {
  const FrontEndEvidence e = AssessFrontEnd(Steady(100));
  EXPECT_EQ(e.matches, 100);
  EXPECT_NEAR(e.median_response, 0.82, 1e-12);
  EXPECT_TRUE(e.stretches.empty());
  EXPECT_FALSE(e.points_at_front_end());
  EXPECT_THAT(e.Summary(), HasSubstr("no sign of a broken sequential match (100 matches"));
}

TEST(AssessFrontEnd, IsolatedOddMatchesAreMinorNotEvidence) {
  auto steps = Steady(100);
  steps[20].at_window_edge = true;  // a bump absorbed at the edge
  steps[50].response = 0.2;         // one poor scan
  steps[51].at_window_edge = true;
  const FrontEndEvidence e = AssessFrontEnd(steps);
  EXPECT_EQ(e.at_edge, 2);
  EXPECT_EQ(e.low_response, 1);
  ASSERT_EQ(e.stretches.size(), 1u);  // 50-51; 20 alone is below min_suspects
  EXPECT_FALSE(e.stretches[0].strong());
  EXPECT_FALSE(e.points_at_front_end());
}

TEST(AssessFrontEnd, AnEdgeHitThatFitsBadlyAndStaysIsABreak) {
  // A wheel slip the search could not follow: the match ran out of heading range, found a
  // poor fit, and the matches after it went on from there.
  auto steps = Steady(100);
  steps[60].at_heading_edge = true;
  steps[60].dtheta = 0.345;
  steps[60].response = 0.07;
  steps[61].dtheta = -0.02;
  steps[90].at_window_edge = true;  // far away: a minor stretch
  steps[91].at_window_edge = true;
  const FrontEndEvidence e = AssessFrontEnd(steps);
  EXPECT_EQ(e.breaks, 1);
  ASSERT_EQ(e.stretches.size(), 2u);
  const SuspectStretch& s = e.stretches[0];
  EXPECT_TRUE(s.strong());
  EXPECT_EQ(s.first_log_index, 600);
  EXPECT_EQ(s.last_log_index, 600);
  EXPECT_EQ(s.suspects, 1);
  EXPECT_DOUBLE_EQ(s.min_response, 0.07);
  EXPECT_FALSE(e.stretches[1].strong());
  EXPECT_TRUE(e.points_at_front_end());
  EXPECT_THAT(e.Summary(), HasSubstr("1 stretch where sequential matching lost its place (scans 600-600, 30.0-30.0 s "
                                     "into the log: 1 match at the search's edge, 1 with a collapsed response "
                                     "(down to 0.07))"));
}

TEST(AssessFrontEnd, AGlitchTheNextMatchesUndoIsNoBreak) {
  auto steps = Steady(100);
  steps[60].at_heading_edge = true;
  steps[60].at_window_edge = true;
  steps[60].dtheta = 0.349;
  steps[60].dx = -0.16;
  steps[60].response = 0.11;
  steps[61].dtheta = -0.28;  // the next match takes the heading back
  steps[61].dx = 0.15;
  const FrontEndEvidence e = AssessFrontEnd(steps);
  EXPECT_EQ(e.breaks, 0);
  EXPECT_FALSE(e.points_at_front_end());
  steps[61].dtheta = -0.1;  // only partly: a break
  EXPECT_TRUE(AssessFrontEnd(steps).points_at_front_end());
  steps[60].response = 0.6;  // a good fit at the edge is a bump absorbed, not a break
  EXPECT_FALSE(AssessFrontEnd(steps).points_at_front_end());
}

TEST(AssessFrontEnd, GapsLongerThanTheLimitSplitStretches) {
  auto steps = Steady(100);
  for (int i : {10, 11, 16, 17}) steps[i].at_window_edge = true;
  FrontEndEvidenceOptions options;
  options.max_gap = 3;  // 11 -> 16 is 4 ordinary steps apart
  EXPECT_EQ(AssessFrontEnd(steps, options).stretches.size(), 2u);
  options.max_gap = 4;
  EXPECT_EQ(AssessFrontEnd(steps, options).stretches.size(), 1u);
}

TEST(AssessFrontEnd, RefusesBadOptionsAndHandlesNoMatches) {
  FrontEndEvidenceOptions bad;
  bad.low_response_fraction = 1.5;
  EXPECT_THROW(AssessFrontEnd(Steady(5), bad), InputError);
  bad = {};
  bad.recovery_matches = 0;
  EXPECT_THROW(bad.Validate(), InputError);
  bad = {};
  bad.recovered_fraction = 1.0;
  EXPECT_THROW(bad.Validate(), InputError);
  bad = {};
  bad.degenerate_anisotropy = 1.0;
  EXPECT_THROW(bad.Validate(), InputError);
  bad = {};
  bad.min_degenerate_length_m = 0.0;
  EXPECT_THROW(bad.Validate(), InputError);
  EXPECT_EQ(AssessFrontEnd({}).Summary(), "front end: no sequential match was made");
}

// Feeds `steps` one by one to a BreakWatch; the index of the first break it confirms and the
// number of steps it needed, or (-1, n).
std::pair<int, int> WatchUntilBreak(const std::vector<SequentialMatchStep>& steps, int min_matches = 20) {
  BreakWatch watch({}, min_matches);
  std::vector<SequentialMatchStep> so_far;
  for (const SequentialMatchStep& step : steps) {
    so_far.push_back(step);
    if (const auto i = watch.Add(so_far)) return {static_cast<int>(*i), static_cast<int>(so_far.size())};
  }
  return {-1, static_cast<int>(steps.size())};
}

TEST(BreakWatch, ConfirmsABreakAsSoonAsItsRecoveryMatchesAreIn) {
  auto steps = Steady(100);
  steps[60].at_heading_edge = true;
  steps[60].dtheta = 0.345;
  steps[60].response = 0.07;
  EXPECT_EQ(AssessFrontEnd(steps).breaks, 1);
  const auto [index, needed] = WatchUntilBreak(steps);
  EXPECT_EQ(index, 60);
  EXPECT_EQ(needed, 64);  // the break and its three recovery matches
}

TEST(BreakWatch, AGlitchUndoneOrASteadyRunIsNeverStopped) {
  auto steps = Steady(100);
  EXPECT_EQ(WatchUntilBreak(steps).first, -1);
  steps[60].at_heading_edge = true;
  steps[60].dtheta = 0.349;
  steps[60].response = 0.11;
  steps[61].dtheta = -0.28;  // taken back by the next match
  EXPECT_EQ(WatchUntilBreak(steps).first, -1);
}

TEST(BreakWatch, EarlyStepsAreJudgedOnceEnoughMatchesGiveAMedian) {
  auto steps = Steady(60);
  steps[5].at_window_edge = true;
  steps[5].dx = 0.15;
  steps[5].response = 0.05;
  const auto [index, needed] = WatchUntilBreak(steps, 20);
  EXPECT_EQ(index, 5);
  EXPECT_EQ(needed, 20);
}

TEST(BreakWatch, TheRunningMedianIsAssessFrontEndsMedianOfThePrefix) {
  // The same verdicts as AssessFrontEnd on each prefix that ends with the step's recovery matches.
  std::vector<SequentialMatchStep> steps;
  // Responses wander, and every 17th match hits the window's edge with a poor fit that stays.
  for (int i = 0; i < 120; ++i) steps.push_back(Step(i, 0.4 + 0.5 * std::fabs(std::sin(0.37 * i)), i % 17 == 0));
  for (SequentialMatchStep& s : steps) {
    if (!s.at_window_edge) continue;
    s.dx = 0.15;
    s.response = 0.02 + 0.001 * s.log_index / 10;
  }
  BreakWatch watch({}, 1);
  std::vector<SequentialMatchStep> so_far;
  std::vector<int> watched;
  for (const SequentialMatchStep& step : steps) {
    so_far.push_back(step);
    if (const auto i = watch.Add(so_far)) watched.push_back(static_cast<int>(*i));
  }
  std::vector<int> direct;
  for (std::size_t i = 0; i + 3 < steps.size(); ++i) {
    std::vector<SequentialMatchStep> prefix(steps.begin(), steps.begin() + static_cast<long>(i) + 4);
    std::vector<double> r;
    for (const auto& p : prefix) r.push_back(p.response);
    std::nth_element(r.begin(), r.begin() + static_cast<long>(r.size() / 2), r.end());
    if (IsBreak(prefix, i, r[r.size() / 2], {})) direct.push_back(static_cast<int>(i));
  }
  ASSERT_FALSE(direct.empty());
  ASSERT_FALSE(watched.empty());
  EXPECT_EQ(watched.front(), direct.front());
}

}  // namespace
}  // namespace slamtune::slam
