#include "slamtune/slam/testing/beam_counts.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "slamtune/common/error.h"

namespace slamtune::slam::testing {

io::LaserLog ThinEveryNthScan(io::LaserLog log, std::size_t period, std::size_t stride) {
  SLAMTUNE_CHECK(period >= 1 && stride >= 2);
  for (std::size_t i = period - 1; i < log.scans.size(); i += period) {
    io::LaserScanRecord& scan = log.scans[i];
    std::vector<double> kept;
    for (std::size_t b = 0; b < scan.ranges.size(); b += stride) kept.push_back(scan.ranges[b]);
    log.total_readings -= scan.ranges.size() - kept.size();
    log.total_no_returns -= scan.no_returns;
    scan.ranges = std::move(kept);
    scan.angle_increment *= static_cast<double>(stride);
    if (scan.angle_max) {
      *scan.angle_max = scan.angle_min + scan.angle_increment * static_cast<double>(scan.ranges.size() - 1);
    }
    scan.no_returns = static_cast<std::size_t>(std::count_if(scan.ranges.begin(), scan.ranges.end(), [&](double r) {
      return !std::isfinite(r) || r < 0.0 || r >= scan.max_range;
    }));
    log.total_no_returns += scan.no_returns;
  }
  return log;
}

}  // namespace slamtune::slam::testing
