#include "slamtune/optim/settling.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "slamtune/common/error.h"
#include "slamtune/optim/candidate_selection.h"

namespace slamtune::optim {
namespace {

// The objective vector of the recommendation — chosen as the final candidate selection chooses
// it (MajorityIndex; failed runs are not told apart here, their scores are worse than any map's)
// — and of the knee. Compared as vectors: sets that give the very same map are one answer, and
// a population spread along a front with no set shared would otherwise "change" its answer every
// generation among equals.
std::vector<double> RecommendedScores(const SearchSpace& space, const std::vector<std::vector<double>>& x,
                                      const std::vector<std::vector<double>>& f) {
  std::vector<std::string> keys;
  for (const auto& xi : x) keys.push_back(SearchSpace::Key(space.Assign(xi)));
  return f[MajorityIndex(keys, f, std::vector<bool>(f.size(), true))];
}

}  // namespace

void SettlingOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("--stop-tolerance = {} is out of range: must be in (0, 1)", tolerance));
  }
  if (window < 1) throw InputError(fmt::format("--stop-window = {} is out of range: must be >= 1", window));
}

std::vector<std::vector<double>> NonDominatedVectors(const std::vector<std::vector<double>>& f) {
  std::vector<std::vector<double>> out;
  for (std::size_t i : NonDominatedIndices(f))
    if (std::find(out.begin(), out.end(), f[i]) == out.end()) out.push_back(f[i]);
  return out;
}

double FrontMovement(const std::vector<std::vector<double>>& previous,
                     const std::vector<std::vector<double>>& current) {
  if (previous.empty() || current.empty()) return 1.0;
  const std::size_t m = current.front().size();
  std::vector<double> lo(m, std::numeric_limits<double>::infinity()), hi(m, -lo[0]);
  for (const auto& p : current)
    for (std::size_t k = 0; k < m; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  double sum = 0.0;
  for (const auto& p : current) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& q : previous) {
      double d2 = 0.0;
      for (std::size_t k = 0; k < m; ++k) {
        const double range = hi[k] > lo[k] ? hi[k] - lo[k] : 1.0;
        const double z = (p[k] - q[k]) / range;
        d2 += z * z;
      }
      nearest = std::min(nearest, std::sqrt(d2));
    }
    sum += nearest;
  }
  return sum / static_cast<double>(current.size());
}

SettlingRule::SettlingRule(SettlingOptions options, SearchSpace space)
    : options_(options), space_(std::move(space)) {
  options_.Validate();
}

bool SettlingRule::Update(unsigned generation, const std::vector<std::vector<double>>& x,
                          const std::vector<std::vector<double>>& f) {
  SLAMTUNE_CHECK(x.size() == f.size() && !x.empty());
  SLAMTUNE_CHECK(last_generation_ == 0 || generation == last_generation_ + 1);
  last_generation_ = generation;
  if (settled()) return true;
  const auto front = NonDominatedVectors(f);
  const std::vector<double> recommended = RecommendedScores(space_, x, f);
  const std::vector<double> knee = f[KneeIndex(f)];
  const bool had_previous = !previous_front_.empty();
  last_movement_ = FrontMovement(previous_front_, front);
  const bool same_answer = recommended == previous_recommended_ && knee == previous_knee_;
  const bool calm = had_previous && last_movement_ < options_.tolerance && same_answer;
  last_answer_changed_ = had_previous && !same_answer;
  calm_generations_ = calm ? calm_generations_ + 1 : 0;
  previous_front_ = front;
  previous_recommended_ = recommended;
  previous_knee_ = knee;
  if (options_.enabled && calm_generations_ >= options_.window) settled_at_ = generation;
  return settled();
}

std::string SettlingRule::Describe(unsigned generations_budget) const {
  if (!options_.enabled) return fmt::format("ran the fixed budget of {} generations", generations_budget);
  if (!settled()) {
    if (last_movement_ >= options_.tolerance) {
      return fmt::format("ran all {} generations: the answer was still changing (the front still moved {:.4f}, "
                         "tolerance {:.4f})",
                         generations_budget, last_movement_, options_.tolerance);
    }
    if (last_answer_changed_) {
      return fmt::format("ran all {} generations: the answer was still changing (the front moved {:.4f}, below the "
                         "tolerance {:.4f}, but the recommended or the knee map changed in the last generation)",
                         generations_budget, last_movement_, options_.tolerance);
    }
    return fmt::format("ran all {} generations: the answer was still changing (calm for {} of the {} generations "
                       "in a row the rule needs)",
                       generations_budget, calm_generations_, options_.window);
  }
  return fmt::format("stopped after generation {} of {}: for {} generations the non-dominated front moved less than "
                     "{:.4f} (normalised) and the recommendation and the knee did not change",
                     settled_at_, generations_budget, options_.window, options_.tolerance);
}

}  // namespace slamtune::optim
