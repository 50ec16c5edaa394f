#include "slamtune/slam/loop_closure.h"

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

std::vector<int> FindPossibleLoopClosure(const PoseGraph& graph, std::span<const Pose2> reference_poses,
                                         std::span<const int> walk, int scan, const LoopSearchOptions& options,
                                         int* cursor) {
  SLAMTUNE_CHECK(cursor != nullptr);
  const int n = graph.num_vertices();
  SLAMTUNE_CHECK(scan >= 0 && scan < n && static_cast<int>(reference_poses.size()) >= n);
  const Pose2& ref = reference_poses[scan];
  std::vector<char> linked(n, 0);
  for (int v : NearLinked(graph, reference_poses, scan, options.radius)) linked[v] = 1;

  const double limit = options.radius * options.radius + kKartoTolerance;
  const auto g = static_cast<std::size_t>(options.minimum_chain_size);
  std::vector<int> chain;
  for (; *cursor < static_cast<int>(walk.size()); ++*cursor) {
    const int candidate = walk[*cursor];
    if (SquaredDistance(reference_poses[candidate], ref) < limit) {
      if (linked[candidate]) {
        chain.clear();  // a linked scan breaks the run (§6.2 item 2)
      } else {
        chain.push_back(candidate);
      }
    } else {
      if (chain.size() >= g) return chain;  // the cursor stays on the out-of-range scan (item 4)
      chain.clear();
    }
  }
  return chain;  // [QUIRK] on another laser's walk a pending run of any length (§6.2)
}

}  // namespace slamtune::slam
