// Test fixture: a ring of poses with exact relative constraints (a known graph for the back-ends).
#pragma once

#include <vector>

#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam::testing {

struct RingGraph {
  std::vector<Pose2> truth;    // true poses, node 0 included
  std::vector<Pose2> initial;  // truth perturbed by fixed-seed noise (node 0 exact)
  PoseGraph graph;             // node values = initial; edges i -> i+1 and the loop 0 -> n-1
};

// `n` poses on a circle of radius `radius`, noise of `sigma_xy` m and `sigma_theta` rad.
RingGraph MakeRingGraph(int n, double radius, double sigma_xy, double sigma_theta, unsigned seed);

// `ring.graph` with one more loop edge `from` -> `to` that disagrees with the ring: it measures
// node `to` at its truth moved by `bias` (x, y in m), with covariance `variance` times identity.
PoseGraph WithBiasedLoop(const RingGraph& ring, int from, int to, const Eigen::Vector2d& bias, double variance);

// `solved` (the node values after a back-end's solve) recovers the ring, as gtest expectations:
// node 0 is exactly its truth (the back-ends hold it fixed) and every pose is within `tolerance`
// of its truth in x, y (m) and heading (rad).
void ExpectRecoversRing(const std::vector<Pose2>& solved, const RingGraph& ring, double tolerance);

}  // namespace slamtune::slam::testing
