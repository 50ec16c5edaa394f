// Loop-closure candidate search (docs/engine.md §6.2): FindPossibleLoopClosure walks the
// processed scans of one laser (§3.5) in order from a persistent cursor and returns the next
// run of consecutive scans that lie inside r of the current scan, are not graph-linked to it
// within r, are at least g long and are followed by a scan outside r; or, at the end of the
// walk, whatever run is pending, of any length (always empty on the current scan's own laser).
//
// The cursor is shared by all calls of one TryCloseLoop (§6.1), so each run is tried at most
// once; after an accepted closure the caller recomputes `linked` implicitly by calling again
// with the updated graph and reference poses.
#pragma once

#include <span>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/pose_graph.h"

namespace slamtune::slam {

struct LoopSearchOptions {
  double radius = 4.0;          // r = loop_search_maximum_distance (m)
  int minimum_chain_size = 10;  // g = loop_match_minimum_chain_size
};

// §6.2: the candidate test is d^2 < r^2 + 1e-6 and the linked set is NearLinked(scan, r), whose
// test is d^2 <= r^2 - 1e-6. `walk` holds the state ids of one laser's scans in order (all of
// them with one laser); `scan` is the last vertex of `graph`; `*cursor`, an index into `walk`,
// is advanced up to (not past) the out-of-range scan that ends a returned run. An empty result
// ends the search.
std::vector<int> FindPossibleLoopClosure(const PoseGraph& graph, std::span<const Pose2> reference_poses,
                                         std::span<const int> walk, int scan, const LoopSearchOptions& options,
                                         int* cursor);

}  // namespace slamtune::slam
