#include "slamtune/slam/pose_graph.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

namespace slamtune::slam {
namespace {

using ::testing::ElementsAre;

TEST(PoseGraph, EdgeLabelIsRelativePoseAndRotatedCovariance) {
  // §5.1: P1 = (1, 2, 90 deg), P2 = (1, 3, 90 deg): P2 is 1 m straight ahead of P1.
  const Pose2 p1{1, 2, kPi / 2}, p2{1, 3, kPi / 2};
  const Eigen::Matrix3d cov = Eigen::Vector3d(0.1, 0.4, 0.05).asDiagonal();
  const Constraint c = MakeConstraint(p1, p2, cov);
  EXPECT_NEAR(c.measurement.x, 1.0, 1e-12);
  EXPECT_NEAR(c.measurement.y, 0.0, 1e-12);
  EXPECT_NEAR(c.measurement.theta, 0.0, 1e-12);
  // Rotated by -90 deg, x and y variances swap: information diag(1/0.4, 1/0.1, 1/0.05).
  EXPECT_NEAR(c.information(0, 0), 2.5, 1e-9);
  EXPECT_NEAR(c.information(1, 1), 10.0, 1e-9);
  EXPECT_NEAR(c.information(2, 2), 20.0, 1e-9);
  EXPECT_NEAR(c.information(0, 1), 0.0, 1e-9);
  EXPECT_EQ(c.information, c.information.transpose());
}

TEST(PoseGraph, CorrelatedCovarianceRotatesAsSigmaPrimeEqualsRSigmaRt) {
  const Pose2 p1{0, 0, 0.7}, p2{2, 1, -0.4};
  Eigen::Matrix3d cov;
  cov << 0.04, 0.01, 0.0, 0.01, 0.09, 0.0, 0.0, 0.0, 0.003;
  const Constraint c = MakeConstraint(p1, p2, cov);
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  r.topLeftCorner<2, 2>() << std::cos(-0.7), -std::sin(-0.7), std::sin(-0.7), std::cos(-0.7);
  const Eigen::Matrix3d expected = (r * cov * r.transpose()).inverse();
  EXPECT_TRUE(c.information.isApprox(expected, 1e-9)) << c.information << "\n" << expected;
  EXPECT_EQ(c.measurement, Between(p1, p2));
}

// §5.1, Karto's LinkInfo::Update: R = Rz(-P1.theta) is applied to P1 and P2 separately and the
// results subtracted, which rounds differently from R (P2 - P1) on this pair.
TEST(LinkMeasurement, RotatesBothPosesBeforeSubtractingAsKarto) {
  const Pose2 p1{-10.300000000000001, 10.57, -2.3300000000000001};
  const Pose2 p2{-11.83, -15.24, 2.27};
  const double c = std::cos(p1.theta), s = std::sin(p1.theta);
  const double expected_x = -(c * p1.x + s * p1.y) + (c * p2.x + s * p2.y);
  const double expected_y = -(-s * p1.x + c * p1.y) + (-s * p2.x + c * p2.y);
  const Pose2 z = LinkMeasurement(p1, p2);
  EXPECT_EQ(z.x, expected_x);
  EXPECT_EQ(z.y, expected_y);
  EXPECT_EQ(z.theta, NormalizeAngle(p2.theta - p1.theta));
  EXPECT_EQ(z.x, 0x1.3c67c82e4d80ap+4);
  const Pose2 between = Between(p1, p2);  // R (P2 - P1): one ulp away here
  EXPECT_EQ(between.x, 0x1.3c67c82e4d80bp+4);
  EXPECT_NE(z.x, between.x);
  EXPECT_EQ(MakeConstraint(p1, p2, Eigen::Matrix3d::Identity()).measurement, z);
}

TEST(LinkMeasurement, SourceAtTheOriginUsesNoOffset) {
  const Pose2 p2{3.25, -1.5, 2.0};
  EXPECT_EQ(LinkMeasurement(Pose2{}, p2), p2);
  // Position at the origin, heading not: only the rotation applies.
  const Pose2 turned{0.0, 0.0, 0.5};
  const double c = std::cos(0.5), s = std::sin(0.5);
  const Pose2 z = LinkMeasurement(turned, p2);
  EXPECT_EQ(z.x, c * p2.x + s * p2.y);
  EXPECT_EQ(z.y, -s * p2.x + c * p2.y);
  EXPECT_EQ(z.theta, 1.5);
  // The heading difference is normalised.
  EXPECT_NEAR(LinkMeasurement({1, 1, 3.0}, {2, 2, -3.0}).theta, kTwoPi - 6.0, 1e-15);
}

TEST(PoseGraph, KartoInverseReturnsCofactorsWhenSingular) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  m(0, 0) = 2.0;
  m(1, 1) = 3.0;  // det = 0
  const Eigen::Matrix3d inv = KartoInverse(m);
  EXPECT_EQ(inv(2, 2), 6.0);  // unscaled cofactor
  const Eigen::Matrix3d d = Eigen::Vector3d(2.0, 4.0, 8.0).asDiagonal();
  EXPECT_TRUE(KartoInverse(d).isApprox(d.inverse()));
}

TEST(PoseGraph, DuplicateEdgesInTheSameDirectionAreDropped) {
  PoseGraph g;
  for (int i = 0; i < 3; ++i) g.AddVertex({double(i), 0, 0});
  const Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
  EXPECT_TRUE(g.LinkScans(0, 1, {0, 0, 0}, {1, 0, 0}, cov, EdgeKind::kSequential));
  EXPECT_FALSE(g.LinkScans(0, 1, {0, 0, 0}, {5, 0, 0}, cov, EdgeKind::kRunningBuffer));
  EXPECT_TRUE(g.LinkScans(1, 0, {1, 0, 0}, {0, 0, 0}, cov, EdgeKind::kLoop));  // other direction is new
  ASSERT_EQ(g.edges().size(), 2u);
  EXPECT_EQ(g.edges()[0].constraint.measurement.x, 1.0);  // the first measurement is kept
  EXPECT_EQ(g.edges()[0].kind, EdgeKind::kSequential);
  EXPECT_THAT(g.incident_edges(0), ElementsAre(0, 1));
  EXPECT_THAT(g.incident_edges(2), ElementsAre());
  EXPECT_TRUE(g.HasEdge(0, 1));
  EXPECT_FALSE(g.HasEdge(0, 2));
}

TEST(PoseGraph, NodeValuesAreTheSolverCopy) {
  PoseGraph g;
  g.AddVertex({1, 2, 3});
  g.mutable_node_values()[0].x = 5;
  EXPECT_EQ(g.node_values()[0], (Pose2{5, 2, 3}));
  PoseGraph copy = g;
  EXPECT_EQ(copy, g);
  copy.mutable_node_values()[0].x = 6;
  EXPECT_FALSE(copy == g);
}

// NearLinked: distance always to the query; rejected vertices are not expanded; neighbours in
// edge-insertion order.
TEST(NearLinked, BreadthFirstWithinRadiusOfTheQuery) {
  PoseGraph g;
  //                       0          1          2          3           4          5
  std::vector<Pose2> refs{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3.5, 0, 0}, {0, 1, 0}, {1.9, 0.1, 0}};
  for (const Pose2& p : refs) g.AddVertex(p);
  const Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
  g.LinkScans(0, 1, {}, {}, cov, EdgeKind::kSequential);
  g.LinkScans(1, 2, {}, {}, cov, EdgeKind::kSequential);
  g.LinkScans(2, 3, {}, {}, cov, EdgeKind::kSequential);
  g.LinkScans(3, 5, {}, {}, cov, EdgeKind::kSequential);  // 5 is near 0 but reachable only through 3
  g.LinkScans(0, 4, {}, {}, cov, EdgeKind::kLoop);
  EXPECT_THAT(NearLinked(g, refs, 0, 2.5), ElementsAre(0, 1, 4, 2));
  EXPECT_THAT(NearLinked(g, refs, 0, 4.0), ElementsAre(0, 1, 4, 2, 3, 5));
  // Band: d^2 <= R^2 - 1e-6 accepts. Vertex 2 is exactly 2 m away.
  EXPECT_THAT(NearLinked(g, refs, 0, 2.0), ElementsAre(0, 1, 4));
  EXPECT_THAT(NearLinked(g, refs, 0, std::sqrt(4.0 + 1.01e-6)), ElementsAre(0, 1, 4, 2));
  EXPECT_THAT(NearLinked(g, refs, 0, std::sqrt(4.0 + 0.99e-6)), ElementsAre(0, 1, 4));
  // From vertex 2: distances measured to 2, not to the neighbour being expanded.
  EXPECT_THAT(NearLinked(g, refs, 2, 1.2), ElementsAre(2, 1));
}

}  // namespace
}  // namespace slamtune::slam
