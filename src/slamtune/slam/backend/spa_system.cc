#include "slamtune/slam/backend/spa_system.h"

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

SpaNodeFrame MakeSpaNodeFrame(const Pose2& pose) {
  SpaNodeFrame f;
  f.position << pose.x, pose.y, 1.0;
  f.heading = pose.theta;
  const double c = std::cos(pose.theta), s = std::sin(pose.theta);
  f.world_to_node(0, 0) = c;
  f.world_to_node(1, 1) = c;
  f.world_to_node(0, 1) = s;
  f.world_to_node(1, 0) = -s;
  // Translation column -(R^T t): evaluated as a 2x3 product with a zero third column, the way
  // sba forms it (the zero column contributes an exact +-0).
  f.world_to_node.col(2).setZero();
  f.world_to_node.col(2) = -f.world_to_node * f.position;
  f.rotation_derivative << -s, c, -c, -s;
  return f;
}

Eigen::Matrix<double, 3, 1> SpaEdgeError(const SpaNodeFrame& source, const SpaNodeFrame& target,
                                         const Pose2& measurement) {
  Eigen::Matrix<double, 3, 1> error;
  const Eigen::Vector2d measured_xy(measurement.x, measurement.y);
  // W_i t_j - z: (R_i^T t_j + (-(R_i^T t_i))) - z, summed by Eigen's 2x3 product.
  error.block<2, 1>(0, 0) = source.world_to_node * target.position - measured_xy;
  double heading_error = (target.heading - source.heading) - measurement.theta;
  if (heading_error > kPi) heading_error -= kTwoPi;
  if (heading_error < -kPi) heading_error += kTwoPi;
  error(2) = heading_error;
  return error;
}

double SpaEdgeCost(const Eigen::Matrix<double, 3, 1>& error, const Eigen::Matrix3d& information) {
  return error.dot(information * error);
}

double SpaGraphCost(std::span<const SpaNodeFrame> frames, std::span<const Edge> edges) {
  double cost = 0.0;
  for (const Edge& e : edges) {
    cost += SpaEdgeCost(SpaEdgeError(frames[e.source], frames[e.target], e.constraint.measurement),
                        e.constraint.information);
  }
  return cost;
}

SpaJacobians MakeSpaJacobians(const SpaNodeFrame& source, const SpaNodeFrame& target) {
  SpaJacobians j;
  const Eigen::Matrix<double, 2, 1> offset = (target.position - source.position).head(2);
  const Eigen::Matrix<double, 2, 1> turn = source.rotation_derivative * offset;
  // Source: translation -R^T, heading d(R^T)/dtheta (t_j - t_i) and -1.
  j.source.block<2, 2>(0, 0) = -source.world_to_node.block<2, 2>(0, 0);
  j.source.block<2, 1>(0, 2) = turn;
  j.source.block<1, 2>(2, 0).setZero();
  j.source(2, 2) = -1.0;
  j.source_t = j.source.transpose();
  // Target: translation R^T, heading 1.
  j.target.block<2, 2>(0, 0) = source.world_to_node.block<2, 2>(0, 0);
  j.target.block<2, 1>(0, 2).setZero();
  j.target.block<1, 2>(2, 0).setZero();
  j.target(2, 2) = 1.0;
  j.target_t = j.target.transpose();
  return j;
}

SpaNormalEquations::SpaNormalEquations(int num_nodes, std::span<const Edge> edges)
    : num_free_(std::max(num_nodes - 1, 0)), edges_(edges) {
  BuildPattern();
}

// Block (min, max) of every edge between two free nodes, stored in block column max; rows of a
// column in increasing order, each block once however many edges share it.
void SpaNormalEquations::BuildPattern() {
  std::vector<std::vector<int>> rows_of_column(static_cast<std::size_t>(num_free_));
  slots_.resize(edges_.size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    EdgeSlots& s = slots_[k];
    s.source_block = edges_[k].source - 1;
    s.target_block = edges_[k].target - 1;
    SLAMTUNE_CHECK(s.source_block < num_free_ && s.target_block < num_free_);
    if (s.source_block < 0 || s.target_block < 0) continue;
    s.transposed = s.target_block < s.source_block;
    const int row = std::min(s.source_block, s.target_block), col = std::max(s.source_block, s.target_block);
    rows_of_column[static_cast<std::size_t>(col)].push_back(row);
  }
  block_column_start_.assign(1, 0);
  block_row_.clear();
  for (std::vector<int>& rows : rows_of_column) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    block_row_.insert(block_row_.end(), rows.begin(), rows.end());
    block_column_start_.push_back(static_cast<int>(block_row_.size()));
  }
  for (EdgeSlots& s : slots_) {
    if (s.source_block < 0 || s.target_block < 0) continue;
    const int row = std::min(s.source_block, s.target_block), col = std::max(s.source_block, s.target_block);
    const auto first = block_row_.begin() + block_column_start_[static_cast<std::size_t>(col)];
    const auto last = block_row_.begin() + block_column_start_[static_cast<std::size_t>(col) + 1];
    s.off_diagonal = static_cast<int>(std::lower_bound(first, last, row) - block_row_.begin());
  }
  off_diagonal_.assign(block_row_.size(), Eigen::Matrix3d::Zero());
  diagonal_.assign(static_cast<std::size_t>(num_free_), Eigen::Matrix3d::Zero());

  // Compressed columns: per scalar column, the off-diagonal blocks' three rows, then the
  // diagonal block's rows up to the diagonal.
  column_starts_.clear();
  row_indices_.clear();
  for (int col_block = 0; col_block < num_free_; ++col_block) {
    for (int k = 0; k < 3; ++k) {
      column_starts_.push_back(static_cast<int>(row_indices_.size()));
      for (int b = block_column_start_[col_block]; b < block_column_start_[col_block + 1]; ++b) {
        for (int j = 0; j < 3; ++j) row_indices_.push_back(3 * block_row_[static_cast<std::size_t>(b)] + j);
      }
      for (int kk = 0; kk <= k; ++kk) row_indices_.push_back(3 * col_block + kk);
    }
  }
  column_starts_.push_back(static_cast<int>(row_indices_.size()));
  values_.assign(row_indices_.size(), 0.0);
  rhs_.setZero(size());
}

void SpaNormalEquations::Fill(std::span<const SpaNodeFrame> frames, double lambda) {
  for (Eigen::Matrix3d& m : diagonal_) m.setZero();
  for (Eigen::Matrix3d& m : off_diagonal_) m.setZero();
  rhs_.setZero(size());
  for (std::size_t k = 0; k < edges_.size(); ++k) {
    const Edge& e = edges_[k];
    const EdgeSlots& s = slots_[k];
    const SpaNodeFrame& source = frames[static_cast<std::size_t>(e.source)];
    const SpaNodeFrame& target = frames[static_cast<std::size_t>(e.target)];
    const Eigen::Matrix<double, 3, 1> error = SpaEdgeError(source, target, e.constraint.measurement);
    const SpaJacobians j = MakeSpaJacobians(source, target);
    const Eigen::Matrix3d& information = e.constraint.information;
    if (s.source_block >= 0) {
      const Eigen::Matrix3d block = j.source_t * information * j.source;
      diagonal_[static_cast<std::size_t>(s.source_block)] += block;
    }
    if (s.target_block >= 0) {
      const Eigen::Matrix3d information_target = information * j.target;
      const Eigen::Matrix3d block = j.target_t * information_target;
      diagonal_[static_cast<std::size_t>(s.target_block)] += block;
      if (s.source_block >= 0) {
        const Eigen::Matrix3d cross = j.source_t * information_target;
        Eigen::Matrix3d& stored = off_diagonal_[static_cast<std::size_t>(s.off_diagonal)];
        if (s.transposed) {
          const Eigen::Matrix3d cross_t = cross.transpose();
          stored += cross_t;
        } else {
          stored += cross;
        }
      }
    }
    if (s.source_block >= 0) rhs_.block<3, 1>(3 * s.source_block, 0) -= j.source_t * information * error;
    if (s.target_block >= 0) rhs_.block<3, 1>(3 * s.target_block, 0) -= j.target_t * information * error;
  }

  const double diagonal_factor = 1.0 + lambda;  // Marquardt scaling of the diagonal entries
  std::size_t p = 0;
  for (int col_block = 0; col_block < num_free_; ++col_block) {
    const Eigen::Matrix3d& diagonal = diagonal_[static_cast<std::size_t>(col_block)];
    for (int k = 0; k < 3; ++k) {
      for (int b = block_column_start_[col_block]; b < block_column_start_[col_block + 1]; ++b) {
        const Eigen::Matrix3d& m = off_diagonal_[static_cast<std::size_t>(b)];
        for (int r = 0; r < 3; ++r) values_[p++] = m(r, k);
      }
      for (int kk = 0; kk <= k; ++kk) values_[p++] = diagonal(kk, k);
      values_[p - 1] *= diagonal_factor;
    }
  }
}

}  // namespace slamtune::slam
