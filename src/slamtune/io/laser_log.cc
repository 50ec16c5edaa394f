#include "slamtune/io/laser_log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {

const char* RecordKindName(RecordKind kind) {
  switch (kind) {
    case RecordKind::kFlaser: return "FLASER";
    case RecordKind::kRobotLaser1: return "ROBOTLASER1";
    case RecordKind::kRawLaser: return "RAWLASER";
    case RecordKind::kOdom: return "ODOM";
    case RecordKind::kParam: return "PARAM";
    case RecordKind::kComment: return "#";
    case RecordKind::kUnknown: return "unknown";
    case RecordKind::kRosLaserScan: return "LaserScan";
  }
  return "unknown";
}

bool BeamGeometry::SameAs(const BeamGeometry& other, double tolerance_rad) const {
  return readings == other.readings && std::fabs(angle_min - other.angle_min) <= tolerance_rad &&
         std::fabs(angle_max() - other.angle_max()) <= tolerance_rad;
}

std::string BeamGeometry::ToString() const {
  constexpr double kDeg = 180.0 / 3.14159265358979323846;
  return fmt::format("{} beams, {:.2f} .. {:.2f} deg, step {:.4f} deg", readings, angle_min * kDeg, angle_max() * kDeg,
                     angle_increment * kDeg);
}

BeamGeometry GeometryOf(const LaserScanRecord& scan) {
  return {scan.ranges.size(), scan.angle_min, scan.angle_increment};
}

std::size_t CountNoReturns(const LaserScanRecord& scan) {
  return static_cast<std::size_t>(std::count_if(scan.ranges.begin(), scan.ranges.end(), [&](double r) {
    return !std::isfinite(r) || r < 0.0 || r >= scan.max_range;
  }));
}

std::size_t CountRanges(const LaserLog& log) {
  std::size_t n = 0;
  for (const LaserScanRecord& scan : log.scans) {
    for (const double r : scan.ranges) n += std::isfinite(r) && r > scan.range_min && r < scan.max_range;
  }
  return n;
}

std::int64_t StampNs(const LaserScanRecord& scan) {
  if (scan.header_stamp_ns) return *scan.header_stamp_ns;
  return std::llround(scan.ipc_time * 1e9);
}

void RecordingReadOptions::Validate() const {
  if (!(max_odom_gap_s > 0.0 && max_odom_gap_s <= 60.0)) {
    throw InputError("--max-odom-gap = " + FormatExact(max_odom_gap_s) + ": must be in (0, 60] seconds");
  }
  if (laser_offset) {
    const Pose2& o = *laser_offset;
    if (!std::isfinite(o.x) || !std::isfinite(o.y) || !(std::fabs(o.theta) <= 3.14159265358979323846)) {
      throw InputError(
          fmt::format("--laser-offset = {},{},{}: must be finite, yaw in [-pi, pi] rad", o.x, o.y, o.theta));
    }
  }
}

void LogReadOptions::Validate() const {
  recording.Validate();
  if (!(no_return_value >= 0.0) || !std::isfinite(no_return_value)) {
    throw InputError("no_return_value = " + FormatExact(no_return_value) +
                     ": must be 0 (detect from the log) or a positive finite range in metres");
  }
}

}  // namespace slamtune::io
