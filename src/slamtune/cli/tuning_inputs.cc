#include "slamtune/cli/tuning_inputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params_yaml.h"

namespace slamtune::cli {

void TuningInputOptions::AddTo(CLI::App& app) {
  app.add_option("--relations", relations, "Freiburg relations file: adds ground-truth errors to every evaluation");
  app.add_option("--world", world, "built-in world to simulate when no LOG is given (see `simulate --list`)")
      ->capture_default_str();
  app.add_option("--world-seed", world_seed, "seed of the simulated world")->capture_default_str();
  AddPresetOption(app, preset);
  app.add_option("--params", params_file,
                 "your slam_toolbox (ROS 2) or slam_karto (ROS 1) parameter file: the base of every run and the "
                 "baseline; keys it does not set take that node's own defaults");
  app.add_option("--set", sets, "override one base parameter, NAME=VALUE (repeatable)");
  input.AddTo(app);
}

CLI::Option* AddPresetOption(CLI::App& app, std::string& preset) {
  return app.add_option("--preset", preset,
                        "the node and its defaults: slam_karto (default), open_karto, slam_toolbox (asynchronous "
                        "node), slam_toolbox_sync or slam_toolbox_offline (synchronous node, which filters scans); "
                        "with --params, only the node's mode: the file's keys go over that node's declared "
                        "defaults");
}

void PrintParamsWarnings(const slam::BaseConfiguration& base) {
  for (const std::string& w : base.file_report.warnings) std::fprintf(stderr, "slamtune: warning: %s\n", w.c_str());
}

nlohmann::json TuningInputOptions::ToJson() const {
  nlohmann::json j{{"log", log},
                   {"relations", relations},
                   {"world", world},
                   {"world_seed", world_seed},
                   {"preset", preset},
                   {"params", params_file},
                   {"sets", sets},
                   {"input", input.ToJson()},
                   {"base_rule", base_rule == slam::BaseRule::kNodeDefaults ? "node_defaults" : "preset_then_file"}};
  // A file's identity: its size and modification time, so a changed file is noticed on --resume.
  for (const char* key : {"log", "relations", "params"}) {
    const std::string path = j[key];
    std::error_code ec;
    if (!path.empty() && std::filesystem::is_regular_file(path, ec)) {
      j[std::string(key) + "_bytes"] = std::filesystem::file_size(path, ec);
    }
  }
  return j;
}

TuningInputOptions TuningInputOptions::FromJson(const nlohmann::json& j) {
  TuningInputOptions o;
  o.log = j.at("log");
  o.relations = j.at("relations");
  o.world = j.at("world");
  o.world_seed = j.at("world_seed");
  o.preset = j.at("preset");
  o.params_file = j.at("params");
  o.sets = j.at("sets").get<std::vector<std::string>>();
  o.input = LogInputOptions::FromJson(j.at("input"));
  // Folders written before the rule applied --params over --preset's values.
  o.base_rule = j.value("base_rule", std::string("preset_then_file")) == "node_defaults"
                    ? slam::BaseRule::kNodeDefaults
                    : slam::BaseRule::kPresetThenFile;
  return o;
}

namespace {

void LoadBase(const TuningInputOptions& options, bool quiet, TuningInputs* in) {
  slam::BaseConfiguration base =
      slam::LoadBaseConfiguration(options.params_file, options.preset, options.sets, options.base_rule);
  if (!quiet) {
    PrintParamsWarnings(base);
    std::fprintf(stderr, "base: %s, modelling %s (mode: %s)\n", base.label.c_str(),
                 slam::LaunchOf(base.params.node_mode), base.mode_source.c_str());
  }
  in->base = std::move(base.params);
  in->base_label = std::move(base.label);
  in->base_file_text = std::move(base.file_text);
  in->base_node = base.node;
}

}  // namespace

void WarnPartialRelations(const std::string& relations_file, const metrics::RelationMatch& match) {
  std::fprintf(stderr, "slamtune: warning: %s: %s; the errors use those only\n", relations_file.c_str(),
               match.Brief().c_str());
}

TuningInputs LoadTuningInputs(const TuningInputOptions& options, InputNotes notes) {
  const bool quiet = notes != InputNotes::kAll;
  if (options.log.empty()) options.input.RequireLogForSlice(options.world);  // before anything is said
  TuningInputs in;
  LoadBase(options, quiet, &in);

  if (options.log.empty()) {
    sim::SimulationOptions sim_options;
    sim_options.world = options.world;
    sim_options.seed = options.world_seed;
    sim_options.Validate();
    if (!quiet)
      std::fprintf(stderr, "no LOG given: simulating the built-in world '%s' (seed %u)\n", options.world.c_str(),
                   options.world_seed);
    sim::Simulation simulation = sim::Simulate(sim_options);
    in.log = std::make_shared<const io::LaserLog>(std::move(simulation.log));
    in.log_label = fmt::format("built-in world {} (seed {})", options.world, options.world_seed);
    if (options.relations.empty()) {
      in.relations = std::move(simulation.relations);
      in.relations_label = "simulated (true trajectory)";
    }
  } else {
    in.log = std::make_shared<const io::LaserLog>(ReadLog(options.log, options.input));
    in.log_label = options.log;
    in.log_input = io::DescribeLogInput(*in.log);
    if (notes != InputNotes::kNone) PrintLogInput(*in.log, quiet);
    io::RequireRanges(*in.log);
  }
  in.scans_not_used = io::ReadingLosses(*in.log, slam::LaserRuleOf(in.base.node_mode));
  if (!options.relations.empty()) {
    in.relations = io::ReadRelations(options.relations);
    in.relations_label = options.relations;
    const metrics::RelationMatch match = metrics::RequireMatchingRelations(*in.log, in.relations, options.relations);
    if (!quiet && !match.complete()) WarnPartialRelations(options.relations, match);
  }
  return in;
}

std::vector<CLI::Option*> TuningRunOptions::AddParallelismTo(CLI::App& app) {
  return {app.add_option("--jobs,-j", jobs,
                         "parallel SLAM runs (default: all cores; under mpirun: 1 on rank 0, each other rank runs "
                         "one)"),
          app.add_flag("--quiet,-q", quiet, "no progress output")};
}

std::vector<CLI::Option*> TuningRunOptions::AddSharingTo(CLI::App& app) {
  return {app.add_flag("--no-share", no_share,
                       "do not share scan matches, solves and map scores between SLAM runs (same results, slower; for "
                       "timing comparisons)"),
          app.add_option("--share-mb", share_mb,
                         "memory budget of the shared scan-match cache, MB (solves get half as much more, map scores "
                         "a quarter, barycentres an eighth)")
              ->capture_default_str()};
}

void TuningRunOptions::Validate() const {
  if (jobs < 1) throw InputError(fmt::format("--jobs = {} is out of range: must be >= 1", jobs));
}

int TuningRunOptions::DefaultJobs() { return static_cast<int>(std::max(1u, std::thread::hardware_concurrency())); }

void ShareWork(optim::SlamEvaluationContext& context, const TuningRunOptions& run) {
  context.shared_work = {};
  context.map_scores = nullptr;
  if (run.no_share) return;
  if (run.share_mb == 0) throw InputError("--share-mb = 0 is out of range: must be >= 1 (or use --no-share)");
  optim::ShareWork(context, run.share_mb);
}

std::shared_ptr<optim::SlamEvaluationContext> MakeEvaluationContext(const TuningInputs& inputs,
                                                                    const std::map<std::string, double>& fixed,
                                                                    const TuningRunOptions& run) {
  auto context = std::make_shared<optim::SlamEvaluationContext>();
  context->log = inputs.log;
  context->relations = inputs.relations;
  context->base = inputs.base;
  ShareWork(*context, run);
  // Checked with the varied values by the command (a fixed value may fit only with them).
  for (const auto& [name, value] : fixed) slam::AssignNumeric(context->base, name, value);
  return context;
}

optim::EvaluateFn EvaluateWith(std::shared_ptr<const optim::SlamEvaluationContext> context) {
  return [context = std::move(context)](const optim::Assignment& a) { return optim::EvaluateSlam(*context, a); };
}

nlohmann::json WorkerSetup(const TuningInputOptions& inputs, const std::map<std::string, double>& fixed,
                           const TuningRunOptions& run, optim::WallDrawing drawing, bool stop_broken_runs) {
  return {{"inputs", inputs.ToJson()},
          {"fixed", fixed},
          {"no_share", run.no_share},
          {"share_mb", run.share_mb},
          {"draw_wall", drawing == optim::WallDrawing::kDraw},
          {"stop_broken_runs", stop_broken_runs}};
}

void CreateOutputFolder(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw InputError(dir, 0, "cannot create output folder: " + ec.message());
}

void EnsureWritableOutputFolder(const std::string& dir) {
  CreateOutputFolder(dir);
  const auto probe = std::filesystem::path(dir) / ".slamtune_write_test";
  {
    std::ofstream f(probe);
    if (!f) throw InputError(dir, 0, "output folder is not writable");
  }
  std::error_code ec;
  std::filesystem::remove(probe, ec);
}

int ServeAsWorker(const optim::MpiWorld& world) {
  optim::ServeEvaluations(world, [](const nlohmann::json& setup) -> optim::EvaluateFn {
    const TuningInputs inputs = LoadTuningInputs(TuningInputOptions::FromJson(setup.at("inputs")), InputNotes::kNone);
    TuningRunOptions run;
    run.no_share = setup.at("no_share").get<bool>();
    run.share_mb = setup.at("share_mb").get<std::size_t>();
    auto context = MakeEvaluationContext(inputs, setup.at("fixed").get<std::map<std::string, double>>(), run);
    optim::DrawWall(*context,
                    setup.at("draw_wall").get<bool>() ? optim::WallDrawing::kDraw : optim::WallDrawing::kSkip);
    context->stop_broken_runs = setup.value("stop_broken_runs", false);
    return EvaluateWith(std::move(context));
  });
  return 0;
}

TuningProcess::TuningProcess() {
  if (world_.distributed() && world_.rank() == 0) workers_.emplace(world_);
}

void TuningProcess::FitJobs(const CLI::App& app, TuningRunOptions& run) const {
  if (workers_ && app.get_option("--jobs")->count() == 0) run.jobs = 1;
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

void TuningProcess::PrintWorkersShare(const optim::BatchEvaluator& evaluator) const {
  if (workers_) {
    std::printf("%zu of the SLAM runs ran on the %d worker ranks\n", evaluator.stats().remote, world_.size() - 1);
  }
}

}  // namespace slamtune::cli
