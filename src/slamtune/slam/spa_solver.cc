#include "slamtune/slam/spa_solver.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <cmath>

#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// One Gauss-Newton system H dx = b over the free nodes (node 0 fixed), Jacobians of §7.2.
void BuildSystem(const std::vector<Pose2>& nodes, std::span<const Edge> edges, std::vector<Eigen::Triplet<double>>* h,
                 Eigen::VectorXd* b) {
  h->clear();
  b->setZero();
  for (const Edge& e : edges) {
    const Pose2& a = nodes[e.source];
    const Pose2& p = nodes[e.target];
    const Eigen::Vector3d err = EdgeError(a, p, e.constraint.measurement);
    const double c = std::cos(a.theta), s = std::sin(a.theta);
    const double dx = p.x - a.x, dy = p.y - a.y;
    Eigen::Matrix3d ji, jj;
    ji << -c, -s, -s * dx + c * dy,  //
        s, -c, -c * dx - s * dy,     //
        0, 0, -1;
    jj << c, s, 0,  //
        -s, c, 0,   //
        0, 0, 1;
    const Eigen::Matrix3d& lambda = e.constraint.information;
    const int vi = e.source - 1, vj = e.target - 1;  // free-variable block indices
    const Eigen::Matrix3d* jac[2] = {&ji, &jj};
    const int block[2] = {vi, vj};
    for (int r = 0; r < 2; ++r) {
      if (block[r] < 0) continue;
      const Eigen::Matrix3d jt_lambda = jac[r]->transpose() * lambda;
      b->segment<3>(3 * block[r]) -= jt_lambda * err;
      for (int q = 0; q < 2; ++q) {
        if (block[q] < 0) continue;
        const Eigen::Matrix3d hb = jt_lambda * *jac[q];
        for (int row = 0; row < 3; ++row) {
          for (int col = 0; col < 3; ++col) {
            h->emplace_back(3 * block[r] + row, 3 * block[q] + col, hb(row, col));
          }
        }
      }
    }
  }
}

}  // namespace

SolveSummary SpaSolver::Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const {
  SolveSummary summary;
  summary.backend = "spa";
  summary.initial_cost = summary.final_cost = GraphCost(nodes, edges);
  const int num_free = static_cast<int>(nodes.size()) - 1;
  if (num_free <= 0 || edges.empty()) {
    summary.termination = "nothing to optimise";
    return summary;
  }
  const int dim = 3 * num_free;
  double cost = summary.initial_cost;
  double lambda = options_.initial_lambda;  // §7.3: reset at every call
  double mu = 2.0;

  std::vector<Eigen::Triplet<double>> triplets;
  Eigen::VectorXd b(dim);
  SparseMatrix h(dim, dim);
  Eigen::SimplicialLLT<SparseMatrix, Eigen::Lower> cholesky;
  bool analysed = false;
  summary.termination = "iteration limit";
  for (int iter = 0; iter < options_.max_iterations; ++iter) {
    ++summary.iterations;
    BuildSystem(nodes, edges, &triplets, &b);
    h.setFromTriplets(triplets.begin(), triplets.end());
    for (int k = 0; k < dim; ++k) h.coeffRef(k, k) *= 1.0 + lambda;  // Marquardt scaling
    if (!analysed) {
      cholesky.analyzePattern(h);
      analysed = true;
    }
    cholesky.factorize(h);
    if (cholesky.info() != Eigen::Success) {
      summary.termination = "sparse Cholesky failed";
      break;
    }
    const Eigen::VectorXd delta = cholesky.solve(b);
    if (delta.squaredNorm() < options_.min_squared_step) {
      summary.termination = "step below tolerance";
      break;
    }
    const std::vector<Pose2> old = nodes;
    for (int k = 0; k < num_free; ++k) {
      Pose2& n = nodes[k + 1];
      n.x += delta(3 * k);
      n.y += delta(3 * k + 1);
      n.theta += delta(3 * k + 2);
      if (n.theta > kPi) {  // one wrap, as the SPA node update
        n.theta -= kTwoPi;
      } else if (n.theta < -kPi) {
        n.theta += kTwoPi;
      }
    }
    const double new_cost = GraphCost(nodes, edges);
    if (new_cost < cost) {
      cost = new_cost;
      lambda *= 0.5;
      ++summary.accepted_steps;
    } else {
      nodes = old;
      lambda *= mu;
      mu *= 2.0;
    }
  }
  summary.final_cost = cost;
  summary.updated = summary.accepted_steps > 0;
  return summary;
}

}  // namespace slamtune::slam
