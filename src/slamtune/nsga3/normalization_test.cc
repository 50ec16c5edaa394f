#include "slamtune/nsga3/normalization.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

constexpr NadirSource kHyper = NadirSource::kHyperplane;
constexpr NadirSource kFront = NadirSource::kFrontWorst;

TEST(Normalization, HyperplaneThroughAxisExtremesGivesInterceptsInAbsoluteCoordinates) {
  // Translated extremes (2,0,0), (0,4,0), (0,0,6) and an interior point; ideal (10, 20, 30).
  const std::vector<std::vector<double>> f = {{12, 20, 30}, {10, 24, 30}, {10, 20, 36}, {11, 21, 31}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2, 3}, NormalizationOptions{});
  EXPECT_THAT(n.hyperplane_rejection, IsEmpty());
  EXPECT_THAT(n.ideal, ElementsAre(10, 20, 30));
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 1, 2));
  ASSERT_EQ(n.nadir.size(), 3u);
  EXPECT_NEAR(n.nadir[0], 12.0, 1e-12);
  EXPECT_NEAR(n.nadir[1], 24.0, 1e-12);
  EXPECT_NEAR(n.nadir[2], 36.0, 1e-12);
  EXPECT_THAT(n.nadir_source, ElementsAre(kHyper, kHyper, kHyper));
  const std::vector<double> g = n.Normalize({11, 21, 31});
  EXPECT_NEAR(g[0], 0.5, 1e-12);
  EXPECT_NEAR(g[1], 0.25, 1e-12);
  EXPECT_NEAR(g[2], 1.0 / 6.0, 1e-12);
}

TEST(Normalization, IdealPointOfEarlierGenerationsIsKept) {
  // Same population as above, but an earlier generation reached f_0 = 9: the ideal stays there
  // and the translated extremes become (3,0,0), (1,4,0), (1,0,6), intercepts 3, 6, 9.
  const std::vector<std::vector<double>> f = {{12, 20, 30}, {10, 24, 30}, {10, 20, 36}, {11, 21, 31}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2, 3}, NormalizationOptions{}, {9, 25, 31});
  EXPECT_THAT(n.ideal, ElementsAre(9, 20, 30));
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 1, 2));
  ASSERT_THAT(n.hyperplane_rejection, IsEmpty());
  EXPECT_NEAR(n.nadir[0], 12.0, 1e-12);
  EXPECT_NEAR(n.nadir[1], 26.0, 1e-12);
  EXPECT_NEAR(n.nadir[2], 39.0, 1e-12);
}

TEST(Normalization, TiltedHyperplaneInterceptsExceedTheExtremeCoordinates) {
  // Extremes (1, 0, 0.9), (0.9, 1, 0), (0, 0.9, 1): the plane sum(f) = 1.9 cuts every axis at 1.9.
  const std::vector<std::vector<double>> f = {{1, 0, 0.9}, {0.9, 1, 0}, {0, 0.9, 1}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.hyperplane_rejection, IsEmpty());
  for (double v : n.nadir) EXPECT_NEAR(v, 1.9, 1e-12);
}

TEST(Normalization, IsInvariantToTheScaleOfEachObjective) {
  const std::vector<std::vector<double>> f = {{1, 0, 0.9}, {0.9, 1, 0}, {0, 0.9, 1}, {0.5, 0.5, 0.5}};
  std::vector<std::vector<double>> scaled = f;
  for (auto& p : scaled) {
    p[1] *= 1e3;
    p[2] *= 1e6;
  }
  const Normalization a = ComputeNormalization(f, {0, 1, 2, 3}, NormalizationOptions{});
  const Normalization b = ComputeNormalization(scaled, {0, 1, 2, 3}, NormalizationOptions{});
  for (std::size_t k = 0; k < f.size(); ++k) {
    const auto ga = a.Normalize(f[k]);
    const auto gb = b.Normalize(scaled[k]);
    for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(ga[i], gb[i], 1e-9);
  }
}

TEST(Normalization, DuplicateExtremePointsFallBackToTheWorstOfTheFront) {
  // (1, 1, 0) minimises the ASF of every axis; the dominated (5, 5, 5) is not in the front.
  const std::vector<std::vector<double>> f = {{1, 1, 0}, {0, 2, 2}, {2, 0, 2}, {5, 5, 5}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 0, 0));
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("duplicate extreme points"));
  EXPECT_THAT(n.nadir, ElementsAre(2, 2, 2));
  EXPECT_THAT(n.nadir_source, ElementsAre(kFront, kFront, kFront));
}

TEST(Normalization, MemberAtTheIdealPointIsExtremeForEveryAxis) {
  // (0, 0) has ASF 0 on both axes (its twin loses the tie), so both extremes coincide.
  const std::vector<std::vector<double>> f = {{0, 0}, {0, 0}, {1, 2}};
  const Normalization n = ComputeNormalization(f, {0, 1}, NormalizationOptions{});
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("duplicate extreme points"));
  // The front's worst equals the ideal, so every range widens to all candidates.
  EXPECT_THAT(n.nadir, ElementsAre(1, 2));
  EXPECT_THAT(n.nadir_source, ElementsAre(NadirSource::kCandidatesWorst, NadirSource::kCandidatesWorst));
}

TEST(Normalization, CollinearExtremePointsAreASingularSystemAndAConstantObjectiveGetsUnitRange) {
  // (1,0,1), (0,1,1), (0.5,0.5,1) lie on one line; objective 2 is constant.
  const std::vector<std::vector<double>> f = {{1, 0, 1}, {0, 1, 1}, {0.5, 0.5, 1}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 1, 2));
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("singular system"));
  EXPECT_THAT(n.nadir, ElementsAre(1, 1, 2));
  EXPECT_THAT(n.nadir_source, ElementsAre(kFront, kFront, NadirSource::kUnitRange));
  EXPECT_THAT(n.Normalize({0.5, 0.5, 1}), ElementsAre(0.5, 0.5, 0.0));
}

TEST(Normalization, NegativeInterceptRejectsTheHyperplane) {
  // Extremes (1,0,0), (0,1,0), (0.6,0.6,0.1): 1.2 + 0.1 b_2 = 1 gives b_2 = -2, intercept -0.5.
  const std::vector<std::vector<double>> f = {{1, 0, 0}, {0, 1, 0}, {0.6, 0.6, 0.1}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 1, 2));
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("intercept 2 = -0.5 is not above min_intercept"));
  EXPECT_THAT(n.nadir, ElementsAre(1, 1, 0.1));
  EXPECT_THAT(n.nadir_source, ElementsAre(kFront, kFront, kFront));
}

TEST(Normalization, InfiniteInterceptRejectsTheHyperplane) {
  // Extremes (1,0,0), (0,1,0), (0.5,0.5,0.1): 1 + 0.1 b_2 = 1 gives b_2 = 0, the plane never
  // meets axis 2.
  const std::vector<std::vector<double>> f = {{1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0.1}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("intercept 2 is not finite"));
  EXPECT_THAT(n.nadir, ElementsAre(1, 1, 0.1));
}

TEST(Normalization, TinyInterceptWidensToTheWorstCandidate) {
  // Axis 0 spans only 1e-7 on the front: its intercept is below min_intercept = 1e-6, and the
  // worst of the front does not help either, so the dominated member (5, 5, 5) sets the range.
  const std::vector<std::vector<double>> f = {{1e-7, 0, 0}, {0, 0.01, 0}, {0, 0, 0.01}, {5, 5, 5}};
  const Normalization n = ComputeNormalization(f, {0, 1, 2}, NormalizationOptions{});
  EXPECT_THAT(n.hyperplane_rejection, HasSubstr("intercept 0"));
  EXPECT_THAT(n.extreme_points, ElementsAre(0, 1, 2));
  EXPECT_THAT(n.nadir, ElementsAre(5, 0.01, 0.01));
  EXPECT_THAT(n.nadir_source, ElementsAre(NadirSource::kCandidatesWorst, kFront, kFront));
  // With a smaller threshold the same population keeps its hyperplane.
  NormalizationOptions loose;
  loose.min_intercept = 1e-9;
  const Normalization m = ComputeNormalization(f, {0, 1, 2}, loose);
  EXPECT_THAT(m.hyperplane_rejection, IsEmpty());
  EXPECT_NEAR(m.nadir[0], 1e-7, 1e-20);
}

TEST(NormalizationOptions, RejectsInvalidValuesNamingTheField) {
  NormalizationOptions o;
  o.asf_off_axis_weight = 0.0;
  EXPECT_THAT([&] { o.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("normalization.asf_off_axis_weight = 0")));
  o = NormalizationOptions{};
  o.min_intercept = -1.0;
  EXPECT_THAT([&] { o.Validate(); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("normalization.min_intercept = -1")));
}

}  // namespace
}  // namespace slamtune::nsga3
