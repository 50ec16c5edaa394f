#include "slamtune/slam/matching/match_covariance.h"

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::slam {

SearchProbabilityGrid::SearchProbabilityGrid(int side, double resolution)
    : side_(side), scale_(1.0 / resolution), values_(static_cast<std::size_t>(side) * side, 0.0) {}

void SearchProbabilityGrid::Reset(const Eigen::Vector2d& origin) {
  origin_ = origin;
  std::fill(values_.begin(), values_.end(), 0.0);
}

int SearchProbabilityGrid::IndexOf(double world_x, double world_y) const {
  const int x = KartoRoundToInt((world_x - origin_.x()) * scale_);
  const int y = KartoRoundToInt((world_y - origin_.y()) * scale_);
  SLAMTUNE_CHECK_MSG(x >= 0 && x < side_ && y >= 0 && y < side_, "index out of range in probability search");
  return x + y * side_;
}

Eigen::Matrix3d PositionalCovariance(const Pose2& best_pose, double best_response, const Pose2& center,
                                     double offset_xy, double step_xy, double angle_step,
                                     const SearchProbabilityGrid& probabilities) {
  Eigen::Matrix3d cov = Eigen::Matrix3d::Identity();
  // No overlap at all: the weakest possible edge (§4.6 first rule).
  if (best_response < kKartoTolerance) {
    cov(0, 0) = kMaxVariance;
    cov(1, 1) = kMaxVariance;
    cov(2, 2) = 4 * (angle_step * angle_step);
    return cov;
  }
  double sxx = 0, sxy = 0, syy = 0, norm = 0;
  const double dx = best_pose.x - center.x;
  const double dy = best_pose.y - center.y;
  const int n = static_cast<int>(KartoRound(offset_xy * 2.0 / step_xy) + 1);
  const double start = -offset_xy;
  for (int yi = 0; yi < n; ++yi) {
    const double y = start + yi * step_xy;
    for (int xi = 0; xi < n; ++xi) {
      const double x = start + xi * step_xy;
      const double response = probabilities.at(probabilities.IndexOf(center.x + x, center.y + y));
      // Window of the best - 0.1 (§4.6): needs every position within 0.1 of the best.
      if (response >= (best_response - 0.1)) {
        norm += response;
        sxx += ((x - dx) * (x - dx) * response);
        sxy += ((x - dx) * (y - dy) * response);
        syy += ((y - dy) * (y - dy) * response);
      }
    }
  }
  if (norm > kKartoTolerance) {
    const double min_variance = 0.1 * (step_xy * step_xy);
    const double vxx = std::max(sxx / norm, min_variance);
    const double vxy = sxy / norm;
    const double vyy = std::max(syy / norm, min_variance);
    // Karto multiplies by 1/best (rather than dividing), and leaves theta-theta unscaled.
    const double multiplier = 1.0 / best_response;
    cov(0, 0) = vxx * multiplier;
    cov(0, 1) = vxy * multiplier;
    cov(1, 0) = vxy * multiplier;
    cov(1, 1) = vyy * multiplier;
    cov(2, 2) = 4 * (angle_step * angle_step);
  }
  // Variances that came out as zero (too sparse to overlap) become MAX_VARIANCE.
  if (KartoEqual(cov(0, 0), 0.0)) cov(0, 0) = kMaxVariance;
  if (KartoEqual(cov(1, 1), 0.0)) cov(1, 1) = kMaxVariance;
  return cov;
}

double AngularVariance(double best_heading, double best_response, double center_heading, double angle_step,
                       std::span<const double> angles, std::span<const double> raw_responses) {
  SLAMTUNE_CHECK(angles.size() == raw_responses.size());
  // Karto shifts the best heading by whole turns towards the centre; its loop adds 2 pi
  // while below -pi first, then subtracts while above pi (the shared helper runs the two
  // loops in the other order; they agree whenever one shift suffices).
  double best_angle = best_heading;
  while (best_angle - center_heading < -kPi) best_angle += kTwoPi;
  while (best_angle - center_heading > kPi) best_angle -= kTwoPi;
  double norm = 0, s = 0;
  for (std::size_t k = 0; k < angles.size(); ++k) {
    const double response = raw_responses[k];
    if (response >= (best_response - 0.1)) {
      norm += response;
      s += ((angles[k] - best_angle) * (angles[k] - best_angle) * response);
    }
  }
  if (norm > kKartoTolerance) {
    // A single contributing heading gives zero spread: seed it with one step^2 (§4.6).
    if (s < kKartoTolerance) s = angle_step * angle_step;
    return s / norm;
  }
  return 1000 * (angle_step * angle_step);
}

}  // namespace slamtune::slam
