#include "slamtune/slam/backend/spa_system.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace slamtune::slam {
namespace {

using ::testing::ElementsAre;

// e_xy = R_i^T t_j + (-(R_i^T t_i)) - z: the node's world-to-node transform applied to t_j,
// each row summed left to right.
TEST(SpaEdgeError, AppliesTheWorldToNodeTransformOfTheSource) {
  const Pose2 a{-10.300000000000001, 10.57, -2.3300000000000001}, b{-11.83, -15.24, 2.27};
  const Pose2 z{0.25, -0.5, 0.1};
  const double c = std::cos(a.theta), s = std::sin(a.theta);
  const Eigen::Vector3d e = SpaEdgeError(MakeSpaNodeFrame(a), MakeSpaNodeFrame(b), z);
  EXPECT_EQ(e(0), ((c * b.x + s * b.y) + -(c * a.x + s * a.y)) - z.x);
  EXPECT_EQ(e(1), ((-s * b.x + c * b.y) + -(-s * a.x + c * a.y)) - z.y);
  double heading = (b.theta - a.theta) - z.theta;
  if (heading > kPi) heading -= kTwoPi;
  EXPECT_EQ(e(2), heading);
  // Algebraically the same as R^T (t_j - t_i) - z, but not in the last bits.
  EXPECT_NEAR(e(0), c * (b.x - a.x) + s * (b.y - a.y) - z.x, 1e-12);
}

TEST(SpaEdgeError, WrapsTheHeadingOnce) {
  const Eigen::Vector3d e = SpaEdgeError(MakeSpaNodeFrame({0, 0, -3.1}), MakeSpaNodeFrame({0, 0, 3.1}), {0, 0, 0});
  EXPECT_EQ(e(2), 6.2 - kTwoPi);
}

TEST(SpaJacobians, MatchSection72) {
  const Pose2 a{1.0, 2.0, 0.4}, b{3.0, -1.0, 1.1};
  const SpaJacobians j = MakeSpaJacobians(MakeSpaNodeFrame(a), MakeSpaNodeFrame(b));
  const double c = std::cos(0.4), s = std::sin(0.4), dx = 2.0, dy = -3.0;
  Eigen::Matrix3d source, target;
  source << -c, -s, -s * dx + c * dy, s, -c, -c * dx - s * dy, 0, 0, -1;
  target << c, s, 0, -s, c, 0, 0, 0, 1;
  EXPECT_EQ(j.source, source);
  EXPECT_EQ(j.target, target);
  EXPECT_EQ(j.source_t, source.transpose());
  EXPECT_EQ(j.target_t, target.transpose());
}

// Edges 0-1 (node 0 fixed), 1-2, 2-3, 3-1 (stored transposed in column 3 at row 1), 1-3 again.
std::vector<Edge> SmallEdges() {
  std::vector<Edge> edges;
  const std::vector<std::pair<int, int>> ends{{0, 1}, {1, 2}, {2, 3}, {3, 1}, {1, 3}};
  for (const auto& [from, to] : ends) {
    Edge e;
    e.source = from;
    e.target = to;
    e.constraint.measurement = {0.5, 0.1, 0.05};
    e.constraint.information << 40, 2, 1, 2, 30, 0.5, 1, 0.5, 90;
    edges.push_back(e);
  }
  return edges;
}

// Compressed columns of the upper triangle: in each block column, every scalar column lists the
// off-diagonal blocks (rows increasing), then the diagonal block down to the diagonal.
TEST(SpaNormalEquations, CompressedColumnLayoutOfTheUpperTriangle) {
  const std::vector<Edge> edges = SmallEdges();
  SpaNormalEquations system(4, edges);
  EXPECT_EQ(system.size(), 9);
  // Free blocks 0..2 (nodes 1..3); off-diagonal blocks (0,1) and (0,2) and (1,2).
  EXPECT_THAT(system.column_starts(), ElementsAre(0, 1, 3, 6, 10, 15, 21, 28, 36, 45));
  EXPECT_THAT(system.row_indices(),
              ElementsAre(0, 0, 1, 0, 1, 2,                             // block column 0: diagonal only
                          0, 1, 2, 3, 0, 1, 2, 3, 4, 0, 1, 2, 3, 4, 5,  // column 1: block (0,1), diagonal
                          0, 1, 2, 3, 4, 5, 6, 0, 1, 2, 3, 4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 8));
}

// The values equal the dense sum of J^T L J over edges (up to rounding), with the diagonal
// scaled by 1 + lambda, and b = -sum J^T L e.
TEST(SpaNormalEquations, ValuesAreTheGaussNewtonSystemWithScaledDiagonal) {
  const std::vector<Edge> edges = SmallEdges();
  const std::vector<Pose2> poses{{0, 0, 0}, {0.4, 0.2, 0.1}, {1.1, 0.1, 0.2}, {1.4, 0.5, 0.3}};
  std::vector<SpaNodeFrame> frames;
  for (const Pose2& p : poses) frames.push_back(MakeSpaNodeFrame(p));
  SpaNormalEquations system(4, edges);
  const double lambda = 0.25;
  system.Fill(frames, lambda);

  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(9, 9);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(9);
  for (const Edge& e : edges) {
    const SpaJacobians j = MakeSpaJacobians(frames[e.source], frames[e.target]);
    const Eigen::Vector3d err = SpaEdgeError(frames[e.source], frames[e.target], e.constraint.measurement);
    Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(3, 9);
    if (e.source > 0) jac.block<3, 3>(0, 3 * (e.source - 1)) = j.source;
    jac.block<3, 3>(0, 3 * (e.target - 1)) = j.target;
    h += jac.transpose() * e.constraint.information * jac;
    b -= jac.transpose() * e.constraint.information * err;
  }
  for (int k = 0; k < 9; ++k) h(k, k) *= 1.0 + lambda;
  Eigen::MatrixXd got = Eigen::MatrixXd::Zero(9, 9);
  for (int col = 0; col < 9; ++col) {
    for (int p = system.column_starts()[col]; p < system.column_starts()[col + 1]; ++p) {
      got(system.row_indices()[p], col) = system.values()[p];
    }
  }
  const Eigen::MatrixXd upper = h.triangularView<Eigen::Upper>();
  EXPECT_TRUE(got.isApprox(upper, 1e-12)) << got << "\n\n" << upper;
  EXPECT_TRUE(system.rhs().isApprox(b, 1e-12));
}

}  // namespace
}  // namespace slamtune::slam
