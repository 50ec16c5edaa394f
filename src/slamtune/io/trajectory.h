// Trajectory files: one pose per line, `timestamp x y theta` (s, m, m, rad); `#` comments.
// Used for the simulator's true trajectory, the engine's output and gt-error input.
#pragma once

#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::io {

struct TimedPose {
  double time = 0.0;
  Pose2 pose;
};

// Throws InputError "FILE:LINE: what" on malformed lines or unreadable paths, and at the
// second of two different poses with one timestamp (which one a lookup by time would take is
// arbitrary). A pose repeated exactly is read once.
std::vector<TimedPose> ReadTrajectory(const std::string& path);

// Writes with enough digits to round-trip timestamps (%.6f) and poses (%.9g), whole or not at
// all (atomic_file.h); InputError naming `path` when it cannot be written.
void WriteTrajectory(const std::string& path, const std::vector<TimedPose>& poses);

}  // namespace slamtune::io
