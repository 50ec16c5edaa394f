// `slamtune optimize [LOG] --out DIR`: NSGA-III over the loop-closure parameters, scored by
// the map objectives of each SLAM run, with a report an engineer can act on (the work:
// tune/optimize/optimize_command.h). Under mpirun, rank 0 optimises and writes; the other ranks evaluate
// (optim/evaluation/mpi_evaluation.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/cli/result_neutral_options.h"
#include "slamtune/nsga3/reference_points.h"
#include "slamtune/optim/space_choice.h"
#include "slamtune/tune/optimize/optimize_command.h"
#include "slamtune/tune/optimize/tuning_process.h"

namespace slamtune::cli {
namespace {

struct OptimizeArgs {
  tune::OptimizeOptions options;
  std::string out;
  std::string resume;
  bool verbose = false;  // --verbose: the shared-work caches' statistics
  tune::TuningRunOptions run;
  ResultNeutralOptions result_neutral;  // the options that may accompany --resume
};

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
void PrintOutcome(const optim::OptimizeResult& result, const tune::RecommendationFiles& files, std::size_t report_files,
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
  for (const std::string& line : tune::HowToLoad(dir, result.node_mode)) std::printf("%s\n", line.c_str());
}

int RunOptimize(OptimizeArgs args, const CLI::App& app) {
  tune::TuningProcess process;
  if (process.is_worker()) return process.Serve();
  process.FitJobs(app.get_option("--jobs")->count() > 0, args.run);
  tune::RunFolder folder(args.out, args.resume);
  folder.LockIfWritable();
  if (folder.resume()) {
    tune::PrepareResume(folder, args.result_neutral.OnlyTheseGiven(app), args.options);
  } else {
    folder.RefuseHeldRun();
  }
  tune::PreparedOptimization prepared = tune::PrepareOptimization(args.options, args.run, folder, process);
  Progress progress(args.run.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto);
  progress.Update(
      tune::OptimizeHeadline(prepared.plan.settings, prepared.inputs, process.Parallelism(args.run.jobs), folder.dir()),
      true);
  progress.Finish();
  const optim::SearchSpace space = prepared.plan.settings.space;
  const tune::OptimizeOutcome outcome =
      tune::RunPreparedOptimization(prepared, args.run, folder, process, progress, args.verbose);
  for (const std::string& warning : outcome.files.warnings) {
    std::fprintf(stderr, "slamtune: warning: %s\n", warning.c_str());
  }
  if (!args.run.quiet) {
    PrintOutcome(outcome.result, outcome.files, outcome.report_files, space, prepared.inputs.base_label, folder.dir());
    const std::string workers = process.WorkersShare(outcome.evaluations);
    if (!workers.empty()) std::printf("%s\n", workers.c_str());
    if (args.verbose) std::printf("%s\n", outcome.shared_work.c_str());
  }
  return 0;
}

const SubcommandRegistrar kOptimize{{
    "optimize",
    "Tune loop closure (r, g by default) with NSGA-III on a log, or on the built-in office world",
    40,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<OptimizeArgs>();
      app.add_option("LOG", args->options.inputs.log,
                     "CARMEN log (.clf/.log, plain or gzip) or a ROS 2 / ROS 1 recording (.mcap, .db3, bag folder, "
                     ".bag); none: the built-in world");
      ResultNeutralOptions& neutral = args->result_neutral;
      neutral.Add(app.add_option("--out", args->out, "output folder (created; must not hold another optimisation)"));
      neutral.Add(app.add_option("--resume", args->resume, "continue an interrupted optimisation in this folder"));
      app.add_option("--space", args->options.space,
                     "search-space YAML (vary: NAME: {min, max, step, type}; fix: NAME: V); 'loop' for r and g "
                     "around the base configuration; 'paper' for the seed paper's (r 2..6, g 6..20, p = 0.7, "
                     "q = 0.4); 'front-end' for sequential matching and node spacing plus r, g, p, q (maps that "
                     "break before any loop closes); default: 'loop', or 'front-end' when a run of the base "
                     "configuration shows its sequential matching losing its place");
      app.add_option("--vary", args->options.vary,
                     "search this parameter, NAME=MIN:MAX[:STEP] (repeatable; NAME a ROS name or r, g, p, q; an "
                     "integer parameter is searched by whole numbers): the search space without a YAML file");
      app.add_option("--fix", args->options.fix,
                     "hold a parameter at a value while --vary searches others, NAME=VALUE (repeatable)");
      app.add_option("--objectives", args->options.objectives,
                     "what the map is judged by: 'occupied' (unbacked hits u_h, corner pixels n_c and occupied "
                     "cells n_o, which also sees a corridor mapped twice side by side), 'drawn' (u_h, n_c and the "
                     "wall n_w that the same scans of the log draw along each run's path), 'consistency' (u_h, "
                     "n_c, enclosed areas n_e) or 'paper' (the seed paper's eta, n_c, n_e, which rewards a map for "
                     "breaking apart); 'auto': 'occupied' unless the search varies the node spacing, the laser "
                     "range or the resolution (which change the count of wall cells), then 'drawn'")
          ->capture_default_str();
      app.add_flag(
          "--no-early-stop", [args](std::int64_t) { args->options.settling.enabled = false; },
          "run every generation of the budget instead of stopping once the answer has settled");
      app.add_option("--stop-tolerance", args->options.settling.tolerance,
                     "settled when the non-dominated front moves less than this per generation (normalised by its "
                     "range) and the recommendation and knee stay the same...")
          ->capture_default_str();
      app.add_option("--stop-window", args->options.settling.window, "... for this many generations in a row")
          ->capture_default_str();
      app.add_option("--sound-answer-window", args->options.budget.sound_answer_window,
                     fmt::format("also stop once the recommended map is sound (its run did not fail) and the same for "
                                 "this many generations in a row; 0 = off (default 0; {} when the tuner searches the "
                                 "front end of a broken map)",
                                 optim::BrokenMapBudget{}.sound_answer_window));
      app.add_option("--population", args->options.budget.population,
                     fmt::format("population size (default {}; {} on the built-in world; {} when the tuner "
                                 "searches the front end of a broken map; the seed paper's: 66 with --divisions 10)",
                                 optim::OptimizeSettings{}.population, tune::kBuiltInWorldBudget.population,
                                 optim::BrokenMapBudget{}.population));
      app.add_option("--generations", args->options.budget.generations,
                     fmt::format("the most generations (default {}; {} on the built-in world); the run stops earlier "
                                 "once the answer has settled, unless --no-early-stop",
                                 optim::OptimizeSettings{}.generations, tune::kBuiltInWorldBudget.generations));
      app.add_option("--divisions", args->options.budget.divisions,
                     fmt::format("Das-Dennis divisions of the reference points (default {}: {} points for the "
                                 "three objectives; {} on the built-in world; {} for a broken map's front end)",
                                 optim::OptimizeSettings{}.divisions,
                                 nsga3::DasDennisCount(3, optim::OptimizeSettings{}.divisions),
                                 tune::kBuiltInWorldBudget.divisions, optim::BrokenMapBudget{}.divisions));
      app.add_option("--seed", args->options.seed, "random seed: the same seed gives the same result")
          ->capture_default_str();
      neutral.Add(AddParallelismFlags(app, args->run));
      neutral.Add(app.add_flag("--verbose,-v", args->verbose,
                               "also show how much work the SLAM runs shared (cache statistics)"));
      neutral.Add(AddSharingFlags(app, args->run));
      AddTuningInputFlags(app, args->options.inputs);
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
