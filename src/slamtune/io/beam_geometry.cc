#include "slamtune/io/beam_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

// Distinct geometries of the log, most scans first (stable: first seen wins a tie).
std::vector<BeamReport::Seen> DistinctGeometries(const LaserLog& log) {
  std::vector<BeamReport::Seen> seen;
  for (const LaserScanRecord& scan : log.scans) {
    const BeamGeometry g = GeometryOf(scan);
    auto it = std::find_if(seen.begin(), seen.end(),
                           [&](const BeamReport::Seen& s) { return s.geometry.SameAs(g, kSameAngleTolerance); });
    if (it == seen.end()) {
      seen.push_back({g, 1});
    } else {
      ++it->scans;
    }
  }
  std::stable_sort(seen.begin(), seen.end(), [](const auto& a, const auto& b) { return a.scans > b.scans; });
  return seen;
}

}  // namespace

std::string BeamAnglesProblem(double first, double increment, std::size_t n) {
  constexpr const char* kHint = "angles must be radians (written in degrees?)";
  const double span = n > 1 ? increment * static_cast<double>(n - 1) : 0.0;
  if (!(std::fabs(first) <= kMaxBeamAngle)) {
    return fmt::format("first beam at {} rad is beyond +-2pi: {}", first, kHint);
  }
  if (!(std::fabs(span) <= kMaxBeamAngle)) {
    return fmt::format("{} beams {} rad apart span {} rad ({:.0f} deg), more than a full turn: {}", n, increment, span,
                       RadToDeg(span), kHint);
  }
  if (!(std::fabs(first + span) <= kMaxBeamAngle)) {
    return fmt::format("last beam at {} rad is beyond +-2pi: {}", first + span, kHint);
  }
  return "";
}

const char* BeamPolicyName(BeamPolicy policy) {
  switch (policy) {
    case BeamPolicy::kNode: return "node";
    case BeamPolicy::kPerGeometry: return "per-geometry";
    case BeamPolicy::kNearestBeam: return "nearest-beam";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

BeamPolicy ParseBeamPolicy(const std::string& text) {
  if (text == "node" || text == "strict") return BeamPolicy::kNode;
  if (text == "per-geometry") return BeamPolicy::kPerGeometry;
  if (text == "nearest-beam" || text == "resample") return BeamPolicy::kNearestBeam;
  throw InputError("--beams '" + text +
                   "': must be 'node' (as the ROS node: scans of another reading count than the "
                   "first are dropped), 'per-geometry' (one Karto laser per beam geometry) or 'nearest-beam' (scans "
                   "resampled onto the most common geometry, an approximation)");
}

std::size_t ExpectedReadings(KartoLaserRule rule, const LaserScanRecord& first) {
  if (!first.angle_max) return first.ranges.size();
  const double min = first.angle_min, max = *first.angle_max, inc = first.angle_increment;
  std::size_t residual = 1;
  if (rule == KartoLaserRule::kSlamToolbox) {
    // laser_utils.cpp, in its float arithmetic on the message's values.
    const float fmin = static_cast<float>(min), fmax = static_cast<float>(max), finc = static_cast<float>(inc);
    const float angular_range = std::fabs(fmax - fmin);
    bool is_360 = std::fabs(angular_range - 2.0 * kPi) < (finc - (std::numeric_limits<float>::epsilon() * 2.0f * kPi));
    if (angular_range > 6.10865 &&
        static_cast<std::size_t>(std::round(angular_range / finc)) + 1 == first.ranges.size()) {
      is_360 = false;
    }
    if (is_360) residual = 0;
  }
  const double steps = std::floor((max - min) / inc + 0.5);  // Karto's math::Round
  if (!(steps >= 0.0 && steps < 1e9)) return 0;
  return static_cast<std::size_t>(steps) + residual;
}

std::size_t ResampleScan(const BeamGeometry& target, LaserScanRecord* scan) {
  const BeamGeometry own = GeometryOf(*scan);
  std::vector<double> out(target.readings, std::numeric_limits<double>::infinity());
  std::size_t outside = target.readings;
  for (std::size_t j = 0; j < target.readings; ++j) {
    const double angle = target.angle_min + static_cast<double>(j) * target.angle_increment;
    if (own.readings == 0) break;
    double index = 0.0;
    if (own.readings > 1 && own.angle_increment != 0.0) {
      index = std::floor((angle - own.angle_min) / own.angle_increment + 0.5);  // a tie takes the later beam
    }
    if (!(index >= 0.0 && index <= static_cast<double>(own.readings - 1))) continue;
    const std::size_t i = static_cast<std::size_t>(index);
    const double own_angle = own.angle_min + static_cast<double>(i) * own.angle_increment;
    const double reach = 0.5 * std::fabs(own.readings > 1 ? own.angle_increment : target.angle_increment) + 1e-9;
    if (std::fabs(own_angle - angle) <= reach) {
      out[j] = scan->ranges[i];
      --outside;
    }
  }
  scan->ranges = std::move(out);
  scan->angle_min = target.angle_min;
  scan->angle_increment = target.angle_increment;
  scan->no_returns = CountNoReturns(*scan);
  return outside;
}

void HarmonizeBeams(BeamPolicy policy, LaserLog* log) {
  SLAMTUNE_CHECK(log != nullptr);
  BeamReport& report = log->beams;
  report = BeamReport{};
  report.policy = BeamPolicyName(policy);
  report.geometries = DistinctGeometries(*log);
  if (log->scans.empty()) return;
  for (auto [rule, count] : {std::pair{KartoLaserRule::kSlamKarto, &report.slam_karto},
                             std::pair{KartoLaserRule::kSlamToolbox, &report.slam_toolbox}}) {
    count->expected = ExpectedReadings(rule, log->scans.front());
    const std::size_t expected = count->expected;
    count->dropped = static_cast<std::size_t>(std::count_if(
        log->scans.begin(), log->scans.end(), [&](const LaserScanRecord& s) { return s.ranges.size() != expected; }));
  }
  if (policy != BeamPolicy::kNearestBeam || report.geometries.size() < 2) return;
  const BeamGeometry reference = report.geometries.front().geometry;
  for (LaserScanRecord& scan : log->scans) {
    const BeamGeometry own = GeometryOf(scan);
    if (own.SameAs(reference, kSameAngleTolerance)) continue;
    log->total_readings -= scan.ranges.size();
    log->total_no_returns -= scan.no_returns;
    report.readings_outside += ResampleScan(reference, &scan);
    ++report.scans_resampled;
    log->total_readings += scan.ranges.size();
    log->total_no_returns += scan.no_returns;
  }
}

}  // namespace slamtune::io
