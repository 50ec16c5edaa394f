// Karto's pose graph (docs/engine.md §5.1, §5.2, §7.1): one vertex per processed scan
// (vertex id = state id), directed edges old -> new with a constraint label, traversed as
// undirected, and the back-end's node values.
//
// The node values are the solver's own copy of the poses (§7.1): a node is initialised with
// the scan's corrected pose when its vertex is created and afterwards changed only by a
// solve. They are kept here, in the graph value, so that copying the graph copies the whole
// back-end state.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <span>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::slam {

// Why an edge was created (§5.3 steps 1-3, §6.1); kLaserLink: a laser's first scan linked from
// the first scan of each other laser (§3.5).
enum class EdgeKind { kSequential = 0, kRunningBuffer = 1, kNearChain = 2, kLoop = 3, kLaserLink = 4 };
inline constexpr int kNumEdgeKinds = 5;
// "sequential", "running_buffer", "near_chain", "loop", "laser_link"
const char* EdgeKindName(EdgeKind kind);

// The constraint label of an edge (§5.1): measurement z = P1 (-) P2 (LinkMeasurement) and information
// (Rz(-P1.theta) Sigma Rz(-P1.theta)^T)^-1, symmetrised from its upper triangle.
struct Constraint {
  Pose2 measurement;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
};

// open_karto's label: P1 = sensor pose of the source scan, P2 = the match mean (sensor pose).
Constraint MakeConstraint(const Pose2& source_pose, const Pose2& target_pose, const Eigen::Matrix3d& covariance);

// P2 seen from P1 (§5.1), with the arithmetic of Karto's LinkInfo::Update, which builds the
// transform from P1 to the origin and applies it to P2: with R = Rz(-P1.theta) (Karto's
// axis-angle matrix), xy = (-(R P1)) + R P2, each product summed as Karto's Matrix3 * Pose2
// ((m0 x + m1 y) + m2 theta), and theta = normalize(P2.theta + (0 - P1.theta)). The
// subtraction comes after the two rotations, so the result can differ in the last bit from
// Between(P1, P2) = R (P2 - P1); those bits change which loops a long log closes. When P1 is
// exactly the origin the transform is the identity, and when only its position is zero the
// offset is zero, as in Karto's Transform.
Pose2 LinkMeasurement(const Pose2& p1, const Pose2& p2);

// Karto's 3x3 inverse by cofactors (§1.4): when |det| <= 1e-14 it returns the unscaled
// cofactor matrix, as Karto's release builds do.
Eigen::Matrix3d KartoInverse(const Eigen::Matrix3d& m);

struct Edge {
  int source = -1;  // older scan (state id)
  int target = -1;  // newer scan
  EdgeKind kind = EdgeKind::kSequential;
  Constraint constraint;
};

class PoseGraph {
 public:
  // Adds the vertex of the next state id and its solver node, initialised with `node_value`
  // (§3.2 step 9a). Returns the new vertex id.
  int AddVertex(const Pose2& node_value);

  // LinkScans (§5.1): if an edge source -> target already exists (that direction only) the new
  // measurement is dropped and false is returned; otherwise the edge is added with its label.
  bool LinkScans(int source, int target, const Pose2& source_sensor_pose, const Pose2& mean,
                 const Eigen::Matrix3d& covariance, EdgeKind kind);

  bool HasEdge(int source, int target) const;

  int num_vertices() const { return static_cast<int>(incident_.size()); }
  const std::vector<Edge>& edges() const { return edges_; }
  // Indices into edges() of the edges touching `vertex`, in insertion order.
  const std::vector<int>& incident_edges(int vertex) const { return incident_[vertex]; }
  // The other end of edge `edge_index` seen from `vertex`.
  int Neighbour(int edge_index, int vertex) const;

  // Solver node values (§7.1), index = vertex id.
  const std::vector<Pose2>& node_values() const { return node_values_; }
  std::vector<Pose2>& mutable_node_values() { return node_values_; }

  friend bool operator==(const PoseGraph&, const PoseGraph&);

 private:
  std::vector<Edge> edges_;
  std::vector<std::vector<int>> incident_;
  std::vector<Pose2> node_values_;
};

bool operator==(const Edge& a, const Edge& b);

// NearLinked(s, R) of §5.2: breadth-first search from `vertex` over edges in both directions,
// neighbours in edge-insertion order. A vertex is accepted (and expanded) iff the squared
// distance of its reference pose to the reference pose of `vertex` is <= R^2 - 1e-6. Returns
// the accepted vertices in BFS order. `reference_poses` is indexed by vertex id.
std::vector<int> NearLinked(const PoseGraph& graph, std::span<const Pose2> reference_poses, int vertex, double radius);

}  // namespace slamtune::slam
