#include "slamtune/slam/matching/reference_scan_matcher.h"

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

ReferenceScanMatcher::ReferenceScanMatcher(const ScanMatcherOptions& options)
    : options_((options.Validate(), options)),
      grid_(options.search_dimension, options.search_resolution, options.smear_deviation, options.range_threshold),
      probabilities_(grid_.geometry().search_side, options.search_resolution) {}

double ReferenceScanMatcher::Response(int angle_index, std::int32_t cell_index) const {
  const std::span<const std::int32_t> offsets = table_.offsets(angle_index);
  double response = 0.0;
  for (const std::int32_t o : offsets) {
    if (o == kInvalidLookup) continue;
    const std::int64_t index = static_cast<std::int64_t>(cell_index) + o;
    if (index < 0 || index >= grid_.data_size()) continue;
    response += grid_.data()[index];
  }
  response /= static_cast<std::uint32_t>(offsets.size()) * 100u;
  return response;
}

double ReferenceScanMatcher::CorrelateScan(const LaserScan& scan, const Pose2& center, double offset_xy, double step_xy,
                                           double angle_offset, double angle_step, Penalize penalize, Pass pass,
                                           Pose2* mean, Eigen::Matrix3d* cov) {
  table_.Compute(scan, center.theta, angle_offset, angle_step, grid_.roi_origin(), grid_.scale(),
                 grid_.geometry().stride);
  if (pass == Pass::kCoarse) probabilities_.Reset({center.x - offset_xy, center.y - offset_xy});
  const int n = static_cast<int>(KartoRound(offset_xy * 2.0 / step_xy) + 1);
  const int num_angles = KartoRoundToInt(angle_offset * 2.0 / angle_step) + 1;
  std::vector<Candidate> candidates;
  for (int yi = 0; yi < n; ++yi) {
    const double y = -offset_xy + yi * step_xy;
    const double position_y = center.y + y;
    for (int xi = 0; xi < n; ++xi) {
      const double x = -offset_xy + xi * step_xy;
      const double position_x = center.x + x;
      const std::int32_t cell = grid_.GridIndex(grid_.WorldToGrid({position_x, position_y}));
      const double start_angle = center.theta - angle_offset;
      for (int k = 0; k < num_angles; ++k) {
        const double angle = start_angle + k * angle_step;
        double response = Response(k, cell);
        if (penalize == Penalize::kYes && !KartoEqual(response, 0.0)) {
          const double squared_distance = x * x + y * y;
          double distance_penalty = 1.0 - (0.2 * squared_distance / options_.distance_variance_penalty);
          if (!(distance_penalty > options_.minimum_distance_penalty)) {
            distance_penalty = options_.minimum_distance_penalty;
          }
          const double squared_angle = (angle - center.theta) * (angle - center.theta);
          double angle_penalty = 1.0 - (0.2 * squared_angle / options_.angle_variance_penalty);
          if (!(angle_penalty > options_.minimum_angle_penalty)) angle_penalty = options_.minimum_angle_penalty;
          response *= (distance_penalty * angle_penalty);
        }
        candidates.push_back({response, Pose2{position_x, position_y, NormalizeAngle(angle)}});
      }
    }
  }
  double best = -1;
  for (const Candidate& c : candidates) {
    if (c.response > best) best = c.response;
    if (pass == Pass::kCoarse) {
      double& p = probabilities_.at(probabilities_.IndexOf(c.pose.x, c.pose.y));
      if (c.response > p) p = c.response;
    }
  }
  double sum_x = 0, sum_y = 0, sum_cos = 0, sum_sin = 0;
  int count = 0;
  for (const Candidate& c : candidates) {
    if (!KartoEqual(c.response, best)) continue;
    sum_x += c.pose.x;
    sum_y += c.pose.y;
    sum_cos += std::cos(c.pose.theta);
    sum_sin += std::sin(c.pose.theta);
    ++count;
  }
  SLAMTUNE_CHECK(count > 0);
  const Pose2 average{sum_x / count, sum_y / count, std::atan2(sum_sin / count, sum_cos / count)};
  if (pass == Pass::kCoarse) {
    *cov = PositionalCovariance(average, best, center, offset_xy, step_xy, angle_step, probabilities_);
  } else {
    const std::int32_t cell = grid_.GridIndex(grid_.WorldToGrid({average.x, average.y}));
    std::vector<double> angles, raw;
    for (int k = 0; k < num_angles; ++k) {
      angles.push_back(center.theta - angle_offset + k * angle_step);
      raw.push_back(Response(k, cell));
    }
    (*cov)(2, 2) = AngularVariance(average.theta, best, center.theta, angle_step, angles, raw);
  }
  *mean = average;
  return best > 1.0 ? 1.0 : best;
}

MatchResult ReferenceScanMatcher::Match(const LaserScan& scan, std::span<const LaserScan* const> base_scans,
                                        Penalize penalize, Refine refine) {
  scan.EnsureReadout();
  for (const LaserScan* base : base_scans) base->EnsureReadout();
  MatchResult result;
  const Pose2 center = scan.SensorPose();
  if (scan.ranges().empty()) {
    result.mean = center;
    result.covariance(0, 0) = kMaxVariance;
    result.covariance(1, 1) = kMaxVariance;
    result.covariance(2, 2) = 4 * (options_.coarse_angle_resolution * options_.coarse_angle_resolution);
    return result;
  }
  const double resolution = 1.0 / grid_.scale();
  const int roi = grid_.geometry().roi_side;
  grid_.SetRoiOrigin({center.x - (0.5 * (roi - 1) * resolution), center.y - (0.5 * (roi - 1) * resolution)});
  grid_.AddScans(base_scans, {center.x, center.y});
  const double coarse_offset = 0.5 * (grid_.geometry().search_side - 1) * resolution;
  const double coarse_step = 2 * resolution;
  double best =
      CorrelateScan(scan, center, coarse_offset, coarse_step, options_.coarse_angle_offset,
                    options_.coarse_angle_resolution, penalize, Pass::kCoarse, &result.mean, &result.covariance);
  if (options_.use_response_expansion && KartoEqual(best, 0.0)) {
    double angle_offset = options_.coarse_angle_offset;
    for (int i = 0; i < 3; ++i) {
      angle_offset += 20 * 0.01745329251994329577;
      best = CorrelateScan(scan, center, coarse_offset, coarse_step, angle_offset, options_.coarse_angle_resolution,
                           penalize, Pass::kCoarse, &result.mean, &result.covariance);
      if (!KartoEqual(best, 0.0)) break;
    }
  }
  if (refine == Refine::kYes) {
    const Pose2 coarse_mean = result.mean;
    best = CorrelateScan(scan, coarse_mean, coarse_step * 0.5, resolution, 0.5 * options_.coarse_angle_resolution,
                         options_.fine_angle_step, penalize, Pass::kFine, &result.mean, &result.covariance);
  }
  result.response = best;
  return result;
}

}  // namespace slamtune::slam
