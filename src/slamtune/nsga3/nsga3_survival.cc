#include "slamtune/nsga3/nsga3_survival.h"

#include <pagmo/utils/multi_objective.hpp>

#include "slamtune/common/error.h"
#include "slamtune/nsga3/niching.h"

namespace slamtune::nsga3 {

SurvivalResult SelectSurvivors(const std::vector<std::vector<double>>& objectives, std::size_t n,
                               const ReferencePoints& reference_points, const NormalizationOptions& options,
                               std::mt19937& rng, const std::vector<double>& earlier_ideal) {
  SLAMTUNE_CHECK(objectives.size() >= 2 && n >= 1 && n <= objectives.size());
  SurvivalResult result;
  // Steps 3-7: non-dominated sorting, then whole fronts into S_t until |S_t| >= N.
  const auto fronts = std::get<0>(pagmo::fast_non_dominated_sorting(objectives));
  std::vector<std::size_t> s_t;  // indices into `objectives`, front by front
  s_t.reserve(objectives.size());
  std::size_t accepted = 0;  // |P_{t+1}| before niching: members of F_1 .. F_{l-1}
  for (const auto& front : fronts) {
    accepted = s_t.size();
    s_t.insert(s_t.end(), front.begin(), front.end());
    ++result.fronts_used;
    result.last_front_size = front.size();
    if (s_t.size() >= n) break;
  }
  SLAMTUNE_CHECK(s_t.size() >= n);
  if (s_t.size() == n) {  // steps 8-9: S_t fits exactly
    result.survivors = std::move(s_t);
    return result;
  }
  // Step 12: normalise S_t; first-front members are s_t[0 .. |F_1|).
  std::vector<std::vector<double>> s_objectives;
  s_objectives.reserve(s_t.size());
  for (std::size_t index : s_t) s_objectives.push_back(objectives[index]);
  std::vector<std::size_t> first_front(fronts.front().size());
  for (std::size_t k = 0; k < first_front.size(); ++k) first_front[k] = k;
  result.normalization = ComputeNormalization(s_objectives, first_front, options, earlier_ideal);
  // Step 13: associate every member of S_t with a reference line.
  const Association association = Associate(result.normalization->NormalizeAll(s_objectives), reference_points);
  // Step 14: niche counts of P_{t+1} = F_1 u ... u F_{l-1}.
  std::vector<std::size_t> niche_count(reference_points.size(), 0);
  for (std::size_t k = 0; k < accepted; ++k) ++niche_count[association.reference[k]];
  // Step 15: choose K = N - |P_{t+1}| members of F_l, which is s_t[accepted ..).
  std::vector<std::size_t> last_front;
  for (std::size_t k = accepted; k < s_t.size(); ++k) last_front.push_back(k);
  result.niched = n - accepted;
  const NicheSelection selection = SelectByNiching(result.niched, std::move(niche_count), last_front, association, rng);
  result.excluded_references = selection.excluded_references;
  result.survivors.assign(s_t.begin(), s_t.begin() + static_cast<std::ptrdiff_t>(accepted));
  for (std::size_t k : selection.chosen) result.survivors.push_back(s_t[k]);
  return result;
}

}  // namespace slamtune::nsga3
