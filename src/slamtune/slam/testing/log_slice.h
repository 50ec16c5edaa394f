// Test helper: the first scans of a CARMEN log (e.g. /work/shared/datasets/intel.clf.gz) as
// engine LaserScans at their odometric laser poses, with slam_karto's range threshold
// clip(12, min_range, max_range) and a zero laser offset (docs/engine.md §1.4, §2.3).
#pragma once

#include <string>
#include <vector>

#include "slamtune/slam/laser_scan.h"

namespace slamtune::slam::testing {

// Path of a dataset under SLAMTUNE_DATASETS_DIR, or "" when the file is absent.
std::string DatasetPath(const std::string& file_name);

// Reads at most `max_scans` laser scans of the log at `path`.
std::vector<LaserScan> ReadLogSlice(const std::string& path, std::size_t max_scans);

}  // namespace slamtune::slam::testing
