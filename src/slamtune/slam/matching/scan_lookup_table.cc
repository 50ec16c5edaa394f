#include "slamtune/slam/matching/scan_lookup_table.h"

#include <cmath>
#include <cstring>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

void ScanLookupTable::Compute(const LaserScan& scan, double angle_center, double angle_offset, double angle_step,
                              const Eigen::Vector2d& grid_origin, double scale, std::int32_t stride) {
  SLAMTUNE_CHECK(angle_step > 0.0);
  const int num_angles = KartoRoundToInt(angle_offset * 2.0 / angle_step) + 1;
  SLAMTUNE_CHECK(num_angles >= 1);
  const std::vector<Eigen::Vector2d>& points = scan.unfiltered_points();
  const std::vector<double>& ranges = scan.ranges();
  num_beams_ = static_cast<int>(points.size());

  // Points in the frame of the scan's current sensor pose: R(-theta) (p - s), evaluated as
  // Karto's inverse transform does (rotation matrix of angle 0 - theta), §4.4.
  const Pose2 sensor = scan.SensorPose();
  const double inv_c = std::cos(0.0 - sensor.theta), inv_s = std::sin(0.0 - sensor.theta);
  local_points_.resize(points.size());
  invalid_.resize(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const double dx = points[i].x() - sensor.x, dy = points[i].y() - sensor.y;
    local_points_[i] = {inv_c * dx - inv_s * dy, inv_s * dx + inv_c * dy};
    invalid_[i] = std::isnan(ranges[i]) || std::isinf(ranges[i]);
  }

  // The tables are a function of exactly these inputs; when every bit repeats the previous
  // call (the near chains of one scan are matched from the same pose), they are kept.
  const double inputs[] = {
      angle_center, angle_offset, angle_step, grid_origin.x(), grid_origin.y(), scale, static_cast<double>(stride)};
  static_assert(sizeof(inputs) == sizeof(inputs_));
  const bool same = computed_ && std::memcmp(inputs, inputs_, sizeof(inputs)) == 0 &&
                    previous_local_points_.size() == local_points_.size() &&
                    std::memcmp(previous_local_points_.data(), local_points_.data(),
                                local_points_.size() * sizeof(Eigen::Vector2d)) == 0 &&
                    previous_invalid_ == invalid_;
  if (same) return;
  std::memcpy(inputs_, inputs, sizeof(inputs));
  previous_local_points_ = local_points_;
  previous_invalid_ = invalid_;
  computed_ = true;

  angles_.resize(static_cast<std::size_t>(num_angles));
  offsets_.resize(static_cast<std::size_t>(num_angles) * points.size());
  const double start_angle = angle_center - angle_offset;
  for (int k = 0; k < num_angles; ++k) {
    const double angle = start_angle + k * angle_step;
    angles_[static_cast<std::size_t>(k)] = angle;
    const double c = std::cos(angle), s = std::sin(angle);
    std::int32_t* out = offsets_.data() + static_cast<std::size_t>(k) * points.size();
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (invalid_[i]) {
        out[i] = kInvalidLookup;
        continue;
      }
      const Eigen::Vector2d& q = local_points_[i];
      const double ox = c * q.x() - s * q.y();
      const double oy = s * q.x() + c * q.y();
      // Karto: WorldToGrid(offset + gridOrigin) = Round(((o + origin) - origin) * scale).
      const double gx = KartoRound(((ox + grid_origin.x()) - grid_origin.x()) * scale);
      const double gy = KartoRound(((oy + grid_origin.y()) - grid_origin.y()) * scale);
      const double linear = gx + gy * static_cast<double>(stride);
      // Karto's 32-bit arithmetic is only defined while the offset fits; beyond that the point
      // is millions of cells away and could never be inside the grid.
      if (!(std::fabs(gx) < 1e9 && std::fabs(gy) < 1e9 && std::fabs(linear) < 2.0e9)) {
        out[i] = kInvalidLookup;
        continue;
      }
      out[i] = static_cast<std::int32_t>(gx) + static_cast<std::int32_t>(gy) * stride;
    }
  }
}

void ScanLookupTable::Partition(std::int64_t min_index, std::int64_t max_index, std::int64_t data_size) {
  const int num_angles = this->num_angles();
  safe_.clear();
  checked_.clear();
  safe_begin_.assign(1, 0);
  checked_begin_.assign(1, 0);
  for (int k = 0; k < num_angles; ++k) {
    for (const std::int32_t o : offsets(k)) {
      if (o == kInvalidLookup) continue;
      if (min_index + o >= 0 && max_index + o < data_size) {
        safe_.push_back(o);
      } else {
        checked_.push_back(o);
      }
    }
    safe_begin_.push_back(safe_.size());
    checked_begin_.push_back(checked_.size());
  }
}

}  // namespace slamtune::slam
