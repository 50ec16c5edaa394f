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
// it (MajorityIndex, failed runs told by `is_failure`) — and of the knee. Compared as vectors:
// sets that give the very same map are one answer, and a population spread along a front with
// no set shared would otherwise "change" its answer every generation among equals.
std::vector<double> RecommendedScores(const SearchSpace& space, const FailureTest& is_failure,
                                      const std::vector<std::vector<double>>& x,
                                      const std::vector<std::vector<double>>& f) {
  std::vector<std::string> keys;
  std::vector<bool> ok;
  for (const auto& xi : x) keys.push_back(SearchSpace::Key(space.Assign(xi)));
  for (const auto& fi : f) ok.push_back(!is_failure || !is_failure(fi));
  return f[MajorityIndex(keys, f, ok)];
}

}  // namespace

void SettlingOptions::Validate() const {
  if (!(tolerance > 0.0 && tolerance < 1.0)) {
    throw InputError(fmt::format("--stop-tolerance = {} is out of range: must be in (0, 1)", tolerance));
  }
  if (window < 1) throw InputError(fmt::format("--stop-window = {} is out of range: must be >= 1", window));
  if (sound_answer_window < 0) {
    throw InputError(
        fmt::format("--sound-answer-window = {} is out of range: must be >= 0 (0 = off)", sound_answer_window));
  }
}

nlohmann::json SettlingOptions::ToJson() const {
  nlohmann::json j = {{"enabled", enabled}, {"tolerance", tolerance}, {"window", window}};
  if (sound_answer_window != 0) j["sound_answer_window"] = sound_answer_window;  // absent when off: older folders
  return j;
}

SettlingOptions SettlingOptions::FromJson(const nlohmann::json& j) {
  SettlingOptions o;
  o.enabled = j.at("enabled").get<bool>();
  o.tolerance = j.at("tolerance").get<double>();
  o.window = j.at("window").get<int>();
  o.sound_answer_window = j.value("sound_answer_window", 0);
  return o;
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

SettlingRule::SettlingRule(SettlingOptions options, SearchSpace space, FailureTest is_failure)
    : options_(options), space_(std::move(space)), is_failure_(std::move(is_failure)) {
  options_.Validate();
}

bool SettlingRule::Update(unsigned generation, const std::vector<std::vector<double>>& x,
                          const std::vector<std::vector<double>>& f) {
  SLAMTUNE_CHECK(x.size() == f.size() && !x.empty());
  SLAMTUNE_CHECK(!fed_ || generation == last_generation_ + 1);
  fed_ = true;
  last_generation_ = generation;
  if (settled()) return true;
  const std::vector<double> recommended = RecommendedScores(space_, is_failure_, x, f);
  const bool sound = !is_failure_ || !is_failure_(recommended);
  // (A failed recommendation equal to the previous one is failed too: the count stays 0.)
  sound_generations_ = sound && recommended == previous_recommended_ ? sound_generations_ + 1 : 0;
  if (generation == 0) {  // the front's movement is measured from generation 1 on
    previous_recommended_ = recommended;
    return false;
  }
  const auto front = NonDominatedVectors(f);
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
  if (options_.enabled && calm_generations_ >= options_.window) {
    settled_at_ = generation;
  } else if (options_.enabled && options_.sound_answer_window > 0 &&
             sound_generations_ >= options_.sound_answer_window) {
    settled_at_ = generation;
    settled_by_sound_answer_ = true;
  }
  return settled();
}

std::string SettlingRule::Describe(unsigned generations_budget) const {
  if (!options_.enabled) return fmt::format("ran the fixed budget of {} generations", generations_budget);
  if (!settled()) {
    if (last_movement_ >= options_.tolerance) {
      return fmt::format(
          "ran all {} generations: the answer was still changing (the front still moved {:.4f}, "
          "tolerance {:.4f})",
          generations_budget, last_movement_, options_.tolerance);
    }
    if (last_answer_changed_) {
      return fmt::format(
          "ran all {} generations: the answer was still changing (the front moved {:.4f}, below the "
          "tolerance {:.4f}, but the recommended or the knee map changed in the last generation)",
          generations_budget, last_movement_, options_.tolerance);
    }
    return fmt::format(
        "ran all {} generations: the answer was still changing (calm for {} of the {} generations "
        "in a row the rule needs)",
        generations_budget, calm_generations_, options_.window);
  }
  if (settled_by_sound_answer_) {
    const std::string front =
        settled_at_ >= 2 ? fmt::format("the front moved {:.4f} in the last generation; ", last_movement_) : "";
    return fmt::format(
        "stopped after generation {} of {}: the recommended map was sound (its run held) and the same "
        "for {} generation{} in a row ({}--sound-answer-window 0 runs on until the front settles too)",
        settled_at_, generations_budget, options_.sound_answer_window, options_.sound_answer_window == 1 ? "" : "s",
        front);
  }
  return fmt::format(
      "stopped after generation {} of {}: for {} generations the non-dominated front moved less than "
      "{:.4f} (normalised) and the recommendation and the knee did not change",
      settled_at_, generations_budget, options_.window, options_.tolerance);
}

}  // namespace slamtune::optim
