// Chains of scans near a scan (docs/engine.md §5.2, §5.4): the closest member of a chain,
// and FindNearChains, the older passes through the neighbourhood of a new scan that the
// mapper matches against to add near-chain edges (§5.3 step 3).
//
// Chains are lists of state ids in increasing order, all of one laser (§3.5). Distances are
// between reference poses (barycentres by default, §2.2), given as a span indexed by state id.
#pragma once

#include <span>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/pose_graph.h"
#include "slamtune/slam/scans_by_laser.h"

namespace slamtune::slam {

// closest(chain, s) of §5.2: the member with the smallest squared reference distance to
// `scan`, strict <, so the first in chain order wins ties. `chain` must not be empty.
int ClosestInChain(std::span<const int> chain, std::span<const Pose2> reference_poses, int scan);

// FindNearChains(scan) of §5.4 with L = link_scan_maximum_distance: seeds from
// NearLinked(scan, L); each unprocessed seed grows backwards and forwards over the consecutive
// scans of its own laser (`lasers`) while d^2 < L^2 + 1e-6; a chain that would contain `scan`
// is dropped. Chains of any size are returned, in seed order (the caller gates them by g).
std::vector<std::vector<int>> FindNearChains(const PoseGraph& graph, std::span<const Pose2> reference_poses,
                                             const ScansByLaser& lasers, int scan, double link_distance);

}  // namespace slamtune::slam
