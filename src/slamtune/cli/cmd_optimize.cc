// `slamtune optimize [LOG] --out DIR`: NSGA-III over the loop-closure parameters, scored by
// the map objectives of each SLAM run, with a report an engineer can act on. Under mpirun,
// rank 0 optimises and writes; the other ranks evaluate (optim/mpi_evaluation.h).
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/recommendation_files.h"
#include "slamtune/cli/result_neutral_options.h"
#include "slamtune/cli/tuning_inputs.h"
#include "slamtune/common/error.h"
#include "slamtune/common/folder_lock.h"
#include "slamtune/common/progress.h"
#include "slamtune/common/signal_notice.h"
#include "slamtune/io/content_hash.h"
#include "slamtune/nsga3/reference_points.h"
#include "slamtune/optim/front_end_repair.h"
#include "slamtune/optim/mpi_evaluation.h"
#include "slamtune/optim/optimizer.h"
#include "slamtune/optim/slam_evaluation.h"
#include "slamtune/optim/space_choice.h"
#include "slamtune/report/optimize_report.h"
#include "slamtune/slam/params_yaml.h"

namespace slamtune::cli {
namespace {

// --objectives auto: the set is chosen from the search space (optim::DefaultObjectiveSetKind).
constexpr const char* kAutomaticObjectives = "auto";

struct OptimizeArgs {
  TuningInputOptions inputs;
  std::string out;
  std::string resume;
  std::string space_file;
  std::vector<std::string> vary;  // --vary NAME=MIN:MAX[:STEP]: the space from the command line
  std::vector<std::string> fix;   // --fix NAME=VALUE, with --vary
  bool verbose = false;           // --verbose: the shared-work caches' statistics
  // Resuming a folder written before named spaces (no space, no --vary): r and g around the
  // base without steps (SearchSpace::AroundBase), not the default-space probe.
  bool around_base_without_steps = false;
  std::string objectives = kAutomaticObjectives;
  optim::SettlingOptions settling;  // --no-early-stop, --stop-tolerance, --stop-window
  std::size_t population = optim::OptimizeSettings{}.population;
  unsigned generations = optim::OptimizeSettings{}.generations;
  std::size_t divisions = optim::OptimizeSettings{}.divisions;
  unsigned seed = 1;
  // Budget flags the user gave; the others take the default of the search (the built-in world's,
  // or a broken map's: optim::BrokenMapBudget).
  bool population_given = false, divisions_given = false, generations_given = false, sound_answer_given = false;
  // The front end's informed start (optim/front_end_repair.h) when the default space is the
  // front end: the space's raised lower bounds and the repaired configuration; kept for --resume.
  std::map<std::string, double> space_lower;
  std::vector<optim::Assignment> initial;
  // The space was chosen by a run of the base configuration (no --space, no --vary): what that
  // run found of the front end goes into the report and results.json (base_front_end), and a
  // resumed run makes it again, so that it writes what the uninterrupted one writes.
  bool space_probed = false;
  TuningRunOptions run;
  ResultNeutralOptions result_neutral;  // the options that may accompany --resume
};

// The budget on a built-in world: a few minutes on 2 cores (20 individuals over the 66
// reference points of 10 divisions, 8 generations). A world whose map breaks in the front end
// (the main job's office-jump) takes the broken-map budget's population, divisions and stop,
// within these 8 generations.
constexpr std::size_t kBuiltInPopulation = 20;
constexpr unsigned kBuiltInGenerations = 8;
constexpr std::size_t kBuiltInDivisions = 10;

// The files whose content the run depends on, by their key in TuningInputOptions::ToJson.
std::map<std::string, std::string> InputFiles(const TuningInputOptions& in) {
  return {{"log", in.log}, {"params", in.params_file}, {"relations", in.relations}};
}

nlohmann::json InvocationJson(const OptimizeArgs& a) {
  return {{"inputs", a.inputs.ToJson()},
          {"space", a.space_file},
          {"vary", a.vary},
          {"fix", a.fix},
          {"population", a.population},
          {"generations", a.generations},
          {"divisions", a.divisions},
          {"seed", a.seed},
          {"objectives", a.objectives},
          {"front_end_repair", {{"lower_bounds", a.space_lower}, {"initial", a.initial}}},
          {"space_probed", a.space_probed},
          {"input_hashes", io::ContentHashes(InputFiles(a.inputs))},
          {"settling", a.settling.ToJson()}};
}

// The recorded inputs that are the files named now must still have their recorded content
// (runs recorded before content hashes were kept are not checked).
void RequireRecordedContent(const nlohmann::json& invocation, const TuningInputOptions& inputs) {
  if (!invocation.contains("input_hashes")) return;
  std::map<std::string, std::string> same_path;
  for (const auto& [key, path] : InputFiles(inputs)) {
    if (invocation.at("inputs").value(key, std::string()) == path) same_path[key] = path;
  }
  io::RequireSameContent(invocation.at("input_hashes").get<std::map<std::string, std::string>>(), same_path);
}

// The run's folder (--out DIR, or --resume DIR) and its run database. One process at a time
// works in it, from before its database is read to the last report file (FolderLock).
class RunFolder {
 public:
  // InputError for --out and --resume naming different folders, or neither.
  RunFolder(const std::string& out, const std::string& resume) : resume_(!resume.empty()) {
    if (resume_ && !out.empty() && out != resume) {
      throw InputError("give either --out DIR or --resume DIR, not both with different folders");
    }
    dir_ = resume_ ? resume : out;
    if (dir_.empty()) throw InputError("--out DIR is required (or --resume DIR to continue a run)");
    db_path_ = (std::filesystem::path(dir_) / "run.sqlite").string();
  }

  const std::string& dir() const { return dir_; }
  const std::string& db_path() const { return db_path_; }
  bool resume() const { return resume_; }

  // Locks the folder now if it can be locked before the inputs are read: it exists and can be
  // written (else EnsureLocked creates and checks it after the inputs, and locks it then).
  void LockIfWritable() {
    if (std::filesystem::is_directory(dir_) && access(dir_.c_str(), W_OK) == 0) lock_.emplace(dir_);
  }
  // Creates and checks the folder, and locks it unless it is locked already; a new run's
  // folder must not hold another.
  void EnsureLocked() {
    EnsureWritableOutputFolder(dir_);
    if (!lock_) {
      lock_.emplace(dir_);
      if (!resume_) RefuseHeldRun();
    }
  }
  void RefuseHeldRun() const {
    if (std::filesystem::exists(db_path_)) {
      throw InputError(dir_, 0, "already holds an optimisation; use --resume DIR or a new --out");
    }
  }

 private:
  std::string dir_;
  std::string db_path_;
  bool resume_ = false;
  std::optional<FolderLock> lock_;
};

// --resume DIR: before anything is printed, the run database must be whole (PRAGMA
// quick_check); alone (with options that do not change results), --resume takes the settings
// from it; the input files must be unchanged.
void PrepareResume(const RunFolder& folder, const CLI::App& app, OptimizeArgs& args) {
  const std::string& db_path = folder.db_path();
  if (!std::filesystem::exists(db_path)) {
    throw InputError(folder.dir(), 0, "--resume: not a slamtune optimisation folder (no run.sqlite)");
  }
  optim::CheckRunDatabase(db_path);
  std::optional<nlohmann::json> inv = optim::EvaluationStore(db_path).Meta("invocation");
  if (args.result_neutral.OnlyTheseGiven(app)) {
    if (!inv) throw InputError(db_path, 0, "--resume: the run database holds no command line");
    args.inputs = TuningInputOptions::FromJson(inv->at("inputs"));
    args.space_file = inv->at("space");
    args.vary = inv->value("vary", std::vector<std::string>{});
    args.fix = inv->value("fix", std::vector<std::string>{});
    args.around_base_without_steps = args.space_file.empty() && args.vary.empty();
    args.population = inv->at("population");
    args.generations = inv->at("generations");
    args.divisions = inv->at("divisions");
    args.seed = inv->at("seed");
    args.space_probed = inv->value("space_probed", false);
    if (inv->contains("front_end_repair")) {
      const auto& repair = inv->at("front_end_repair");
      args.space_lower = repair.at("lower_bounds").get<std::map<std::string, double>>();
      args.initial = repair.at("initial").get<std::vector<optim::Assignment>>();
    }
    // Folders written before objective sets existed were optimised on the paper's.
    args.objectives = inv->value("objectives", optim::ObjectiveSet::NameOf(optim::ObjectiveSetKind::kPaper));
    // ... and ran their whole budget.
    if (inv->contains("settling")) {
      args.settling = optim::SettlingOptions::FromJson(inv->at("settling"));
    } else {
      args.settling.enabled = false;
    }
  }
  if (inv) RequireRecordedContent(*inv, args.inputs);
}

// Everything the optimisation runs with, decided before its first SLAM run.
struct OptimizationPlan {
  optim::OptimizeSettings settings;
  std::shared_ptr<optim::SlamEvaluationContext> context;
  std::optional<optim::BaseFrontEnd> base_front_end;  // when a run of the base configuration chose the space
};

// The settings from the command line: a named objective set (checked before any work; the
// automatic choice waits for the search space), early stopping and the budget.
optim::OptimizeSettings CommandLineSettings(const OptimizeArgs& args) {
  optim::OptimizeSettings settings;
  if (args.objectives != kAutomaticObjectives) {
    try {
      settings.objectives = optim::ObjectiveSet::Parse(args.objectives);
    } catch (const InputError&) {
      throw InputError(fmt::format("--objectives: unknown objective set '{}' (known: {}, {})", args.objectives,
                                   kAutomaticObjectives, optim::ObjectiveSet::KnownNames()));
    }
  }
  settings.settling = args.settling;
  settings.population = args.population;
  settings.generations = args.generations;
  settings.divisions = args.divisions;
  settings.seed = args.seed;
  return settings;
}

// The search space given by --vary/--fix, if any.
std::optional<optim::SearchSpace> FlagSpace(const OptimizeArgs& args) {
  if (!args.vary.empty() && !args.space_file.empty()) {
    throw InputError("give the search space either with --space or with --vary/--fix, not both");
  }
  if (args.vary.empty() && !args.fix.empty()) {
    throw InputError(
        "--fix goes with --vary (it holds a value while others are searched); to change a base "
        "value, use --set NAME=VALUE");
  }
  if (args.vary.empty()) return std::nullopt;
  return optim::SearchSpace::FromFlags(args.vary, args.fix);
}

// No --space: loop closure, or the front end when the base configuration's map breaks there
// (one SLAM run, after the output folder is known to be usable). Sets args.space_file to the
// chosen space's name and returns the context of that run.
std::shared_ptr<optim::SlamEvaluationContext> ProbeDefaultSpace(const TuningInputs& inputs, RunFolder& folder,
                                                                OptimizeArgs& args, OptimizationPlan& plan) {
  folder.EnsureLocked();
  args.space_probed = true;
  auto probed = MakeEvaluationContext(inputs, {}, args.run);
  optim::DefaultSpaceChoice choice = optim::ChooseDefaultSpace(*probed);
  args.space_file = choice.space_name();
  if (!args.run.quiet) std::fprintf(stderr, "%s\n", choice.Reason().c_str());
  std::string informed;
  if (choice.kind == optim::DefaultSpaceKind::kFrontEnd) {
    const optim::SearchSpace space = optim::SearchSpace::FrontEnd(inputs.base);
    const optim::FrontEndRepair repair = optim::RepairFrontEnd(*probed, choice.steps, choice.evidence, space);
    args.space_lower = repair.lower_bounds;
    if (!repair.repaired.empty()) {
      optim::Assignment individual;
      for (const optim::Dimension& d : optim::WithLowerBounds(space, repair.lower_bounds).dimensions) {
        individual[d.name] =
            repair.repaired.count(d.name) ? repair.repaired.at(d.name) : slam::GetNumeric(inputs.base, d.name);
      }
      args.initial = {individual};
    }
    informed = repair.Describe();
    if (!args.run.quiet && !informed.empty()) std::fprintf(stderr, "%s\n", informed.c_str());
  }
  plan.base_front_end = optim::BaseFrontEnd{choice.evidence, std::move(choice.steps), choice.Reason(),
                                            informed,        std::move(choice.map),   std::move(choice.trajectory)};
  return probed;
}

// A base map that breaks in the front end: the broken-map budget (optim::BrokenMapBudget) for
// what the user left to the tuner. Not for a featureless stretch alone, where no run breaks and
// every map would count as sound.
void UseBrokenMapBudget(OptimizeArgs& args, optim::OptimizeSettings& settings) {
  const optim::BrokenMapBudget budget;
  if (!args.population_given) args.population = budget.population;
  if (!args.divisions_given) args.divisions = budget.divisions;
  if (!args.sound_answer_given) args.settling.sound_answer_window = budget.sound_answer_window;
  settings.population = args.population;
  settings.divisions = args.divisions;
  settings.settling = args.settling;
  if (!args.run.quiet) {
    const int window = args.settling.sound_answer_window;
    const std::string stop = window == 0 ? "stopping when the front settles"
                                         : fmt::format(
                                               "stopping once the recommended map is sound and unchanged for "
                                               "{} generation{}",
                                               window, window == 1 ? "" : "s");
    std::fprintf(stderr,
                 "budget for a broken map: population %zu over %zu divisions, %s (--population, --divisions, "
                 "--sound-answer-window)\n",
                 args.population, args.divisions, stop.c_str());
  }
}

// --space NAME or FILE (or, resuming a folder written before named spaces, r and g around the base).
optim::SearchSpace NamedOrFileSpace(const OptimizeArgs& args, const slam::MapperParams& base) {
  if (args.space_file == "loop") return optim::SearchSpace::Loop(base);
  if (args.around_base_without_steps) {
    return optim::SearchSpace::AroundBase(base.loop_search_maximum_distance, base.loop_match_minimum_chain_size);
  }
  if (args.space_file == "paper") return optim::SearchSpace::PaperDefault();
  if (args.space_file == "front-end") {
    return optim::WithLowerBounds(optim::SearchSpace::FrontEnd(base), args.space_lower);
  }
  return optim::SearchSpace::FromYaml(args.space_file);
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
  settings.log_path = inputs.log_label;
  settings.log_input = inputs.log_input;
  settings.scans_not_used = inputs.scans_not_used;
  settings.relations_path = inputs.relations_label;
  settings.engine = {{"inputs", input_options.ToJson()}, {"base", nlohmann::json::object()}};
  for (const auto& p : slam::ToNamedValues(inputs.base)) {
    std::visit([&](const auto& v) { settings.engine["base"][p.name] = v; }, p.value);
  }
}

// Preamble: the settings, the search space, the objective set and the evaluation context,
// each validated before any work starts.
OptimizationPlan PlanOptimization(const TuningInputs& inputs, RunFolder& folder, OptimizeArgs& args) {
  OptimizationPlan plan;
  optim::OptimizeSettings& settings = plan.settings;
  settings = CommandLineSettings(args);
  args.run.Validate();
  const std::optional<optim::SearchSpace> flag_space = FlagSpace(args);
  settings.Validate();  // the budget, before any run
  std::shared_ptr<optim::SlamEvaluationContext> probed;
  if (args.space_file.empty() && !flag_space && !args.around_base_without_steps) {
    probed = ProbeDefaultSpace(inputs, folder, args, plan);
    // A break (not only a featureless stretch): runs that break there fail, so a sound map means one that held.
    if (args.space_file == std::string("front-end") && plan.base_front_end->evidence.breaks > 0) {
      UseBrokenMapBudget(args, settings);
    }
  } else if (args.space_probed && !flag_space) {
    // Resuming a run whose space the base's run chose: that run again, for what it found of the
    // front end; the space and the informed start stay the recorded ones.
    const std::string space_file = args.space_file;
    const std::map<std::string, double> space_lower = args.space_lower;
    const std::vector<optim::Assignment> initial = args.initial;
    probed = ProbeDefaultSpace(inputs, folder, args, plan);
    args.space_file = space_file;
    args.space_lower = space_lower;
    args.initial = initial;
  }
  settings.space = flag_space ? *flag_space : NamedOrFileSpace(args, inputs.base);
  if (!flag_space) settings.seeds = args.initial;
  if (args.objectives == kAutomaticObjectives) {
    args.objectives = optim::ObjectiveSet::NameOf(optim::DefaultObjectiveSetKind(settings.space.VariesMapSampling()));
    settings.objectives = optim::ObjectiveSet::Parse(args.objectives);
  }
  settings.Validate();
  const bool named_space = args.space_file == "loop" || args.space_file == "paper" || args.space_file == "front-end";
  optim::CheckSpaceAgainst(settings.space, inputs.base,
                           flag_space    ? "--vary/--fix"
                           : named_space ? "--space"
                                         : args.space_file);
  plan.context =
      probed && settings.space.fixed.empty() ? probed : MakeEvaluationContext(inputs, settings.space.fixed, args.run);
  optim::DrawWall(*plan.context, optim::WallDrawingFor(settings.objectives));
  // Runs that differ in their front end may break where others hold: stop them there.
  plan.context->stop_broken_runs = settings.space.VariesFrontEnd();
  DescribeBase(inputs, args.inputs, settings);
  settings.engine["stop_broken_runs"] = plan.context->stop_broken_runs;
  return plan;
}

// The progress hooks of the optimisation: its lines (with the shared work's counts under
// --verbose) and the candidates' maps.
optim::OptimizeHooks ProgressHooks(Progress& progress, const std::shared_ptr<optim::SlamEvaluationContext>& context,
                                   const TuningProcess& process, bool verbose) {
  optim::OptimizeHooks hooks;
  // Under mpirun the counts are rank 0's own runs (each rank has its own caches).
  const std::string shared_label = process.has_workers() ? "rank 0 " : "";
  hooks.progress = [&progress, context, shared_label, verbose](const std::string& line, bool force) {
    const std::string shared = verbose ? optim::SharedWorkBrief(*context) : std::string();
    progress.Update(shared.empty() ? line : line + " | " + shared_label + shared, force);
  };
  hooks.render_map = [context](const optim::Assignment& a) { return optim::RenderSlamMap(*context, a); };
  return hooks;
}

// The first line: what is optimised on what, with which budget and parallelism, and where to.
std::string Headline(const optim::OptimizeSettings& settings, const TuningInputs& inputs,
                     const std::string& parallelism, const std::string& dir) {
  const std::size_t total = settings.population * (settings.generations + 1);
  return fmt::format(
      "optimising {} on {}: population {}, {} generations (<= {} SLAM runs), {}, "
      "seed {}; maps judged by {}; results in {}",
      settings.space.size() == 2 ? "r and g" : "the search space", inputs.log_label, settings.population,
      settings.generations, total, parallelism, settings.seed, settings.objectives.Describe(), dir);
}

// One line per candidate: its parameters, objectives, loop closures and errors.
void PrintCandidates(const optim::OptimizeResult& result, const optim::SearchSpace& space) {
  for (const auto& c : result.candidates) {
    std::string params;
    for (const auto& d : space.dimensions) {
      params += fmt::format("{}{}={:.4g}", params.empty() ? "" : " ", d.name, c.record.params.at(d.name));
    }
    std::string objectives;
    for (optim::Objective o : result.objectives.objectives()) {
      objectives += fmt::format("{}{} {:.4g}", objectives.empty() ? "" : " ", optim::InfoOf(o).short_name,
                                optim::ValueOf(c.record, o));
    }
    std::printf(
        "%-12s %s | %s | loops %d%s\n", c.label.c_str(), params.c_str(), objectives.c_str(), c.record.loop_closures,
        c.record.has_gt
            ? fmt::format(" | trans {:.4f} m rot {:.3f} deg", c.record.trans_mean_m, c.record.rot_mean_deg).c_str()
            : "");
  }
}

// The verdict, the candidates, the changes to make and what was written, on stdout.
void PrintOutcome(const optim::OptimizeResult& result, const RecommendationFiles& files, std::size_t report_files,
                  const optim::SearchSpace& space, const std::string& base_label, const std::string& dir) {
  std::printf("%s\n\n", result.verdict.c_str());
  PrintCandidates(result, space);
  if (result.verdict_kind == optim::VerdictKind::kBetter) {
    std::printf("\nchanges from %s (best_change.yaml):\n", base_label.c_str());
    for (const std::string& change : files.changes) std::printf("  %s\n", change.c_str());
  } else {
    std::printf("\nno change from %s: best.yaml is that configuration unchanged, best_change.yaml sets nothing\n",
                base_label.c_str());
  }
  std::printf("\nNSGA-III %s.", result.settling.c_str());
  std::printf(
      "\n%zu SLAM runs, %zu cache hits, %.1f s. Wrote the parameter files (best.yaml, best_change.yaml for "
      "slam_toolbox; best_slam_karto.yaml, best_slam_karto_change.yaml for slam_karto) and %zu report files "
      "(report.html, results.json, tables, maps, figures) to %s\n",
      result.evaluation_count, result.cache_hits, result.wall_s, report_files, dir.c_str());
  for (const std::string& line : HowToLoad(dir, result.node_mode)) std::printf("%s\n", line.c_str());
}

int RunOptimize(OptimizeArgs args, const CLI::App& app) {
  TuningProcess process;
  if (process.is_worker()) return process.Serve();
  process.FitJobs(app, args.run);
  RunFolder folder(args.out, args.resume);
  folder.LockIfWritable();
  if (folder.resume()) {
    PrepareResume(folder, app, args);
  } else {
    folder.RefuseHeldRun();
  }
  args.population_given = app.get_option("--population")->count() > 0;
  args.divisions_given = app.get_option("--divisions")->count() > 0;
  args.generations_given = app.get_option("--generations")->count() > 0;
  args.sound_answer_given = app.get_option("--sound-answer-window")->count() > 0;
  if (args.inputs.log.empty() && !folder.resume()) {  // the built-in world's budget
    if (!args.population_given) args.population = kBuiltInPopulation;
    if (!args.generations_given) args.generations = kBuiltInGenerations;
    if (!args.divisions_given) args.divisions = kBuiltInDivisions;
  }

  // Preamble: every input is loaded and validated before any work starts.
  const TuningInputs inputs = LoadTuningInputs(args.inputs, args.run.quiet ? InputNotes::kDataLoss : InputNotes::kAll);
  OptimizationPlan plan = PlanOptimization(inputs, folder, args);
  const optim::OptimizeSettings& settings = plan.settings;
  folder.EnsureLocked();
  if (!folder.resume()) plan.settings.invocation = InvocationJson(args);
  process.SetupWorkers(args.inputs, settings.space.fixed, args.run, optim::WallDrawingFor(settings.objectives),
                       plan.context->stop_broken_runs);

  optim::EvaluationStore store(folder.db_path());
  Progress progress(args.run.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto);
  progress.Update(Headline(settings, inputs, process.Parallelism(args.run.jobs), folder.dir()), true);
  progress.Finish();

  optim::BatchEvaluator evaluator(EvaluateWith(plan.context), &store, args.run.jobs);
  plan.context->idle_slots = evaluator.idle_slots();  // before the first evaluation
  process.ShareWith(evaluator);
  optim::OptimizeHooks hooks = ProgressHooks(progress, plan.context, process, args.verbose);
  // From the committed start on, Ctrl-C or a kill says how to go on.
  std::optional<SignalNotice> notice;
  hooks.started = [&notice, &folder] {
    notice.emplace(
        fmt::format("every finished evaluation is saved: continue with `slamtune optimize --resume {}`", folder.dir()));
  };
  optim::OptimizeResult result = optim::RunOptimization(
      settings, evaluator, store, folder.resume() ? optim::OptimizationStart::kResume : optim::OptimizationStart::kNew,
      hooks);
  result.base_front_end = std::move(plan.base_front_end);
  progress.Finish();
  process.StopWorkers();  // the report's maps are rendered here

  const auto* best = result.Find("recommended");
  const slam::MapperParams best_params = plan.context->ParamsFor(best->record.params);
  const RecommendationFiles files = WriteRecommendationFiles(folder.dir(), inputs, best_params, result);
  for (const std::string& warning : files.warnings) std::fprintf(stderr, "slamtune: warning: %s\n", warning.c_str());
  if (result.verdict_kind == optim::VerdictKind::kBetter) result.changes = files.changes;
  result.how_to_load = HowToLoad(folder.dir(), inputs.base.node_mode);
  const auto summary = report::WriteOptimizeReport(result, folder.dir());
  if (!args.run.quiet) {
    PrintOutcome(result, files, summary.files.size(), settings.space, inputs.base_label, folder.dir());
    process.PrintWorkersShare(evaluator);
    if (args.verbose) std::printf("%s\n", optim::SharedWorkReport(*plan.context).c_str());
  }
  return 0;
}

const SubcommandRegistrar kOptimize{{
    "optimize",
    "Tune loop closure (r, g by default) with NSGA-III on a log, or on the built-in office world",
    40,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<OptimizeArgs>();
      app.add_option("LOG", args->inputs.log,
                     "CARMEN log (.clf/.log, plain or gzip) or a ROS 2 / ROS 1 recording (.mcap, .db3, bag folder, "
                     ".bag); none: the built-in world");
      ResultNeutralOptions& neutral = args->result_neutral;
      neutral.Add(app.add_option("--out", args->out, "output folder (created; must not hold another optimisation)"));
      neutral.Add(app.add_option("--resume", args->resume, "continue an interrupted optimisation in this folder"));
      app.add_option("--space", args->space_file,
                     "search-space YAML (vary: NAME: {min, max, step, type}; fix: NAME: V); 'loop' for r and g "
                     "around the base configuration; 'paper' for the seed paper's (r 2..6, g 6..20, p = 0.7, "
                     "q = 0.4); 'front-end' for sequential matching and node spacing plus r, g, p, q (maps that "
                     "break before any loop closes); default: 'loop', or 'front-end' when a run of the base "
                     "configuration shows its sequential matching losing its place");
      app.add_option("--vary", args->vary,
                     "search this parameter, NAME=MIN:MAX[:STEP] (repeatable; NAME a ROS name or r, g, p, q; an "
                     "integer parameter is searched by whole numbers): the search space without a YAML file");
      app.add_option("--fix", args->fix,
                     "hold a parameter at a value while --vary searches others, NAME=VALUE (repeatable)");
      app.add_option("--objectives", args->objectives,
                     "what the map is judged by: 'occupied' (unbacked hits u_h, corner pixels n_c and occupied "
                     "cells n_o, which also sees a corridor mapped twice side by side), 'drawn' (u_h, n_c and the "
                     "wall n_w that the same scans of the log draw along each run's path), 'consistency' (u_h, "
                     "n_c, enclosed areas n_e) or 'paper' (the seed paper's eta, n_c, n_e, which rewards a map for "
                     "breaking apart); 'auto': 'occupied' unless the search varies the node spacing, the laser "
                     "range or the resolution (which change the count of wall cells), then 'drawn'")
          ->capture_default_str();
      app.add_flag(
          "--no-early-stop", [args](std::int64_t) { args->settling.enabled = false; },
          "run every generation of the budget instead of stopping once the answer has settled");
      app.add_option("--stop-tolerance", args->settling.tolerance,
                     "settled when the non-dominated front moves less than this per generation (normalised by its "
                     "range) and the recommendation and knee stay the same...")
          ->capture_default_str();
      app.add_option("--stop-window", args->settling.window, "... for this many generations in a row")
          ->capture_default_str();
      app.add_option("--sound-answer-window", args->settling.sound_answer_window,
                     fmt::format("also stop once the recommended map is sound (its run did not fail) and the same for "
                                 "this many generations in a row; 0 = off (default 0; {} when the tuner searches the "
                                 "front end of a broken map)",
                                 optim::BrokenMapBudget{}.sound_answer_window));
      app.add_option("--population", args->population,
                     fmt::format("population size (default {}; {} on the built-in world; {} when the tuner "
                                 "searches the front end of a broken map; the seed paper's: 66 with --divisions 10)",
                                 args->population, kBuiltInPopulation, optim::BrokenMapBudget{}.population));
      app.add_option("--generations", args->generations,
                     fmt::format("the most generations (default {}; {} on the built-in world); the run stops earlier "
                                 "once the answer has settled, unless --no-early-stop",
                                 args->generations, kBuiltInGenerations));
      app.add_option("--divisions", args->divisions,
                     fmt::format("Das-Dennis divisions of the reference points (default {}: {} points for the "
                                 "three objectives; {} on the built-in world; {} for a broken map's front end)",
                                 args->divisions, nsga3::DasDennisCount(3, args->divisions), kBuiltInDivisions,
                                 optim::BrokenMapBudget{}.divisions));
      app.add_option("--seed", args->seed, "random seed: the same seed gives the same result")->capture_default_str();
      neutral.Add(args->run.AddParallelismTo(app));
      neutral.Add(app.add_flag("--verbose,-v", args->verbose,
                               "also show how much work the SLAM runs shared (cache statistics)"));
      neutral.Add(args->run.AddSharingTo(app));
      args->inputs.AddTo(app);
      app.footer(
          "Examples:\n"
          "  slamtune optimize --out runs/office-jump --world office-jump   # a built-in world whose defaults fail\n"
          "  slamtune optimize drive.mcap --out runs/drive                  # your recording; space chosen for you\n"
          "  slamtune optimize drive.mcap --out runs/drive2 --params my_slam_toolbox.yaml\n"
          "  slamtune optimize intel.clf.gz --out runs/intel --vary r=2:8:0.01 --vary g=4:20 --fix p=0.7\n"
          "  slamtune optimize aces.clf.gz --out runs/aces --space front-end --relations aces.relations\n"
          "  slamtune optimize --resume runs/drive                          # after Ctrl-C or a crash");
      return [args, &app] { return RunOptimize(*args, app); };
    },
}};

}  // namespace
}  // namespace slamtune::cli
