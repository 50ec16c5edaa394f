// Freiburg benchmark relations (Kümmerle et al. 2009): lines `t1 t2 x y z roll pitch yaw`,
// the relative pose from the pose at t1 to the pose at t2 (2D: x, y, yaw). `#` starts a
// comment line. Timestamps are laser ipc_timestamps of the log.
#pragma once

#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::io {

struct Relation {
  double t1 = 0.0;
  double t2 = 0.0;
  Pose2 delta;           // pose at t2 seen from the pose at t1 (Between(pose(t1), pose(t2)))
  std::size_t line = 0;  // 1-based line in its file (0 when made in memory)
};

// Reads a relations file. Malformed lines (wrong column count, non-numbers, NaN/inf) throw
// InputError "FILE:LINE: what"; empty files give an empty list; unreadable paths throw.
std::vector<Relation> ReadRelations(const std::string& path);

// Writes relations with z = roll = pitch = 0, full double precision. Throws InputError if the
// file cannot be written.
void WriteRelations(const std::string& path, const std::vector<Relation>& relations);

}  // namespace slamtune::io
