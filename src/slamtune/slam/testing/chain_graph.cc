#include "slamtune/slam/testing/chain_graph.h"

namespace slamtune::slam::testing {

PoseGraph ChainGraph(const std::vector<Pose2>& refs) {
  PoseGraph g;
  for (const Pose2& p : refs) g.AddVertex(p);
  for (int i = 1; i < static_cast<int>(refs.size()); ++i) {
    g.LinkScans(i - 1, i, {}, {}, Eigen::Matrix3d::Identity(), EdgeKind::kSequential);
  }
  return g;
}

}  // namespace slamtune::slam::testing
