// Ground-truth relations for a simulated log, in the spirit of the Freiburg benchmark
// (Kümmerle et al. 2009, "On measuring the accuracy of SLAM algorithms", Auton. Robots 27,
// §4): relative true poses Between(truth(t1), truth(t2)) between pairs of scans, both
// nearby in time (local consistency) and far apart in time but close in space (revisits,
// which only a closed loop gets right).
#pragma once

#include <cstddef>
#include <vector>

#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"

namespace slamtune::sim {

struct RelationSamplingOptions {
  int stride = 5;                       // scans between sampled scans (>= 1); 5 = one per second at 5 Hz
  double local_gap_s = 2.0;             // s: each sampled scan is paired with the first scan this much later, > 0
  double revisit_radius_m = 1.0;        // m: revisit pairs lie at most this far apart, > 0
  double revisit_min_gap_s = 30.0;      // s: ... and at least this far apart in time, > 0
  double revisit_max_angle_deg = 90.0;  // deg: ... and their headings differ by at most this, in (0, 180]

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

struct RelationSample {
  std::vector<io::Relation> relations;  // ordered by the later scan; local pair before revisit pair
  std::size_t local_pairs = 0;
  std::size_t revisit_pairs = 0;
  double longest_revisit_gap_s = 0.0;  // largest t2 - t1 among revisit pairs
};

// Pairs of poses of `truth` (time-ordered). For every stride-th scan j: a local pair (i, j)
// with i the last scan at least local_gap_s before j, and a revisit pair (i, j) with i the
// scan nearest to j in position among the earlier scans that satisfy the revisit rules.
RelationSample SampleRelations(const std::vector<io::TimedPose>& truth, const RelationSamplingOptions& options);

}  // namespace slamtune::sim
