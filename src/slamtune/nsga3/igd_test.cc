#include "slamtune/nsga3/igd.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "slamtune/nsga3/reference_points.h"

namespace slamtune::nsga3 {
namespace {

TEST(InvertedGenerationalDistance, IsZeroOnTheTargetsAndAveragesNearestDistances) {
  const std::vector<std::vector<double>> z = {{0, 1}, {1, 0}};
  EXPECT_DOUBLE_EQ(InvertedGenerationalDistance(z, z), 0.0);
  // Only (0, 1) obtained: distances 0 and sqrt(2).
  EXPECT_DOUBLE_EQ(InvertedGenerationalDistance(z, {{0, 1}}), std::sqrt(2.0) / 2.0);
  // Extra obtained points never hurt: IGD looks from the targets.
  EXPECT_DOUBLE_EQ(InvertedGenerationalDistance(z, {{0, 1}, {1, 0}, {5, 5}}), 0.0);
  EXPECT_DOUBLE_EQ(InvertedGenerationalDistance(z, {{0, 1.5}, {1.5, 0}}), 0.5);
}

TEST(Targets, LieOnTheDtlzFrontsAlongTheReferenceDirections) {
  const ReferencePoints w = DasDennisPoints(3, 12);
  const auto plane = TargetsOnSimplex(w, 0.5);
  const auto sphere = TargetsOnUnitSphere(w);
  ASSERT_EQ(plane.size(), 91u);
  ASSERT_EQ(sphere.size(), 91u);
  for (std::size_t k = 0; k < w.size(); ++k) {
    EXPECT_NEAR(std::accumulate(plane[k].begin(), plane[k].end(), 0.0), 0.5, 1e-12);
    EXPECT_NEAR(std::inner_product(sphere[k].begin(), sphere[k].end(), sphere[k].begin(), 0.0), 1.0, 1e-12);
    // Same direction: the cross-ratio of the first two components is preserved.
    EXPECT_NEAR(plane[k][0] * w[k][1], plane[k][1] * w[k][0], 1e-12);
    EXPECT_NEAR(sphere[k][0] * w[k][1], sphere[k][1] * w[k][0], 1e-12);
  }
}

}  // namespace
}  // namespace slamtune::nsga3
