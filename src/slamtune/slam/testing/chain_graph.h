// Test fixture: a graph whose vertices form one chain of sequential edges (the chains of the loop
// closure's search).
#pragma once

#include <vector>

#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam::testing {

// Vertices with the given reference poses and sequential edges i-1 -> i.
PoseGraph ChainGraph(const std::vector<Pose2>& refs);

}  // namespace slamtune::slam::testing
