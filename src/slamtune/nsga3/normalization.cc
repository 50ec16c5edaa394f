#include "slamtune/nsga3/normalization.h"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

// Relative accuracy demanded of the hyperplane solve E b = 1; a larger residual means the
// extreme points are too close to dependent for the intercepts to be trusted.
constexpr double kSolveTolerance = 1e-9;

// Index of the candidate minimising ASF(f - ideal, w_axis), eq. 4. Ties go to the lowest index.
std::size_t ExtremePoint(const std::vector<std::vector<double>>& candidates, const std::vector<double>& ideal,
                         std::size_t axis, double off_axis_weight) {
  std::size_t best = 0;
  double best_asf = std::numeric_limits<double>::infinity();
  for (std::size_t s = 0; s < candidates.size(); ++s) {
    double asf = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ideal.size(); ++i) {
      const double weight = i == axis ? 1.0 : off_axis_weight;
      asf = std::max(asf, (candidates[s][i] - ideal[i]) / weight);
    }
    if (asf < best_asf) {
      best_asf = asf;
      best = s;
    }
  }
  return best;
}

// Intercepts of the hyperplane through the translated extreme points (§IV-C), or the reason
// they cannot be used.
std::string HyperplaneIntercepts(const std::vector<std::vector<double>>& candidates, const std::vector<double>& ideal,
                                 const std::vector<std::size_t>& extremes, double min_intercept,
                                 std::vector<double>* intercepts) {
  const std::size_t m = ideal.size();
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t k = j + 1; k < m; ++k) {
      if (candidates[extremes[j]] == candidates[extremes[k]]) {
        return fmt::format("duplicate extreme points: axes {} and {} share the objective vector", j, k);
      }
    }
  }
  // Row j holds the translated extreme point of axis j; the plane is {t : b . t = 1}.
  Eigen::MatrixXd e(m, m);
  for (std::size_t j = 0; j < m; ++j) {
    for (std::size_t i = 0; i < m; ++i) e(j, i) = candidates[extremes[j]][i] - ideal[i];
  }
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(e);
  if (!lu.isInvertible()) {
    return "singular system: the extreme points are collinear or their hyperplane contains the ideal point";
  }
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m);
  const Eigen::VectorXd b = lu.solve(ones);
  if (!b.allFinite() || (e * b - ones).norm() > kSolveTolerance * std::sqrt(static_cast<double>(m))) {
    return "ill-conditioned system: the hyperplane solve is inaccurate";
  }
  intercepts->assign(m, 0.0);
  for (std::size_t i = 0; i < m; ++i) {
    const double a = 1.0 / b(i);  // intercept on axis i: b_i * a_i = 1
    if (!std::isfinite(a)) return fmt::format("intercept {} is not finite", i);
    if (!(a > min_intercept))
      return fmt::format("intercept {} = {:g} is not above min_intercept {:g}", i, a, min_intercept);
    (*intercepts)[i] = a;
  }
  return "";
}

}  // namespace

void NormalizationOptions::Validate() const {
  if (!(asf_off_axis_weight > 0.0 && asf_off_axis_weight < 1.0)) {
    throw InputError(
        fmt::format("normalization.asf_off_axis_weight = {} is invalid, must be in (0, 1)", asf_off_axis_weight));
  }
  if (!(min_intercept >= 0.0) || !std::isfinite(min_intercept)) {
    throw InputError(
        fmt::format("normalization.min_intercept = {} is invalid, must be finite and >= 0", min_intercept));
  }
}

const char* ToString(NadirSource source) {
  switch (source) {
    case NadirSource::kHyperplane: return "hyperplane";
    case NadirSource::kFrontWorst: return "front-worst";
    case NadirSource::kCandidatesWorst: return "candidates-worst";
    case NadirSource::kUnitRange: return "unit-range";
  }
  return "?";
}

std::vector<double> Normalization::Normalize(const std::vector<double>& f) const {
  SLAMTUNE_CHECK(f.size() == ideal.size());
  std::vector<double> out(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) out[i] = (f[i] - ideal[i]) / (nadir[i] - ideal[i]);  // eq. 5
  return out;
}

std::vector<std::vector<double>> Normalization::NormalizeAll(const std::vector<std::vector<double>>& points) const {
  std::vector<std::vector<double>> out;
  out.reserve(points.size());
  for (const auto& f : points) out.push_back(Normalize(f));
  return out;
}

Normalization ComputeNormalization(const std::vector<std::vector<double>>& candidates,
                                   const std::vector<std::size_t>& first_front, const NormalizationOptions& options,
                                   const std::vector<double>& earlier_ideal) {
  SLAMTUNE_CHECK(!candidates.empty() && !first_front.empty());
  const std::size_t m = candidates[0].size();
  SLAMTUNE_CHECK(m >= 1);
  SLAMTUNE_CHECK(earlier_ideal.empty() || earlier_ideal.size() == m);
  Normalization result;
  // Step 1: ideal point over S_t and earlier generations (§IV-C), and the worst values used
  // by the fall-backs.
  result.ideal = earlier_ideal;
  if (result.ideal.empty()) result.ideal.assign(m, std::numeric_limits<double>::infinity());
  std::vector<double> worst(m, -std::numeric_limits<double>::infinity());
  for (const auto& f : candidates) {
    SLAMTUNE_CHECK(f.size() == m);
    for (std::size_t i = 0; i < m; ++i) {
      SLAMTUNE_CHECK_MSG(std::isfinite(f[i]), "objective values must be finite");
      result.ideal[i] = std::min(result.ideal[i], f[i]);
      worst[i] = std::max(worst[i], f[i]);
    }
  }
  // Step 2: extreme points by the ASF (eq. 4).
  for (std::size_t axis = 0; axis < m; ++axis) {
    result.extreme_points.push_back(ExtremePoint(candidates, result.ideal, axis, options.asf_off_axis_weight));
  }
  // Step 3: hyperplane intercepts, nadir = ideal + a; else the worst point of the first front.
  std::vector<double> intercepts;
  result.hyperplane_rejection =
      HyperplaneIntercepts(candidates, result.ideal, result.extreme_points, options.min_intercept, &intercepts);
  result.nadir.assign(m, -std::numeric_limits<double>::infinity());
  if (result.hyperplane_rejection.empty()) {
    for (std::size_t i = 0; i < m; ++i) result.nadir[i] = result.ideal[i] + intercepts[i];
    result.nadir_source.assign(m, NadirSource::kHyperplane);
  } else {
    for (std::size_t index : first_front) {
      SLAMTUNE_CHECK(index < candidates.size());
      for (std::size_t i = 0; i < m; ++i) result.nadir[i] = std::max(result.nadir[i], candidates[index][i]);
    }
    result.nadir_source.assign(m, NadirSource::kFrontWorst);
  }
  // Per-objective guards: a range not above min_intercept widens to all candidates, a zero
  // range (constant objective) becomes 1 so that the division stays defined.
  for (std::size_t i = 0; i < m; ++i) {
    if (result.nadir[i] - result.ideal[i] <= options.min_intercept) {
      result.nadir[i] = worst[i];
      result.nadir_source[i] = NadirSource::kCandidatesWorst;
    }
    if (!(result.nadir[i] - result.ideal[i] > 0.0)) {
      result.nadir[i] = result.ideal[i] + 1.0;
      result.nadir_source[i] = NadirSource::kUnitRange;
    }
  }
  return result;
}

}  // namespace slamtune::nsga3
