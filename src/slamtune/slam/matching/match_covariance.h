// Covariances of a correlative match (docs/engine.md §4.6) and the search-space
// probability grid they read (§4.1, §4.5).
//
// Positional covariance (coarse pass): the response-weighted spread, around the best mean,
// of every lattice position whose best response over headings is within 0.1 of the best;
// floored at 0.1 step^2, scaled by 1/best, with the 500 m^2 fallbacks. Angular variance
// (fine pass): the same spread over headings at the best cell, from *unpenalised* responses.
// These numbers gate loop closure (q, §6.3) and weight every graph edge, so each expression
// follows Karto's evaluation order.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::slam {

// MAX_VARIANCE (m^2): the covariance given to matches without overlap (§1.1).
inline constexpr double kMaxVariance = 500.0;

// n x n doubles at resolution rho; cell (i, j) holds the best response over headings of the
// candidate at origin + (i, j) rho in the last coarse pass (§4.5).
class SearchProbabilityGrid {
 public:
  SearchProbabilityGrid(int side, double resolution);

  // Zeroes every cell and moves the grid (coarse pass start, §4.5).
  void Reset(const Eigen::Vector2d& origin);
  // Linear index of the cell of a world position, Round((w - origin) * scale); the cell must
  // exist (checked: Karto throws "Index out of range in probability search").
  int IndexOf(double world_x, double world_y) const;
  double& at(int index) { return values_[static_cast<std::size_t>(index)]; }
  double at(int index) const { return values_[static_cast<std::size_t>(index)]; }
  int side() const { return side_; }

 private:
  int side_;
  double scale_;
  Eigen::Vector2d origin_{0, 0};
  std::vector<double> values_;
};

// §4.6 positional covariance. `best_pose` is the pass's mean, `center` its search centre,
// the lattice is -offset_xy + j step_xy (j = 0 .. Round(2 offset/step)) on both axes and
// `angle_step` the pass's heading step.
Eigen::Matrix3d PositionalCovariance(const Pose2& best_pose, double best_response, const Pose2& center,
                                     double offset_xy, double step_xy, double angle_step,
                                     const SearchProbabilityGrid& probabilities);

// §4.6 angular variance: `angles` are the fine headings alpha_k and `raw_responses` the
// unpenalised responses at the best cell for each of them; `best_response` is the fine
// pass's (penalised) best.
double AngularVariance(double best_heading, double best_response, double center_heading, double angle_step,
                       std::span<const double> angles, std::span<const double> raw_responses);

}  // namespace slamtune::slam
