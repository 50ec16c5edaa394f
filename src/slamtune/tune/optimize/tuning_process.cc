#include "slamtune/tune/optimize/tuning_process.h"

#include <fmt/format.h>

namespace slamtune::tune {

nlohmann::json WorkerSetup(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                           const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs) {
  return {{"inputs", inputs.ToJson()},
          {"fixed", fixed},
          {"no_share", run.no_share},
          {"share_mb", run.share_mb},
          {"draw_wall", drawing == optim::WallDrawing::kDraw},
          {"stop_broken_runs", stop_broken_runs}};
}

std::shared_ptr<optim::SlamEvaluationContext> WorkerContext(const nlohmann::json& setup) {
  const TuningInputs inputs = LoadTuningInputs(TuningInputOptions::FromJson(setup.at("inputs")), InputNotes::kNone);
  TuningRunOptions run;
  run.no_share = setup.at("no_share").get<bool>();
  run.share_mb = setup.at("share_mb").get<std::size_t>();
  auto context = MakeEvaluationContext(inputs, setup.at("fixed").get<std::map<std::string, double>>(), run);
  optim::DrawWall(*context, setup.at("draw_wall").get<bool>() ? optim::WallDrawing::kDraw : optim::WallDrawing::kSkip);
  context->stop_broken_runs = setup.value("stop_broken_runs", false);
  return context;
}

int ServeAsWorker(const optim::MpiWorld& world) {
  optim::ServeEvaluations(
      world, [](const nlohmann::json& setup) -> optim::EvaluateFn { return EvaluateWith(WorkerContext(setup)); });
  return 0;
}

TuningProcess::TuningProcess() {
  if (world_.distributed() && world_.rank() == 0) workers_.emplace(world_);
}

void TuningProcess::FitJobs(bool jobs_given, TuningRunOptions& run) const {
  if (workers_ && !jobs_given) run.jobs = 1;
}

void TuningProcess::SetupWorkers(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                                 const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs) {
  if (workers_) workers_->Setup(WorkerSetup(inputs, fixed, run, drawing, stop_broken_runs));
}

void TuningProcess::ShareWith(optim::BatchEvaluator& evaluator) {
  if (workers_) evaluator.SetRemote(&*workers_);
}

void TuningProcess::StopWorkers() {
  if (workers_) workers_->Stop();
}

std::string TuningProcess::Parallelism(int jobs) const {
  return workers_ ? fmt::format("{} MPI ranks ({} evaluating on rank 0)", world_.size(), jobs)
                  : fmt::format("{} job{}", jobs, jobs == 1 ? "" : "s");
}

std::string TuningProcess::WorkersShare(const optim::BatchEvaluatorStats& evaluations) const {
  if (!workers_) return "";
  return fmt::format("{} of the SLAM runs ran on the {} worker ranks", evaluations.remote, world_.size() - 1);
}

}  // namespace slamtune::tune
