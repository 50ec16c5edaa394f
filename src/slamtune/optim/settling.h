// When has an optimisation settled? A budget of generations is arbitrary (the seed paper's
// 66 x 60 among them); a user wants the answer the full budget would give as soon as it stops
// changing. After each generation this rule looks at two things, in the spirit of pymoo's
// default multi-objective termination (Blank & Deb 2020, pymoo: "ftol" on the movement of the
// non-dominated front):
//   * the front's movement: the mean distance from each point of this generation's
//     non-dominated front to the nearest point of the previous generation's, with every
//     objective normalised by the current front's range (an IGD between successive fronts);
//   * the answer: the map the final population would recommend (the set most individuals share,
//     ties to the lowest normalised sum of objectives, as candidate_selection.h chooses) and the
//     knee of the front, each compared by its objective vector — sets that give the same map are
//     one answer.
// The optimisation has settled when, for `window` consecutive generations, the front moved less
// than `tolerance` and the recommendation's and the knee's objective vectors stayed the same. The rule
// reads only what every saved generation holds (decision and objective vectors), so a resumed
// run replays the saved generations through it and stops at the same generation.
//
// A search for a broken map asks a narrower question — which parameters give a sound map — and
// its front keeps moving long after that is answered (eleven parameters, most of them refining
// maps that are already right; docs/benchmarks.md, "A budget for a broken map"). With
// `sound_answer_window` N > 0 the rule also ends the search once the recommendation is a sound
// map (its run did not fail: with the front-end search a run that breaks is stopped and failed)
// and its objective vector stayed the same for N generations in a row, counted from
// generation 0.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/optim/search_space.h"

namespace slamtune::optim {

struct SettlingOptions {
  bool enabled = true;
  double tolerance = 0.0025;  // mean normalised front movement per generation, in (0, 1)
  int window = 3;             // generations in a row that must satisfy the rule, >= 1
  // Also settled when the recommendation is a sound map, unchanged for this many generations in
  // a row (>= 0; 0 = off).
  int sound_answer_window = 0;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
  // As stored in the run folder; FromJson reads folders written before sound_answer_window
  // existed as 0 (off), which is how they ran.
  nlohmann::json ToJson() const;
  static SettlingOptions FromJson(const nlohmann::json& j);
};

// Whether an objective vector is a failed run's score (ObjectiveSet::IsFailureScore).
using FailureTest = std::function<bool(const std::vector<double>& scores)>;

class SettlingRule {
 public:
  // `is_failure` tells failed runs' scores (needed by sound_answer_window; none without it).
  SettlingRule(SettlingOptions options, SearchSpace space, FailureTest is_failure = nullptr);

  // Feeds one finished generation (its population); returns true once the optimisation has
  // settled (and stays true). Generation numbers must increase by one, from 0 or 1: the front's
  // movement is measured from generation 1 on, the sound answer from the first fed.
  bool Update(unsigned generation, const std::vector<std::vector<double>>& x,
              const std::vector<std::vector<double>>& f);

  bool settled() const { return settled_at_ > 0; }
  unsigned settled_at() const { return settled_at_; }  // 0 while not settled
  double last_movement() const { return last_movement_; }
  // One sentence: when and why it stopped, or that it ran the whole budget.
  std::string Describe(unsigned generations_budget) const;

 private:
  SettlingOptions options_;
  SearchSpace space_;
  FailureTest is_failure_;
  std::vector<std::vector<double>> previous_front_;
  std::vector<double> previous_recommended_, previous_knee_;  // objective vectors
  bool last_answer_changed_ = false;
  int calm_generations_ = 0;
  // The sound-answer rule: for how many generations in a row (after the first) the
  // recommendation was the same sound map as in the generation before.
  int sound_generations_ = 0;
  bool settled_by_sound_answer_ = false;
  bool fed_ = false;
  unsigned last_generation_ = 0;
  unsigned settled_at_ = 0;
  double last_movement_ = -1.0;
};

// The front's movement between two sets of objective vectors: the mean distance from each point
// of `current` to the nearest point of `previous`, each objective normalised by `current`'s range
// (a zero range counts as 1). 1 when `previous` is empty.
double FrontMovement(const std::vector<std::vector<double>>& previous, const std::vector<std::vector<double>>& current);

// The non-dominated vectors of `f` (duplicates kept once).
std::vector<std::vector<double>> NonDominatedVectors(const std::vector<std::vector<double>>& f);

}  // namespace slamtune::optim
