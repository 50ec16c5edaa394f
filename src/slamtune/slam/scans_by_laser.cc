#include "slamtune/slam/scans_by_laser.h"

#include "slamtune/common/error.h"

namespace slamtune::slam {

void ScansByLaser::Add(int laser) {
  SLAMTUNE_CHECK(laser >= 0 && laser < kMaxLasers);
  if (laser >= num_lasers()) lists_.resize(static_cast<std::size_t>(laser) + 1);
  std::vector<int>& list = lists_[laser];
  position_.push_back(static_cast<int>(list.size()));
  list.push_back(size());
  laser_of_.push_back(laser);
}

std::span<const int> ScansByLaser::scans_of(int laser) const {
  SLAMTUNE_CHECK(laser >= 0);
  if (laser >= num_lasers()) return {};
  return lists_[laser];
}

}  // namespace slamtune::slam
