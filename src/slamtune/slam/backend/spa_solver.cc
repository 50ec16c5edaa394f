#include "slamtune/slam/backend/spa_solver.h"

#include <Eigen/Core>
#include <cmath>

#include "slamtune/common/karto_math.h"
#include "slamtune/slam/backend/spa_system.h"
#include "slamtune/slam/backend/sparse_cholesky.h"

namespace slamtune::slam {
namespace {

std::vector<SpaNodeFrame> Frames(const std::vector<Pose2>& nodes) {
  std::vector<SpaNodeFrame> frames;
  frames.reserve(nodes.size());
  for (const Pose2& n : nodes) frames.push_back(MakeSpaNodeFrame(n));
  return frames;
}

// Adds the step to every free node; the heading is wrapped once, as the SPA node update does.
void ApplyStep(const Eigen::VectorXd& step, std::vector<Pose2>& nodes) {
  for (std::size_t k = 1; k < nodes.size(); ++k) {
    const Eigen::Index at = 3 * static_cast<Eigen::Index>(k - 1);
    Pose2& n = nodes[k];
    n.x += step(at);
    n.y += step(at + 1);
    n.theta += step(at + 2);
    if (n.theta > kPi) n.theta -= kTwoPi;
    if (n.theta < -kPi) n.theta += kTwoPi;
  }
}

}  // namespace

SolveSummary SpaSolver::Solve(std::vector<Pose2>& nodes, std::span<const Edge> edges) const {
  SolveSummary summary;
  summary.backend = "spa";
  std::vector<SpaNodeFrame> frames = Frames(nodes);
  summary.initial_cost = summary.final_cost = SpaGraphCost(frames, edges);
  const int num_free = static_cast<int>(nodes.size()) - 1;
  if (num_free <= 0 || edges.empty()) {
    summary.termination = "nothing to optimise";
    return summary;
  }
  double cost = summary.initial_cost;
  double lambda = options_.initial_lambda;  // §7.3: reset at every call
  double lambda_increase = 2.0;             // and so is the increase factor

  SpaNormalEquations system(static_cast<int>(nodes.size()), edges);
  SparseCholesky cholesky(system.size(), system.column_starts(), system.row_indices());
  Eigen::VectorXd step;
  summary.termination = "iteration limit";
  for (int iter = 0; iter < options_.max_iterations; ++iter) {
    ++summary.iterations;
    system.Fill(frames, lambda);
    step = system.rhs();
    // On failure CSparse leaves the right-hand side in place and sba goes on with it as the
    // step; the same happens here (the summary notes it).
    if (!cholesky.Solve(system.values(), step.data())) ++summary.cholesky_failures;
    if (step.squaredNorm() < options_.min_squared_step) {
      summary.termination = "step below tolerance";
      break;
    }
    const std::vector<Pose2> old = nodes;
    ApplyStep(step, nodes);
    std::vector<SpaNodeFrame> new_frames = Frames(nodes);
    const double new_cost = SpaGraphCost(new_frames, edges);
    const bool accepted = new_cost < cost;
    if (accepted) {
      cost = new_cost;
      frames = std::move(new_frames);
      lambda *= 0.5;
      ++summary.accepted_steps;
    } else {
      nodes = old;
      lambda *= lambda_increase;
      lambda_increase *= 2.0;
    }
    summary.steps.push_back({new_cost, accepted});
  }
  summary.final_cost = cost;
  summary.updated = summary.accepted_steps > 0;
  return summary;
}

}  // namespace slamtune::slam
