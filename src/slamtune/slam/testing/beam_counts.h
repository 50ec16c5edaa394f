// Test helper: a log whose laser changes its beam count from scan to scan, as cheap spinning
// lidars do (docs/recordings.md): some scans keep only every `stride`-th beam, each at its own
// angle, so the log has two beam geometries with exact angles and no reading changed.
#pragma once

#include <cstddef>

#include "slamtune/io/laser_log.h"

namespace slamtune::slam::testing {

// `log` with every `period`-th scan (log indices period - 1, 2 period - 1, ...) thinned to beams
// 0, stride, 2 stride, ... (first angle kept, increment times `stride`, angle_max and the
// reading totals updated). period >= 1, stride >= 2. The beam report is not touched: call
// io::HarmonizeBeams with the policy under test.
io::LaserLog ThinEveryNthScan(io::LaserLog log, std::size_t period, std::size_t stride);

}  // namespace slamtune::slam::testing
