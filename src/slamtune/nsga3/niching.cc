#include "slamtune/nsga3/niching.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

// Uniform index in [0, size), size >= 1.
std::size_t RandomIndex(std::size_t size, std::mt19937& rng) {
  return std::uniform_int_distribution<std::size_t>(0, size - 1)(rng);
}

}  // namespace

double PerpendicularDistance(const std::vector<double>& point, const std::vector<double>& direction) {
  SLAMTUNE_CHECK(point.size() == direction.size());
  double wf = 0.0, ww = 0.0;
  for (std::size_t i = 0; i < point.size(); ++i) {
    wf += direction[i] * point[i];
    ww += direction[i] * direction[i];
  }
  SLAMTUNE_CHECK(ww > 0.0);
  const double scale = wf / ww;
  double d2 = 0.0;
  for (std::size_t i = 0; i < point.size(); ++i) {
    const double r = point[i] - scale * direction[i];
    d2 += r * r;
  }
  return std::sqrt(d2);
}

Association Associate(const std::vector<std::vector<double>>& normalized_points,
                      const std::vector<std::vector<double>>& reference_points) {
  SLAMTUNE_CHECK(!reference_points.empty());
  Association result;
  result.reference.reserve(normalized_points.size());
  result.distance.reserve(normalized_points.size());
  // Algorithm 3, steps 4-7: nearest reference line by perpendicular distance.
  for (const auto& f : normalized_points) {
    std::size_t best = 0;
    double best_distance = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < reference_points.size(); ++j) {
      const double d = PerpendicularDistance(f, reference_points[j]);
      if (d < best_distance) {
        best_distance = d;
        best = j;
      }
    }
    result.reference.push_back(best);
    result.distance.push_back(best_distance);
  }
  return result;
}

NicheSelection SelectByNiching(std::size_t count, std::vector<std::size_t> niche_count,
                               const std::vector<std::size_t>& last_front, const Association& association,
                               std::mt19937& rng) {
  SLAMTUNE_CHECK(count <= last_front.size());
  const std::size_t h = niche_count.size();
  // Unselected members of F_l per reference point, in the order of `last_front`.
  std::vector<std::vector<std::size_t>> members(h);
  for (std::size_t index : last_front) {
    SLAMTUNE_CHECK(index < association.reference.size());
    SLAMTUNE_CHECK(association.reference[index] < h);
    members[association.reference[index]].push_back(index);
  }
  std::vector<bool> active(h, true);
  NicheSelection result;
  result.chosen.reserve(count);
  std::vector<std::size_t> least_crowded;
  while (result.chosen.size() < count) {
    // Algorithm 4, steps 3-4: J_min = argmin of rho_j over the active reference points.
    std::size_t min_rho = std::numeric_limits<std::size_t>::max();
    least_crowded.clear();
    for (std::size_t j = 0; j < h; ++j) {
      if (!active[j]) continue;
      if (niche_count[j] < min_rho) {
        min_rho = niche_count[j];
        least_crowded.clear();
      }
      if (niche_count[j] == min_rho) least_crowded.push_back(j);
    }
    // Every member of F_l is associated with some reference point, so while members remain
    // unselected at least one active point has candidates.
    SLAMTUNE_CHECK(!least_crowded.empty());
    const std::size_t j = least_crowded[RandomIndex(least_crowded.size(), rng)];
    std::vector<std::size_t>& candidates = members[j];
    if (candidates.empty()) {  // step 15: no candidate in F_l, exclude for this generation
      active[j] = false;
      ++result.excluded_references;
      continue;
    }
    std::size_t pick = 0;
    if (niche_count[j] == 0) {  // steps 8-9: the member closest to the reference line
      for (std::size_t k = 1; k < candidates.size(); ++k) {
        if (association.distance[candidates[k]] < association.distance[candidates[pick]]) pick = k;
      }
    } else {  // step 11: a random member
      pick = RandomIndex(candidates.size(), rng);
    }
    result.chosen.push_back(candidates[pick]);
    candidates.erase(candidates.begin() + static_cast<std::ptrdiff_t>(pick));
    ++niche_count[j];  // step 12
  }
  result.niche_count = std::move(niche_count);
  return result;
}

}  // namespace slamtune::nsga3
