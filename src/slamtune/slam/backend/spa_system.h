// The arithmetic of slam_karto's back-end, sba's SysSPA2d (docs/engine.md §7.2, §7.3):
// residuals, Jacobians and the normal equations of one Levenberg-Marquardt iteration, in the
// order of floating-point operations sba uses, so that a solve gives the same bits.
//
// Why the order matters: the solver runs after every loop closure and its result decides where
// every later scan is matched; a last-bit difference in one solve can decide a later loop on a
// long log (on mit-killian at r 5.90, g 8, p 0.7, algebraically equal variants of this
// arithmetic, the edge measurement and the mean heading close 8 loops where Karto closes 14).
//
// The order, as sba computes it (all with Eigen fixed-size types, whose evaluation order is
// part of the result, so the expressions here keep sba's types and groupings):
//  - each node has a world-to-node transform W = [R^T | -(R^T t)] (2x3), t = (x, y, 1);
//  - residual: e_xy = W_i t_j - z_xy, i.e. R_i^T t_j + (-(R_i^T t_i)), not R_i^T (t_j - t_i);
//    e_theta = (theta_j - theta_i) - z_theta, wrapped once into [-pi, pi];
//  - Jacobians J_i, J_j of §7.2 with their transposes stored;
//  - blocks: H_ii += (J_i^T L) J_i, H_jj += J_j^T (L J_j), H_ij = J_i^T (L J_j), upper triangle only
//    (H_ji^T stored in the upper block when j < i); b_i -= (J_i^T L) e, b_j -= (J_j^T L) e;
//  - the matrix is handed to CSparse in compressed columns: per block column, each of its three
//    columns lists the off-diagonal blocks in increasing row order, then the diagonal block's
//    upper part; the diagonal entry is multiplied by (1 + lambda). Node 0 is fixed (dropped).
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam {

// A node as the SPA system sees it: homogeneous position, heading, world-to-node transform and
// the derivative of R^T by the heading.
struct SpaNodeFrame {
  Eigen::Matrix<double, 3, 1> position;  // (x, y, 1)
  double heading = 0.0;
  Eigen::Matrix<double, 2, 3> world_to_node;  // [R^T | -(R^T t)]
  Eigen::Matrix2d rotation_derivative;        // d(R^T)/d(theta)
};

SpaNodeFrame MakeSpaNodeFrame(const Pose2& pose);

// e of one constraint (§7.2) from the frames of its source and target.
Eigen::Matrix<double, 3, 1> SpaEdgeError(const SpaNodeFrame& source, const SpaNodeFrame& target,
                                         const Pose2& measurement);

// e^T L e with sba's grouping.
double SpaEdgeCost(const Eigen::Matrix<double, 3, 1>& error, const Eigen::Matrix3d& information);

// Sum over edges, in edge order, of e^T L e.
double SpaGraphCost(std::span<const SpaNodeFrame> frames, std::span<const Edge> edges);

// The two Jacobians of a constraint and their transposes.
struct SpaJacobians {
  Eigen::Matrix3d source, source_t, target, target_t;
};
SpaJacobians MakeSpaJacobians(const SpaNodeFrame& source, const SpaNodeFrame& target);

// The normal equations of one iteration over the free nodes (node 0 fixed), in CSparse's
// compressed-column layout (upper triangle). The sparsity pattern depends only on the edges and
// is built once; Fill recomputes the values for new node frames.
class SpaNormalEquations {
 public:
  SpaNormalEquations(int num_nodes, std::span<const Edge> edges);

  // H (diagonal times 1 + lambda) and b = -sum J^T L e for the given frames. Every edge's
  // error is recomputed from the frames (sba reuses the error of the last cost evaluation,
  // which was made at the same frames).
  void Fill(std::span<const SpaNodeFrame> frames, double lambda);

  int size() const { return 3 * num_free_; }                                // rows of H
  const std::vector<int>& column_starts() const { return column_starts_; }  // size() + 1
  const std::vector<int>& row_indices() const { return row_indices_; }
  const std::vector<double>& values() const { return values_; }
  const Eigen::VectorXd& rhs() const { return rhs_; }

 private:
  struct EdgeSlots {
    int source_block = -1;  // free index of the source node, -1 when fixed
    int target_block = -1;
    int off_diagonal = -1;    // index into off_diagonal_, -1 when a node is fixed
    bool transposed = false;  // the stored block is H_ij^T (target block before source block)
  };
  void BuildPattern();

  int num_free_ = 0;
  std::span<const Edge> edges_;
  std::vector<EdgeSlots> slots_;
  // Off-diagonal blocks, grouped by block column, rows increasing inside a column.
  std::vector<int> block_column_start_;  // num_free_ + 1
  std::vector<int> block_row_;           // block row of each off-diagonal block
  std::vector<Eigen::Matrix3d> off_diagonal_;
  std::vector<Eigen::Matrix3d> diagonal_;
  std::vector<int> column_starts_, row_indices_;
  std::vector<double> values_;
  Eigen::VectorXd rhs_;
};

}  // namespace slamtune::slam
