#include "slamtune/tune/optimize/optimize_plan.h"

#include <fmt/format.h>

#include <cstdio>

#include "slamtune/common/error.h"
#include "slamtune/optim/front_end_repair.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/space_choice.h"
#include "slamtune/slam/params/params_yaml.h"

namespace slamtune::tune {
namespace {

// The settings from the options: a named objective set (checked before any work; the automatic
// choice waits for the search space), early stopping and the budget.
optim::OptimizeSettings OptionSettings(const OptimizeOptions& options, const BudgetDefaults& defaults) {
  optim::OptimizeSettings settings;
  if (options.objectives != kAutomaticObjectives) {
    try {
      settings.objectives = optim::ObjectiveSet::Parse(options.objectives);
    } catch (const InputError&) {
      throw InputError(fmt::format("--objectives: unknown objective set '{}' (known: {}, {})", options.objectives,
                                   kAutomaticObjectives, optim::ObjectiveSet::KnownNames()));
    }
  }
  settings.settling = options.settling;
  settings.seed = options.seed;
  const OptimizeBudget& b = options.budget;
  settings.population = b.population.value_or(defaults.population);
  settings.generations = b.generations.value_or(defaults.generations);
  settings.divisions = b.divisions.value_or(defaults.divisions);
  settings.settling.sound_answer_window = b.sound_answer_window.value_or(defaults.sound_answer_window);
  return settings;
}

// The search space given by --vary/--fix, if any.
std::optional<optim::SearchSpace> FlagSpace(const OptimizeOptions& options) {
  if (!options.vary.empty() && !options.space.empty()) {
    throw InputError("give the search space either with --space or with --vary/--fix, not both");
  }
  if (options.vary.empty() && !options.fix.empty()) {
    throw InputError(
        "--fix goes with --vary (it holds a value while others are searched); to change a base "
        "value, use --set NAME=VALUE");
  }
  if (options.vary.empty()) return std::nullopt;
  return optim::SearchSpace::FromFlags(options.vary, options.fix);
}

// No --space: loop closure, or the front end when the base configuration's map breaks there
// (one SLAM run, after the output folder is known to be usable). Sets options.space to the
// chosen space's name (and the informed start) and returns the context of that run.
std::shared_ptr<optim::SlamEvaluationContext> ProbeDefaultSpace(const TuningInputs& inputs, RunFolder& folder,
                                                                OptimizeOptions& options, const TuningRunOptions& run,
                                                                OptimizationPlan& plan) {
  folder.EnsureLocked();
  options.space_probed = true;
  auto probed = MakeEvaluationContext(inputs, {}, run);
  optim::DefaultSpaceChoice choice = optim::ChooseDefaultSpace(*probed);
  options.space = choice.space_name();
  if (!run.quiet) std::fprintf(stderr, "%s\n", choice.Reason().c_str());
  std::string informed;
  if (choice.kind == optim::DefaultSpaceKind::kFrontEnd) {
    const optim::SearchSpace space = optim::SearchSpace::FrontEnd(inputs.base);
    const optim::FrontEndRepair repair = optim::RepairFrontEnd(*probed, choice.steps, choice.evidence, space);
    options.space_lower = repair.lower_bounds;
    if (!repair.repaired.empty()) {
      optim::Assignment individual;
      for (const optim::Dimension& d : optim::WithLowerBounds(space, repair.lower_bounds).dimensions) {
        individual[d.name] =
            repair.repaired.count(d.name) ? repair.repaired.at(d.name) : slam::GetNumeric(inputs.base, d.name);
      }
      options.initial = {individual};
    }
    informed = repair.Describe();
    if (!run.quiet && !informed.empty()) std::fprintf(stderr, "%s\n", informed.c_str());
  }
  plan.base_front_end = optim::BaseFrontEnd{choice.evidence, std::move(choice.steps), choice.Reason(),
                                            informed,        std::move(choice.map),   std::move(choice.trajectory)};
  return probed;
}

// "budget for a broken map: ..." on stderr.
void SayBrokenMapBudget(const optim::OptimizeSettings& settings) {
  const int window = settings.settling.sound_answer_window;
  const std::string stop = window == 0 ? "stopping when the front settles"
                                       : fmt::format(
                                             "stopping once the recommended map is sound and unchanged for "
                                             "{} generation{}",
                                             window, window == 1 ? "" : "s");
  std::fprintf(stderr,
               "budget for a broken map: population %zu over %zu divisions, %s (--population, --divisions, "
               "--sound-answer-window)\n",
               settings.population, settings.divisions, stop.c_str());
}

// What the report says of the base configuration and the run's inputs, and what of them must
// match on --resume: the baseline is the base configuration itself, its values of the varied
// and the fixed parameters.
void DescribeBase(const TuningInputs& inputs, const TuningInputOptions& input_options,
                  optim::OptimizeSettings& settings) {
  for (const auto& d : settings.space.dimensions) {
    settings.default_assignment[d.name] = slam::GetNumeric(inputs.base, d.name);
  }
  for (const auto& [name, value] : settings.space.fixed) {
    settings.default_assignment[name] = slam::GetNumeric(inputs.base, name);
  }
  settings.base_label = inputs.base_label;
  settings.node_mode = inputs.base.node_mode;
  settings.source = inputs.source;
  settings.engine = {{"inputs", input_options.ToJson()}, {"base", nlohmann::json::object()}};
  for (const auto& p : slam::ToNamedValues(inputs.base)) {
    std::visit([&](const auto& v) { settings.engine["base"][p.name] = v; }, p.value);
  }
}

// The space and its seeds: from the flags, a name or file, or the probe's choice.
std::shared_ptr<optim::SlamEvaluationContext> ChooseSpace(const TuningInputs& inputs, RunFolder& folder,
                                                          OptimizeOptions& options, const TuningRunOptions& run,
                                                          BudgetDefaults& defaults, OptimizationPlan& plan) {
  optim::OptimizeSettings& settings = plan.settings;
  const std::optional<optim::SearchSpace> flag_space = FlagSpace(options);
  settings.Validate();  // the budget, before any run
  std::shared_ptr<optim::SlamEvaluationContext> probed;
  if (options.space.empty() && !flag_space && !options.around_base_without_steps) {
    probed = ProbeDefaultSpace(inputs, folder, options, run, plan);
    // A break (not only a featureless stretch): runs that break there fail, so a sound map means
    // one that held. Not for a featureless stretch alone, where every map would count as sound.
    if (ParseNamedSpace(options.space) == NamedSpace::kFrontEnd && plan.base_front_end->evidence.breaks > 0) {
      defaults = BrokenMapDefaults(defaults);
      settings = OptionSettings(options, defaults);
      if (!run.quiet) SayBrokenMapBudget(settings);
    }
  } else if (options.space_probed && !flag_space) {
    // Resuming a run whose space the base's run chose: that run again, for what it found of the
    // front end; the space and the informed start stay the recorded ones.
    const OptimizeOptions recorded = options;
    probed = ProbeDefaultSpace(inputs, folder, options, run, plan);
    options.space = recorded.space;
    options.space_lower = recorded.space_lower;
    options.initial = recorded.initial;
  }
  settings.space = flag_space ? *flag_space : NamedOrFileSpace(options, inputs.base);
  if (!flag_space) settings.seeds = options.initial;
  optim::CheckSpaceAgainst(settings.space, inputs.base,
                           flag_space                       ? "--vary/--fix"
                           : ParseNamedSpace(options.space) ? "--space"
                                                            : options.space);
  return probed;
}

}  // namespace

BudgetDefaults DefaultBudget(bool built_in_world, bool resume) {
  return built_in_world && !resume ? kBuiltInWorldBudget : BudgetDefaults{};
}

BudgetDefaults BrokenMapDefaults(BudgetDefaults defaults) {
  const optim::BrokenMapBudget broken;
  defaults.population = broken.population;
  defaults.divisions = broken.divisions;
  defaults.sound_answer_window = broken.sound_answer_window;
  return defaults;
}

optim::SearchSpace NamedOrFileSpace(const OptimizeOptions& options, const slam::MapperParams& base) {
  if (options.around_base_without_steps) {
    return optim::SearchSpace::AroundBase(base.loop_search_maximum_distance, base.loop_match_minimum_chain_size);
  }
  const std::optional<NamedSpace> named = ParseNamedSpace(options.space);
  if (!named) return optim::SearchSpace::FromYaml(options.space);
  switch (*named) {
    case NamedSpace::kLoop: return optim::SearchSpace::Loop(base);
    case NamedSpace::kPaper: return optim::SearchSpace::PaperDefault();
    case NamedSpace::kFrontEnd: return optim::WithLowerBounds(optim::SearchSpace::FrontEnd(base), options.space_lower);
  }
  SLAMTUNE_CHECK(false);
  return {};
}

OptimizationPlan PlanOptimization(const TuningInputs& inputs, RunFolder& folder, OptimizeOptions& options,
                                  const TuningRunOptions& run) {
  OptimizationPlan plan;
  BudgetDefaults defaults = DefaultBudget(options.inputs.log.empty(), folder.resume());
  optim::OptimizeSettings& settings = plan.settings;
  settings = OptionSettings(options, defaults);
  run.Validate();
  std::shared_ptr<optim::SlamEvaluationContext> probed = ChooseSpace(inputs, folder, options, run, defaults, plan);
  if (options.objectives == kAutomaticObjectives) {
    options.objectives =
        optim::ObjectiveSet::NameOf(optim::DefaultObjectiveSetKind(settings.space.VariesMapSampling()));
    settings.objectives = optim::ObjectiveSet::Parse(options.objectives);
  }
  settings.Validate();
  // What the tuner decided, recorded for --resume.
  options.budget = {settings.population, settings.generations, settings.divisions,
                    settings.settling.sound_answer_window};
  plan.context =
      probed && settings.space.fixed.empty() ? probed : MakeEvaluationContext(inputs, settings.space.fixed, run);
  optim::DrawWall(*plan.context, optim::WallDrawingFor(settings.objectives));
  // Runs that differ in their front end may break where others hold: stop them there.
  plan.context->stop_broken_runs = settings.space.VariesFrontEnd();
  DescribeBase(inputs, options.inputs, settings);
  settings.engine["stop_broken_runs"] = plan.context->stop_broken_runs;
  return plan;
}

}  // namespace slamtune::tune
