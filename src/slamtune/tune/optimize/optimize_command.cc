#include "slamtune/tune/optimize/optimize_command.h"

#include <fmt/format.h>

#include <cstdio>
#include <optional>

#include "slamtune/common/signal_notice.h"
#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/optim/evaluation_store.h"
#include "slamtune/optim/optimizer.h"
#include "slamtune/report/optimize_report.h"

namespace slamtune::tune {
namespace {

// The progress hooks of the optimisation: its lines (with the shared work's counts under
// `verbose`) and the candidates' maps.
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

}  // namespace

PreparedOptimization PrepareOptimization(OptimizeOptions& options, const TuningRunOptions& run, RunFolder& folder,
                                         TuningProcess& process) {
  PreparedOptimization prepared{LoadTuningInputs(options.inputs, run.quiet ? InputNotes::kDataLoss : InputNotes::kAll),
                                {}};
  prepared.plan = PlanOptimization(prepared.inputs, folder, options, run);
  folder.EnsureLocked();
  const optim::OptimizeSettings& settings = prepared.plan.settings;
  if (!folder.resume()) prepared.plan.settings.invocation = InvocationRecord(options);
  process.SetupWorkers(options.inputs, settings.space.fixed, run, optim::WallDrawingFor(settings.objectives),
                       prepared.plan.context->stop_broken_runs);
  return prepared;
}

OptimizeOutcome RunPreparedOptimization(PreparedOptimization& prepared, const TuningRunOptions& run, RunFolder& folder,
                                        TuningProcess& process, Progress& progress, bool verbose) {
  OptimizationPlan& plan = prepared.plan;
  optim::EvaluationStore store(folder.db_path());
  optim::BatchEvaluator evaluator(EvaluateWith(plan.context), &store, run.jobs);
  plan.context->idle_slots = evaluator.idle_slots();  // before the first evaluation
  process.ShareWith(evaluator);
  optim::OptimizeHooks hooks = ProgressHooks(progress, plan.context, process, verbose);
  std::optional<SignalNotice> notice;
  hooks.started = [&notice, &folder] {
    notice.emplace(
        fmt::format("every finished evaluation is saved: continue with `slamtune optimize --resume {}`", folder.dir()));
  };
  OptimizeOutcome out;
  out.result = optim::RunOptimization(
      plan.settings, evaluator, store,
      folder.resume() ? optim::OptimizationStart::kResume : optim::OptimizationStart::kNew, hooks);
  optim::OptimizeResult& result = out.result;
  result.base_front_end = std::move(plan.base_front_end);
  progress.Finish();
  process.StopWorkers();  // the report's maps are rendered here

  const auto* best = result.Find("recommended");
  const slam::MapperParams best_params = plan.context->ParamsFor(best->record.params);
  out.files = WriteRecommendationFiles(folder.dir(), prepared.inputs, best_params, result);
  if (result.verdict_kind == optim::VerdictKind::kBetter) result.changes = out.files.changes;
  result.how_to_load = HowToLoad(folder.dir(), prepared.inputs.base.node_mode);
  out.report_files = report::WriteOptimizeReport(result, folder.dir()).files.size();
  out.evaluations = evaluator.stats();
  out.shared_work = optim::SharedWorkReport(*plan.context);
  return out;
}

std::string OptimizeHeadline(const optim::OptimizeSettings& settings, const TuningInputs& inputs,
                             const std::string& parallelism, const std::string& dir) {
  const std::size_t total = settings.population * (settings.generations + 1);
  return fmt::format(
      "optimising {} on {}: population {}, {} generations (<= {} SLAM runs), {}, "
      "seed {}; maps judged by {}; results in {}",
      settings.space.size() == 2 ? "r and g" : "the search space", inputs.source.log_label, settings.population,
      settings.generations, total, parallelism, settings.seed, settings.objectives.Describe(), dir);
}

}  // namespace slamtune::tune
