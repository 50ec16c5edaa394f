// The work that SLAM runs of one log share, handed to a Mapper (or LogRunner) as one value: scan
// matches (match_cache.h), back-end solves (solve_cache.h) and scan barycentres
// (barycenter_cache.h). Runs of the same log that differ only in later decisions repeat each
// other's work verbatim until those decisions differ; with the same caches they compute it once.
//
// Each cache may be null (that work is not shared); the default value shares nothing. Results are
// bit-identical with or without any of them. Copies of a mapper keep the caches of the value it
// was given. A SharedWork must only be given to runs of the same log: the caches name scans by
// their log index.
#pragma once

#include <memory>

#include "slamtune/slam/sharing/barycenter_cache.h"
#include "slamtune/slam/sharing/match_cache.h"
#include "slamtune/slam/sharing/solve_cache.h"

namespace slamtune::slam {

struct SharedWork {
  std::shared_ptr<MatchCache> match_cache;            // every scan match (sequential, near chain, loop)
  std::shared_ptr<SolveCache> solve_cache;            // every back-end solve (CorrectPoses)
  std::shared_ptr<BarycenterCache> barycenter_cache;  // every barycentre a reference pose needs
};

}  // namespace slamtune::slam
