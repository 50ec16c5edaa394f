// A line-per-event record of a run's scan matches and back-end solves, at full precision, for
// comparing runs (and builds) decision by decision. Format in docs/trace.md.
//
// The trace only observes: Mapper writes an event after each decision it has already made,
// and nothing is computed for the trace alone (a near-chain match proven unable to link is
// reported as such, not computed). Copies of a Mapper share the trace they were given.
#pragma once

#include <Eigen/Core>
#include <cstdio>
#include <string>

#include "slamtune/common/pose2.h"
#include "slamtune/slam/backend/pose_graph_solver.h"

namespace slamtune::slam {

// One scan match as the mapper used it.
struct TracedMatch {
  const char* kind = "";  // sequential, near_chain, loop_coarse, loop_fine
  int log_index = -1;     // log scan index of the scan being matched
  int scan = -1;          // its state id
  int base_first = -1;    // state ids of the first and last scan matched against
  int base_last = -1;
  int base_size = 0;  // how many scans
  Pose2 pose_in;      // sensor pose the search was centred on
  double response = 0.0;
  Pose2 mean;  // sensor pose found
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  const char* decision = "";  // what the mapper did with it (docs/trace.md)
};

class RunTrace {
 public:
  // Opens `path` for writing (truncating); throws InputError when it cannot.
  explicit RunTrace(const std::string& path);
  ~RunTrace();
  RunTrace(const RunTrace&) = delete;
  RunTrace& operator=(const RunTrace&) = delete;

  void WriteMatch(const TracedMatch& match);
  // Solve number `index` (0-based, in run order) over `nodes` nodes and `edges` edges: one
  // "solve" line, then one "step" line per iteration that took a step.
  void WriteSolve(int index, int nodes, int edges, const SolveSummary& summary);
  // Flushes and closes; throws InputError when the data could not be written.
  void Close();

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
};

}  // namespace slamtune::slam
