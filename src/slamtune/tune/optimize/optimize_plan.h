// Everything an optimisation runs with, decided before its first SLAM run: the search space
// (--space, --vary/--fix, or chosen by one run of the base configuration, with the front end's
// informed start when that run breaks), the objective set, the budget (the user's, a broken map's,
// the built-in world's or the defaults) and the evaluation context. Each is validated before any
// work starts; what the tuner decided is written back into the options, which the run folder
// records for --resume.
#pragma once

#include <memory>
#include <optional>

#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/optim/optimizer.h"
#include "slamtune/tune/optimize/optimize_options.h"
#include "slamtune/tune/optimize/run_folder.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

// The budget the tuner gives what the user left to it.
struct BudgetDefaults {
  std::size_t population = optim::OptimizeSettings{}.population;
  unsigned generations = optim::OptimizeSettings{}.generations;
  std::size_t divisions = optim::OptimizeSettings{}.divisions;
  int sound_answer_window = optim::SettlingOptions{}.sound_answer_window;
};
// On a built-in world (a new run without a log): a few minutes on 2 cores, 20 individuals over
// the 66 reference points of 10 divisions, 8 generations. A world whose map breaks in the front
// end (the main job's office-jump) takes the broken-map budget's population, divisions and stop
// within these 8 generations.
inline constexpr BudgetDefaults kBuiltInWorldBudget{20, 8, 10, 0};
// The defaults for a run: kBuiltInWorldBudget for a new run on a built-in world, else OptimizeSettings'.
BudgetDefaults DefaultBudget(bool built_in_world, bool resume);
// A base map that breaks in the front end: optim::BrokenMapBudget's population, divisions and
// sound-answer stop over `defaults`.
BudgetDefaults BrokenMapDefaults(BudgetDefaults defaults);

struct OptimizationPlan {
  optim::OptimizeSettings settings;
  std::shared_ptr<optim::SlamEvaluationContext> context;
  std::optional<optim::BaseFrontEnd> base_front_end;  // when a run of the base configuration chose the space
};

// Plans the optimisation of `inputs` (loaded from options.inputs). The run of the base
// configuration that chooses the space (no --space, no --vary) comes after the folder is known
// to be usable (folder.EnsureLocked); what it decides, and the resolved budget, go into
// `options`. Notes on stderr unless run.quiet.
OptimizationPlan PlanOptimization(const TuningInputs& inputs, RunFolder& folder, OptimizeOptions& options,
                                  const TuningRunOptions& run);

// The search space --space names, or its YAML file (or, resuming a folder written before named
// spaces, r and g around the base without steps).
optim::SearchSpace NamedOrFileSpace(const OptimizeOptions& options, const slam::MapperParams& base);

}  // namespace slamtune::tune
