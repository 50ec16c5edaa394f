#include "slamtune/slam/near_chains.h"

#include <deque>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

int ClosestInChain(std::span<const int> chain, std::span<const Pose2> reference_poses, int scan) {
  SLAMTUNE_CHECK(!chain.empty());
  const Pose2& ref = reference_poses[scan];
  int best = chain.front();
  double best_d2 = SquaredDistance(reference_poses[best], ref);
  for (int member : chain) {
    const double d2 = SquaredDistance(reference_poses[member], ref);
    if (d2 < best_d2) {
      best_d2 = d2;
      best = member;
    }
  }
  return best;
}

// §5.4. `processed` marks seeds and chain members already used; the walk over the seed's laser
// includes `scan` itself when it is of that laser (its last scan), which invalidates the chain
// that reaches it.
std::vector<std::vector<int>> FindNearChains(const PoseGraph& graph, std::span<const Pose2> reference_poses,
                                             const ScansByLaser& lasers, int scan, double link_distance) {
  const int n = graph.num_vertices();
  SLAMTUNE_CHECK(static_cast<int>(reference_poses.size()) >= n && lasers.size() >= n);
  const Pose2& ref = reference_poses[scan];
  const double limit = link_distance * link_distance + kKartoTolerance;
  auto inside = [&](int id) { return SquaredDistance(reference_poses[id], ref) < limit; };

  std::vector<std::vector<int>> chains;
  std::vector<char> processed(n, 0);
  for (int seed : NearLinked(graph, reference_poses, scan, link_distance)) {
    if (seed == scan || processed[seed]) continue;
    processed[seed] = 1;
    const std::span<const int> walk = lasers.scans_of(lasers.laser_of(seed));
    const int at = lasers.position(seed);
    bool valid = true;
    std::deque<int> chain;
    for (int k = at - 1; k >= 0; --k) {
      const int candidate = walk[k];
      if (candidate == scan) valid = false;
      if (!inside(candidate)) break;
      chain.push_front(candidate);
      processed[candidate] = 1;
    }
    chain.push_back(seed);
    for (int k = at + 1; k < static_cast<int>(walk.size()); ++k) {
      const int candidate = walk[k];
      if (candidate == scan) valid = false;
      if (!inside(candidate)) break;
      chain.push_back(candidate);
      processed[candidate] = 1;
    }
    if (valid) chains.emplace_back(chain.begin(), chain.end());
  }
  return chains;
}

}  // namespace slamtune::slam
