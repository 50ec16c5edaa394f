// `slamtune sweep [LOG] --vary NAME=LO:HI[:STEP] [--fix NAME=V]... --out DIR`: loop closures
// and the three map objectives (and errors, with relations) along one parameter — the seed
// paper's Figures 14-15 (g = 6..20 at r = 2; r = 2..6 by 0.25 at g = 18). Under mpirun, rank 0
// writes and the other ranks evaluate, as for optimize (optim/mpi_evaluation.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <filesystem>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"
#include "slamtune/optim/batch_evaluator.h"
#include "slamtune/optim/mpi_evaluation.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/optim/slam_evaluation.h"
#include "slamtune/report/sweep_report.h"
#include "slamtune/tune/tuning_process.h"

namespace slamtune::cli {
namespace {

struct SweepArgs {
  tune::TuningInputOptions inputs;
  tune::TuningRunOptions run;
  std::string vary;
  std::vector<std::string> fix;
  std::string out;
};

// --vary NAME=LO:HI[:STEP], NAME a full ROS name.
struct SweepRange {
  std::string name;
  double lo = 0, hi = 0, step = 1;
};

SweepRange ParseSweepRange(const std::string& vary) {
  const auto eq = vary.find('=');
  if (eq == std::string::npos) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + vary + "'");
  SweepRange range;
  range.name = optim::FullParamName(vary.substr(0, eq));
  std::vector<std::string> parts;
  for (std::string rest = vary.substr(eq + 1);;) {
    const auto c = rest.find(':');
    parts.push_back(rest.substr(0, c));
    if (c == std::string::npos) break;
    rest = rest.substr(c + 1);
  }
  if (parts.size() < 2 || parts.size() > 3) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + vary + "'");
  range.lo = optim::ParseFlagNumber(parts[0], "--vary LO");
  range.hi = optim::ParseFlagNumber(parts[1], "--vary HI");
  range.step = parts.size() == 3 ? optim::ParseFlagNumber(parts[2], "--vary STEP") : 1.0;
  if (!(range.lo <= range.hi)) throw InputError(fmt::format("--vary: bounds reversed ({} > {})", range.lo, range.hi));
  if (!(range.step > 0)) throw InputError(fmt::format("--vary: STEP must be > 0, got {}", range.step));
  if ((range.hi - range.lo) / range.step > 10000) {
    throw InputError("--vary: more than 10000 values; use a larger STEP");
  }
  return range;
}

// One assignment per value of `range`, each with the --fix values; every one validated before any work.
std::vector<optim::Assignment> SweepBatch(const SweepRange& range, const std::vector<std::string>& fix,
                                          const optim::SlamEvaluationContext& context) {
  optim::Assignment fixed;
  for (const auto& f : fix) {
    const auto e = f.find('=');
    if (e == std::string::npos) throw InputError("--fix must be NAME=VALUE, got '" + f + "'");
    fixed[optim::FullParamName(f.substr(0, e))] = optim::ParseFlagNumber(f.substr(e + 1), "--fix " + f.substr(0, e));
  }
  std::vector<optim::Assignment> batch;
  for (int i = 0;; ++i) {
    const double v = range.lo + i * range.step;
    if (v > range.hi + 1e-9 * std::max(1.0, std::fabs(range.hi))) break;
    optim::Assignment a = fixed;
    a[range.name] = std::round(v * 1e9) / 1e9;  // 2 + 3 * 0.25 prints as 2.75, not 2.7500000000000004
    context.ParamsFor(a);                       // validates names and values before any work
    batch.push_back(a);
  }
  return batch;
}

// The sweep as a table on stdout: one row per value.
void PrintSweepTable(const std::string& name, const std::vector<report::SweepPoint>& points, bool with_errors) {
  std::printf("%-10s %6s %10s %10s %9s%s\n", name.size() > 10 ? name.substr(0, 10).c_str() : name.c_str(), "loops",
              "eta", "corner_px", "enclosed", with_errors ? "   trans_m  rot_deg" : "");
  for (const auto& p : points) {
    std::printf("%-10.4g %6d %10.5f %10.0f %9.0f", p.value, p.record.loop_closures, p.record.occupied_ratio,
                p.record.corner_pixels, p.record.enclosed_areas);
    if (p.record.has_gt) std::printf(" %9.4f %8.3f", p.record.trans_mean_m, p.record.rot_mean_deg);
    std::printf("%s\n", p.record.status == optim::RunStatus::kOk ? "" : ("  FAILED: " + p.record.reason).c_str());
  }
}

int RunSweep(SweepArgs args, const CLI::App& app) {
  tune::TuningProcess process;
  if (process.is_worker()) return process.Serve();
  process.FitJobs(app.get_option("--jobs")->count() > 0, args.run);
  args.run.Validate();
  const SweepRange range = ParseSweepRange(args.vary);
  const std::string& name = range.name;
  if (args.out.empty()) throw InputError("--out DIR is required");

  tune::TuningInputs inputs =
      tune::LoadTuningInputs(args.inputs, args.run.quiet ? tune::InputNotes::kDataLoss : tune::InputNotes::kAll);
  auto context = tune::MakeEvaluationContext(inputs, {}, args.run);
  const std::vector<optim::Assignment> batch = SweepBatch(range, args.fix, *context);
  tune::CreateOutputFolder(args.out);
  process.SetupWorkers(args.inputs, {}, args.run, optim::WallDrawing::kSkip);

  Progress progress(args.run.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto);
  progress.Update(fmt::format("sweeping {} over {} values on {} with {}", name, batch.size(), inputs.log_label,
                              process.Parallelism(args.run.jobs)),
                  true);
  progress.Finish();
  optim::BatchEvaluator evaluator(tune::EvaluateWith(context), nullptr, args.run.jobs);
  process.ShareWith(evaluator);
  evaluator.SetProgressCallback([&](const optim::EvaluationRecord& r, const optim::BatchEvaluatorStats& s) {
    progress.Update(fmt::format("{}/{} runs | last {}={:.4g}: {} loop closure{}", s.evaluated, batch.size(), name,
                                r.params.at(name), r.loop_closures, r.loop_closures == 1 ? "" : "s"));
  });
  const auto records = evaluator.Evaluate(batch);
  progress.Finish();
  process.StopWorkers();
  std::vector<report::SweepPoint> points;
  for (std::size_t i = 0; i < batch.size(); ++i) points.push_back({batch[i].at(name), records[i]});
  report::SweepReportOptions options;
  options.log_path = inputs.log_label;
  options.log_input = inputs.log_input;
  const auto summary = report::WriteSweepReport(name, points, args.out, options);
  if (!args.run.quiet) {
    PrintSweepTable(name, points, !inputs.relations.empty());
    std::printf("wrote %zu files to %s\n", summary.files.size(), args.out.c_str());
    const std::string workers = process.WorkersShare(evaluator.stats());
    if (!workers.empty()) std::printf("%s\n", workers.c_str());
    std::printf("%s\n", optim::SharedWorkReport(*context).c_str());
  }
  return summary.failed > 0 ? 1 : 0;
}

const SubcommandRegistrar kSweep{{
    "sweep",
    "Loop closures and map objectives along one parameter (the paper's Figures 14-15)",
    45,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<SweepArgs>();
      app.add_option("LOG", args->inputs.log, "CARMEN log; none: the built-in world");
      app.add_option("--vary", args->vary, "NAME=LO:HI[:STEP] (r, g, p, q or any numeric ROS name); STEP 1 if omitted")
          ->required();
      app.add_option("--fix", args->fix, "NAME=VALUE held fixed (repeatable)");
      app.add_option("--out", args->out, "output folder")->required();
      AddParallelismFlags(app, args->run);
      AddSharingFlags(app, args->run);
      AddTuningInputFlags(app, args->inputs);
      app.footer(
          "Examples:\n"
          "  slamtune sweep --vary r=2:6:0.5 --out runs/sweep_r             # the built-in world\n"
          "  slamtune sweep aces.clf.gz --vary g=4:20 --fix r=4 --relations aces.relations --out runs/aces_g");
      return [args, &app] { return RunSweep(*args, app); };
    },
}};

}  // namespace
}  // namespace slamtune::cli
