#include "slamtune/tune/tuning_inputs.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/relations.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/params_yaml.h"

namespace slamtune::tune {

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
  o.base_rule = j.at("base_rule").get<std::string>() == "node_defaults" ? slam::BaseRule::kNodeDefaults
                                                                        : slam::BaseRule::kPresetThenFile;
  return o;
}

namespace {

// The base configuration (slam/params/base_configuration.h). Its file's warnings are said unless
// nothing is (a worker rank): they are about the user's input, like data the log loses.
void LoadBase(const TuningInputOptions& options, InputNotes notes, TuningInputs* in) {
  slam::BaseConfiguration base =
      slam::LoadBaseConfiguration(options.params_file, options.preset, options.sets, options.base_rule);
  if (notes != InputNotes::kNone) PrintParamsWarnings(base);
  if (notes == InputNotes::kAll) {
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

sim::SimulationOptions WorldOptions(const TuningInputOptions& options) {
  sim::SimulationOptions world;
  world.world = options.world;
  world.seed = options.world_seed;
  return world;
}

TuningInputs LoadTuningInputs(const TuningInputOptions& options, InputNotes notes,
                              const std::function<void()>& before_log) {
  const bool quiet = notes != InputNotes::kAll;
  if (options.log.empty()) {  // before anything is said
    options.input.RequireLogForSlice(options.world);
    WorldOptions(options).Validate();
  }
  TuningInputs in;
  LoadBase(options, notes, &in);
  // The relations file is read before the log, which may take long; matched against it after.
  if (!options.relations.empty()) {
    in.relations = io::ReadRelations(options.relations);
    in.source.relations_label = options.relations;
  }
  if (before_log) before_log();
  if (options.log.empty()) {
    if (!quiet)
      std::fprintf(stderr, "no LOG given: simulating the built-in world '%s' (seed %u)\n", options.world.c_str(),
                   options.world_seed);
    sim::Simulation simulation = sim::Simulate(WorldOptions(options));
    in.log = std::make_shared<const io::LaserLog>(std::move(simulation.log));
    in.source.log_label = fmt::format("built-in world {} (seed {})", options.world, options.world_seed);
    if (options.relations.empty()) {
      in.relations = std::move(simulation.relations);
      in.source.relations_label = "simulated (true trajectory)";
    }
  } else {
    in.log = std::make_shared<const io::LaserLog>(ReadLog(options.log, options.input));
    in.source.log_label = options.log;
    in.source.log_input = io::DescribeLogInput(*in.log);
    if (notes != InputNotes::kNone) PrintLogInput(*in.log, quiet);
    io::RequireRanges(*in.log);
  }
  in.source.scans_not_used = io::ReadingLosses(*in.log, slam::LaserRuleOf(in.base.node_mode));
  if (!options.relations.empty()) {
    const metrics::RelationMatch match = metrics::RequireMatchingRelations(*in.log, in.relations, options.relations);
    if (!quiet && !match.complete()) WarnPartialRelations(options.relations, match);
  }
  return in;
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

}  // namespace slamtune::tune
