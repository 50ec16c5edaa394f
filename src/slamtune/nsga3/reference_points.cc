#include "slamtune/nsga3/reference_points.h"

#include <fmt/format.h>

#include <cmath>
#include <pagmo/utils/multi_objective.hpp>
#include <random>
#include <string>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

// Upper bound on the number of reference points: beyond this, memory and the O(N H)
// association per generation make the run unreasonable, and the count itself would need
// more than double precision in pagmo's binomial coefficient.
constexpr std::size_t kMaxReferencePoints = 1'000'000;

}  // namespace

std::size_t DasDennisCount(std::size_t objectives, std::size_t divisions) {
  if (objectives < 2) {
    throw InputError(fmt::format("reference points: objectives = {} is invalid, must be >= 2", objectives));
  }
  if (divisions < 1) {
    throw InputError(fmt::format("reference points: divisions = {} is invalid, must be >= 1", divisions));
  }
  // C(M + D - 1, D) built as a running product of exact integer ratios:
  // C(M-1+k, k) = C(M-2+k, k-1) * (M-1+k) / k, each step exact.
  std::size_t count = 1;
  for (std::size_t k = 1; k <= divisions; ++k) {
    count = count * (objectives - 1 + k) / k;
    if (count > kMaxReferencePoints) {
      throw InputError(fmt::format(
          "reference points: objectives = {} with divisions = {} gives more than {} points, reduce divisions",
          objectives, divisions, kMaxReferencePoints));
    }
  }
  return count;
}

ReferencePoints DasDennisPoints(std::size_t objectives, std::size_t divisions) {
  const std::size_t count = DasDennisCount(objectives, divisions);
  // The "grid" method is deterministic; the engine is required by the signature only.
  std::mt19937 unused_engine(0u);
  ReferencePoints points = pagmo::decomposition_weights(objectives, count, "grid", unused_engine);
  SLAMTUNE_CHECK_MSG(points.size() == count,
                     fmt::format("pagmo grid gave {} points, expected {}", points.size(), count));
  return points;
}

ReferencePoints LayeredReferencePoints(std::size_t objectives, std::size_t boundary_divisions,
                                       std::size_t inner_divisions) {
  ReferencePoints points = DasDennisPoints(objectives, boundary_divisions);
  if (inner_divisions == 0) return points;
  const double centroid = 1.0 / static_cast<double>(objectives);
  for (std::vector<double> w : DasDennisPoints(objectives, inner_divisions)) {
    for (double& component : w) component = 0.5 * (component + centroid);  // §V-B, shrink halfway
    points.push_back(std::move(w));
  }
  return points;
}

void ValidateReferencePoints(const ReferencePoints& points, std::size_t objectives, const char* field) {
  if (points.empty()) {
    throw InputError(fmt::format("{}: no reference points given, at least one is required", field));
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::vector<double>& w = points[i];
    if (w.size() != objectives) {
      throw InputError(
          fmt::format("{}[{}] has {} components, the problem has {} objectives", field, i, w.size(), objectives));
    }
    double sum = 0.0;
    for (double component : w) {
      if (!std::isfinite(component) || component < 0.0) {
        throw InputError(
            fmt::format("{}[{}] has component {}, every component must be finite and >= 0", field, i, component));
      }
      sum += component;
    }
    if (!(sum > 0.0)) {
      throw InputError(fmt::format("{}[{}] is the zero vector, a reference direction needs a positive sum", field, i));
    }
  }
}

}  // namespace slamtune::nsga3
