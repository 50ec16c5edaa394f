// The whole method of Han et al. (Sensors 2020) on one log: NSGA-III (nsga3/nsga3.h) over the
// search space, each candidate scored by the map objectives of its SLAM run, then the
// candidates an engineer needs (candidate_selection.h).
//
// Interruption loses nothing: every finished evaluation is committed to the run database at
// once (batch_evaluator.h), and after every generation the population and the generator state
// are saved. A resumed run rebuilds the last finished generation's population, restores the
// generator and evolves the remaining generations, its evaluations served from the database,
// so it ends with exactly the result an uninterrupted run with the same seed gives.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>

#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/evaluation_store.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/optimize_result.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/optim/settling.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::optim {

struct OptimizeSettings {
  LogSource source;  // the log and relations labels are stored for the --resume check
  SearchSpace space = SearchSpace::PaperDefault();
  ObjectiveSet objectives;        // what NSGA-III minimises and the candidates are ranked by
  Assignment default_assignment;  // the base configuration's values of the varied (and fixed) parameters
  std::string base_label = "slam_karto's defaults";  // what the base is: "your configuration (FILE)", ...
  // The node and mode the base is for (its node_mode, also in `engine`); for the report.
  slam::NodeMode node_mode = slam::NodeMode::kSlamKarto;
  // Das-Dennis divisions: M = 3, D = 7 -> 36 reference points, one individual each. On the
  // shared logs the paper's 66 individuals (D = 10) find answers within 0.5 mm of error of these
  // and take up to twice as long (docs/benchmarks.md); --population 66 --divisions 10 asks for them.
  std::size_t divisions = 7;
  std::size_t population = 36;
  unsigned generations = 60;  // the paper's generations: the most that are run
  SettlingOptions settling;   // stop earlier once the answer has settled (settling.h)
  unsigned seed = 1;
  // Individuals of generation 0 before the random ones (e.g. the front end's informed start,
  // front_end_repair.h), each a value for every dimension of `space`.
  std::vector<Assignment> seeds;
  nlohmann::json engine;      // everything else that changes results (base parameters, metric options, log identity)
  nlohmann::json invocation;  // the command line that started the run: stored with the settings, not compared

  // Throws InputError naming the field (population >= 4, generations >= 1, divisions >= 1).
  void Validate() const;
  // What must match for --resume (everything but parallelism).
  nlohmann::json ToJson() const;
};

struct OptimizeHooks {
  // A progress line; `force` for lines that must be shown (generation ends).
  std::function<void(const std::string& line, bool force)> progress;
  // Renders the map and loop closures of one parameter set (for the report); may be empty.
  std::function<CandidateMap(const Assignment&)> render_map;
  // Called once the run's start is committed (or the stored run accepted for resuming),
  // before the first evaluation; may be empty.
  std::function<void()> started;
};

// Whether RunOptimization starts a new run in an empty run database or continues the run
// stored there (--resume).
enum class OptimizationStart { kNew, kResume };

// Runs (or, with kResume, continues) an optimisation. `store` must be the run database; a
// resumed run's stored settings must equal `settings` (InputError otherwise, before any work).
OptimizeResult RunOptimization(const OptimizeSettings& settings, BatchEvaluator& evaluator, EvaluationStore& store,
                               OptimizationStart start, const OptimizeHooks& hooks);

}  // namespace slamtune::optim
