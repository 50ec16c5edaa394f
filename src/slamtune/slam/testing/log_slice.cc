#include "slamtune/slam/testing/log_slice.h"

#include <algorithm>
#include <filesystem>
#include <memory>

#include "slamtune/io/carmen/carmen_reader.h"

namespace slamtune::slam::testing {

std::string DatasetPath(const std::string& file_name) {
#ifdef SLAMTUNE_DATASETS_DIR
  const std::filesystem::path path = std::filesystem::path(SLAMTUNE_DATASETS_DIR) / file_name;
  if (std::filesystem::exists(path)) return path.string();
#endif
  return "";
}

std::vector<LaserScan> ReadLogSlice(const std::string& path, std::size_t max_scans) {
  io::LogReadOptions options;
  options.max_scans = max_scans;
  const io::LaserLog log = io::ReadCarmenLog(path, options);
  std::vector<LaserScan> scans;
  std::shared_ptr<const LaserGeometry> geometry;
  for (const io::LaserScanRecord& record : log.scans) {
    const int n = static_cast<int>(record.ranges.size());
    if (!geometry || geometry->num_readings != n || geometry->min_angle != record.angle_min ||
        geometry->angular_resolution != record.angle_increment || geometry->max_range != record.max_range) {
      auto g = std::make_shared<LaserGeometry>();
      g->min_angle = record.angle_min;
      g->angular_resolution = record.angle_increment;
      g->num_readings = n;
      g->min_range = 0.0;
      g->max_range = record.max_range;
      g->range_threshold = std::clamp(12.0, g->min_range, g->max_range);
      geometry = g;
    }
    scans.emplace_back(geometry, std::make_shared<const std::vector<double>>(record.ranges), record.laser_pose,
                       record.ipc_time);
    scans.back().log_index = static_cast<int>(scans.size()) - 1;
  }
  return scans;
}

}  // namespace slamtune::slam::testing
