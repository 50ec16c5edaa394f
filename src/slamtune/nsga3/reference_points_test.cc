#include "slamtune/nsga3/reference_points.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

using ::testing::HasSubstr;

TEST(DasDennisCount, MatchesBinomialForSeveralSizes) {
  EXPECT_EQ(DasDennisCount(2, 4), 5u);     // C(5, 4)
  EXPECT_EQ(DasDennisCount(3, 10), 66u);   // C(12, 10)
  EXPECT_EQ(DasDennisCount(3, 12), 91u);   // C(14, 12), Table I of Deb & Jain
  EXPECT_EQ(DasDennisCount(5, 6), 210u);   // Table I
  EXPECT_EQ(DasDennisCount(8, 3), 120u);   // boundary layer of M = 8
  EXPECT_EQ(DasDennisCount(10, 3), 220u);  // boundary layer of M = 10
  EXPECT_EQ(DasDennisCount(15, 2), 120u);  // boundary layer of M = 15
  EXPECT_EQ(DasDennisCount(4, 1), 4u);     // the axes only
}

TEST(DasDennisCount, RejectsInvalidSizes) {
  EXPECT_THAT([] { DasDennisCount(1, 4); }, ::testing::ThrowsMessage<InputError>(HasSubstr("objectives = 1")));
  EXPECT_THAT([] { DasDennisCount(3, 0); }, ::testing::ThrowsMessage<InputError>(HasSubstr("divisions = 0")));
  EXPECT_THAT([] { DasDennisCount(20, 40); }, ::testing::ThrowsMessage<InputError>(HasSubstr("more than")));
}

TEST(DasDennisPoints, AreTheDistinctGridPointsOfTheSimplex) {
  for (auto [m, d] : {std::pair<std::size_t, std::size_t>{2, 4}, {3, 12}, {4, 5}, {6, 3}}) {
    const ReferencePoints points = DasDennisPoints(m, d);
    ASSERT_EQ(points.size(), DasDennisCount(m, d));
    std::set<std::vector<long>> grid;
    for (const auto& w : points) {
      ASSERT_EQ(w.size(), m);
      double sum = 0.0;
      std::vector<long> steps;
      for (double c : w) {
        EXPECT_GE(c, 0.0);
        sum += c;
        const double k = c * static_cast<double>(d);
        EXPECT_NEAR(k, std::round(k), 1e-9) << "component is not a multiple of 1/D";
        steps.push_back(std::lround(k));
      }
      EXPECT_NEAR(sum, 1.0, 1e-12);
      grid.insert(steps);
    }
    EXPECT_EQ(grid.size(), points.size()) << "duplicate reference points for M=" << m << " D=" << d;
  }
}

TEST(LayeredReferencePoints, InsideLayerIsShrunkTowardsTheCentroid) {
  // Table I of the paper: M = 8 uses (3, 2) -> 120 + 36 = 156, M = 15 uses (2, 1) -> 135.
  EXPECT_EQ(LayeredReferencePoints(8, 3, 2).size(), 156u);
  EXPECT_EQ(LayeredReferencePoints(10, 3, 2).size(), 275u);
  EXPECT_EQ(LayeredReferencePoints(15, 2, 1).size(), 135u);
  EXPECT_EQ(LayeredReferencePoints(3, 12, 0).size(), 91u);
  const ReferencePoints points = LayeredReferencePoints(3, 2, 1);
  ASSERT_EQ(points.size(), 6u + 3u);
  for (std::size_t k = 6; k < points.size(); ++k) {
    double sum = 0.0;
    for (double c : points[k]) {
      // Inside points come from the axes e_j: (e_j + 1/3) / 2 has components 2/3 and 1/6.
      EXPECT_TRUE(std::abs(c - 2.0 / 3.0) < 1e-12 || std::abs(c - 1.0 / 6.0) < 1e-12) << c;
      sum += c;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
  }
}

TEST(ValidateReferencePoints, AcceptsDirectionsOffTheSimplex) {
  EXPECT_NO_THROW(ValidateReferencePoints({{2.0, 0.0}, {1.0, 1.0}}, 2, "refs"));
}

TEST(ValidateReferencePoints, RejectsBadPointsNamingFieldAndIndex) {
  EXPECT_THAT([] { ValidateReferencePoints({}, 2, "refs"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("refs: no reference points")));
  EXPECT_THAT(
      [] {
        ValidateReferencePoints({{1.0, 0.0}, {1.0, 0.0, 0.0}}, 2, "refs");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("refs[1] has 3 components, the problem has 2")));
  EXPECT_THAT(
      [] {
        ValidateReferencePoints({{1.0, -0.5}}, 2, "refs");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("refs[0] has component -0.5")));
  EXPECT_THAT(
      [] {
        ValidateReferencePoints({{1.0, NAN}}, 2, "refs");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("must be finite")));
  EXPECT_THAT(
      [] {
        ValidateReferencePoints({{0.0, 0.0}}, 2, "refs");
      },
      ::testing::ThrowsMessage<InputError>(HasSubstr("refs[0] is the zero vector")));
}

}  // namespace
}  // namespace slamtune::nsga3
