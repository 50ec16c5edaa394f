#include "slamtune/slam/pose_graph.h"

#include <cmath>
#include <deque>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {
namespace {

// Karto's rotation about z by `angle` (Matrix3::FromAxisAngle with axis (0, 0, 1)); the
// (2, 2) entry is (1 - cos) + cos exactly as Karto computes it.
Eigen::Matrix3d RotationZ(double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d r;
  r << c, -s, 0.0, s, c, 0.0, 0.0, 0.0, (1.0 - c) + c;
  return r;
}

// Row-by-column product with the summation order of Karto's Matrix3.
Eigen::Matrix3d Multiply(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) {
  Eigen::Matrix3d out;
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) sum += a(row, k) * b(k, col);
      out(row, col) = sum;
    }
  }
  return out;
}

// Karto's Matrix3 * Pose2: each row summed left to right, heading included.
Pose2 Times(const Eigen::Matrix3d& m, const Pose2& p) {
  return {m(0, 0) * p.x + m(0, 1) * p.y + m(0, 2) * p.theta, m(1, 0) * p.x + m(1, 1) * p.y + m(1, 2) * p.theta,
          m(2, 0) * p.x + m(2, 1) * p.y + m(2, 2) * p.theta};
}

}  // namespace

Pose2 LinkMeasurement(const Pose2& p1, const Pose2& p2) {
  if (p1 == Pose2{}) {  // Karto's Transform of two equal poses: identity, zero offset
    const Pose2 moved = Times(Eigen::Matrix3d::Identity(), p2);
    return {0.0 + moved.x, 0.0 + moved.y, NormalizeAngle(p2.theta + 0.0)};
  }
  const double turn = 0.0 - p1.theta;  // target heading (0) minus source heading
  const Eigen::Matrix3d r = RotationZ(turn);
  double offset_x = 0.0, offset_y = 0.0;
  if (p1.x != 0.0 || p1.y != 0.0) {
    const Pose2 rotated_p1 = Times(r, p1);
    offset_x = 0.0 - rotated_p1.x;
    offset_y = 0.0 - rotated_p1.y;
  }
  const Pose2 rotated_p2 = Times(r, p2);
  return {offset_x + rotated_p2.x, offset_y + rotated_p2.y, NormalizeAngle(p2.theta + turn)};
}

const char* EdgeKindName(EdgeKind kind) {
  switch (kind) {
    case EdgeKind::kSequential: return "sequential";
    case EdgeKind::kRunningBuffer: return "running_buffer";
    case EdgeKind::kNearChain: return "near_chain";
    case EdgeKind::kLoop: return "loop";
    case EdgeKind::kLaserLink: return "laser_link";
  }
  return "?";
}

Eigen::Matrix3d KartoInverse(const Eigen::Matrix3d& m) {
  Eigen::Matrix3d inv;
  inv(0, 0) = m(1, 1) * m(2, 2) - m(1, 2) * m(2, 1);
  inv(0, 1) = m(0, 2) * m(2, 1) - m(0, 1) * m(2, 2);
  inv(0, 2) = m(0, 1) * m(1, 2) - m(0, 2) * m(1, 1);
  inv(1, 0) = m(1, 2) * m(2, 0) - m(1, 0) * m(2, 2);
  inv(1, 1) = m(0, 0) * m(2, 2) - m(0, 2) * m(2, 0);
  inv(1, 2) = m(0, 2) * m(1, 0) - m(0, 0) * m(1, 2);
  inv(2, 0) = m(1, 0) * m(2, 1) - m(1, 1) * m(2, 0);
  inv(2, 1) = m(0, 1) * m(2, 0) - m(0, 0) * m(2, 1);
  inv(2, 2) = m(0, 0) * m(1, 1) - m(0, 1) * m(1, 0);
  const double det = m(0, 0) * inv(0, 0) + m(0, 1) * inv(1, 0) + m(0, 2) * inv(2, 0);
  if (std::fabs(det) <= 1e-14) return inv;  // §1.4: Karto's release behaviour
  const double inv_det = 1.0 / det;
  return inv * inv_det;
}

// §5.1: z = P1 (-) P2 by LinkMeasurement; Sigma' = Rz(-P1.theta) Sigma Rz(-P1.theta)^T; information = Sigma'^-1 with
// the lower triangle copied from the upper one (as slam_karto's SPA adapter does).
Constraint MakeConstraint(const Pose2& source_pose, const Pose2& target_pose, const Eigen::Matrix3d& covariance) {
  Constraint c;
  c.measurement = LinkMeasurement(source_pose, target_pose);
  const Eigen::Matrix3d r = RotationZ(-source_pose.theta);
  const Eigen::Matrix3d rotated = Multiply(Multiply(r, covariance), r.transpose());
  const Eigen::Matrix3d precision = KartoInverse(rotated);
  for (int row = 0; row < 3; ++row) {
    for (int col = row; col < 3; ++col) {
      c.information(row, col) = precision(row, col);
      c.information(col, row) = precision(row, col);
    }
  }
  return c;
}

int PoseGraph::AddVertex(const Pose2& node_value) {
  incident_.emplace_back();
  node_values_.push_back(node_value);
  return num_vertices() - 1;
}

bool PoseGraph::HasEdge(int source, int target) const {
  SLAMTUNE_CHECK(source >= 0 && source < num_vertices());
  for (int e : incident_[source]) {
    if (edges_[e].source == source && edges_[e].target == target) return true;
  }
  return false;
}

bool PoseGraph::LinkScans(int source, int target, const Pose2& source_sensor_pose, const Pose2& mean,
                          const Eigen::Matrix3d& covariance, EdgeKind kind) {
  SLAMTUNE_CHECK(source >= 0 && source < num_vertices() && target >= 0 && target < num_vertices());
  if (HasEdge(source, target)) return false;
  const int index = static_cast<int>(edges_.size());
  edges_.push_back({source, target, kind, MakeConstraint(source_sensor_pose, mean, covariance)});
  incident_[source].push_back(index);
  if (target != source) incident_[target].push_back(index);
  return true;
}

int PoseGraph::Neighbour(int edge_index, int vertex) const {
  const Edge& e = edges_[edge_index];
  return e.source == vertex ? e.target : e.source;
}

bool operator==(const Edge& a, const Edge& b) {
  return a.source == b.source && a.target == b.target && a.kind == b.kind &&
         a.constraint.measurement == b.constraint.measurement && a.constraint.information == b.constraint.information;
}

bool operator==(const PoseGraph& a, const PoseGraph& b) {
  return a.edges_ == b.edges_ && a.incident_ == b.incident_ && a.node_values_ == b.node_values_;
}

std::vector<int> NearLinked(const PoseGraph& graph, std::span<const Pose2> reference_poses, int vertex, double radius) {
  SLAMTUNE_CHECK(vertex >= 0 && vertex < graph.num_vertices());
  SLAMTUNE_CHECK(static_cast<int>(reference_poses.size()) >= graph.num_vertices());
  const Pose2& centre = reference_poses[vertex];
  const double limit = radius * radius - kKartoTolerance;
  std::vector<char> seen(graph.num_vertices(), 0);
  std::deque<int> to_visit{vertex};
  seen[vertex] = 1;
  std::vector<int> accepted;
  while (!to_visit.empty()) {
    const int next = to_visit.front();
    to_visit.pop_front();
    if (SquaredDistance(reference_poses[next], centre) > limit) continue;
    accepted.push_back(next);
    for (int e : graph.incident_edges(next)) {
      const int adjacent = graph.Neighbour(e, next);
      if (!seen[adjacent]) {
        seen[adjacent] = 1;
        to_visit.push_back(adjacent);
      }
    }
  }
  return accepted;
}

}  // namespace slamtune::slam
