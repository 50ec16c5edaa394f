#include "slamtune/slam/testing/ring_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace slamtune::slam::testing {

RingGraph MakeRingGraph(int n, double radius, double sigma_xy, double sigma_theta, unsigned seed) {
  RingGraph ring;
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int k = 0; k < n; ++k) {
    const double a = kTwoPi * k / n;
    ring.truth.push_back({radius * std::cos(a), radius * std::sin(a), NormalizeAngle(a + kPi / 2)});
  }
  ring.initial = ring.truth;
  for (int k = 1; k < n; ++k) {
    ring.initial[k].x += sigma_xy * noise(rng);
    ring.initial[k].y += sigma_xy * noise(rng);
    ring.initial[k].theta = NormalizeAngle(ring.initial[k].theta + sigma_theta * noise(rng));
  }
  for (const Pose2& p : ring.initial) ring.graph.AddVertex(p);
  // Anisotropic, correlated covariance so that the information matrices are not diagonal.
  Eigen::Matrix3d cov;
  cov << 0.02, 0.005, 0.001, 0.005, 0.04, 0.0, 0.001, 0.0, 0.01;
  for (int k = 0; k + 1 < n; ++k) {
    ring.graph.LinkScans(k, k + 1, ring.truth[k], ring.truth[k + 1], cov, EdgeKind::kSequential);
  }
  ring.graph.LinkScans(0, n - 1, ring.truth[0], ring.truth[n - 1], cov, EdgeKind::kLoop);
  return ring;
}

PoseGraph WithBiasedLoop(const RingGraph& ring, int from, int to, const Eigen::Vector2d& bias, double variance) {
  PoseGraph g = ring.graph;
  Pose2 biased = ring.truth[to];
  biased.x += bias.x();
  biased.y += bias.y();
  g.LinkScans(from, to, ring.truth[from], biased, Eigen::Matrix3d::Identity() * variance, EdgeKind::kLoop);
  return g;
}

void ExpectRecoversRing(const std::vector<Pose2>& solved, const RingGraph& ring, double tolerance) {
  ASSERT_EQ(solved.size(), ring.truth.size());
  EXPECT_EQ(solved[0], ring.truth[0]);
  for (std::size_t k = 0; k < solved.size(); ++k) {
    EXPECT_NEAR(solved[k].x, ring.truth[k].x, tolerance) << k;
    EXPECT_NEAR(solved[k].y, ring.truth[k].y, tolerance) << k;
    EXPECT_NEAR(NormalizeAngle(solved[k].theta - ring.truth[k].theta), 0.0, tolerance) << k;
  }
}

}  // namespace slamtune::slam::testing
