// `slamtune sweep [LOG] --vary NAME=LO:HI[:STEP] [--fix NAME=V]... --out DIR`: loop closures
// and the three map objectives (and errors, with relations) along one parameter — the seed
// paper's Figures 14-15 (g = 6..20 at r = 2; r = 2..6 by 0.25 at g = 18). Under mpirun, rank 0
// writes and the other ranks evaluate, as for optimize (optim/mpi_evaluation.h).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/tuning_inputs.h"
#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"
#include "slamtune/optim/batch_evaluator.h"
#include "slamtune/optim/mpi_evaluation.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/optim/slam_evaluation.h"
#include "slamtune/report/sweep_report.h"

namespace slamtune::cli {
namespace {

struct SweepArgs {
  TuningInputOptions inputs;
  std::string vary;
  std::vector<std::string> fix;
  std::string out;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  bool quiet = false;
  bool no_share = false;       // evaluate without the shared scan-match cache
  std::size_t share_mb = 512;  // MB, memory budget of the shared scan-match cache
};

int RunSweep(SweepArgs args, const CLI::App& app) {
  optim::MpiWorld world;
  if (world.rank() > 0) return ServeAsWorker(world);
  // Rank 0 of several: the workers wait for the setup; any error below stops them (destructor).
  std::optional<optim::MpiDispatcher> workers;
  if (world.distributed()) {
    workers.emplace(world);
    // One rank per core: rank 0 evaluates on one thread unless --jobs says otherwise.
    if (app.get_option("--jobs")->count() == 0) args.jobs = 1;
  }
  if (args.jobs < 1) throw InputError(fmt::format("--jobs = {} is out of range: must be >= 1", args.jobs));
  // --vary NAME=LO:HI[:STEP]
  const auto eq = args.vary.find('=');
  if (eq == std::string::npos) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + args.vary + "'");
  const std::string name = optim::FullParamName(args.vary.substr(0, eq));
  std::vector<std::string> parts;
  for (std::string rest = args.vary.substr(eq + 1);;) {
    const auto c = rest.find(':');
    parts.push_back(rest.substr(0, c));
    if (c == std::string::npos) break;
    rest = rest.substr(c + 1);
  }
  if (parts.size() < 2 || parts.size() > 3) throw InputError("--vary must be NAME=LO:HI[:STEP], got '" + args.vary + "'");
  const double lo = optim::ParseFlagNumber(parts[0], "--vary LO"), hi = optim::ParseFlagNumber(parts[1], "--vary HI");
  const double step = parts.size() == 3 ? optim::ParseFlagNumber(parts[2], "--vary STEP") : 1.0;
  if (!(lo <= hi)) throw InputError(fmt::format("--vary: bounds reversed ({} > {})", lo, hi));
  if (!(step > 0)) throw InputError(fmt::format("--vary: STEP must be > 0, got {}", step));
  if ((hi - lo) / step > 10000) throw InputError("--vary: more than 10000 values; use a larger STEP");
  if (args.out.empty()) throw InputError("--out DIR is required");

  TuningInputs inputs = LoadTuningInputs(args.inputs, args.quiet);
  auto context = MakeEvaluationContext(inputs, {}, args.no_share, args.share_mb);
  optim::Assignment fixed;
  for (const auto& f : args.fix) {
    const auto e = f.find('=');
    if (e == std::string::npos) throw InputError("--fix must be NAME=VALUE, got '" + f + "'");
    fixed[optim::FullParamName(f.substr(0, e))] = optim::ParseFlagNumber(f.substr(e + 1), "--fix " + f.substr(0, e));
  }
  std::vector<optim::Assignment> batch;
  for (int i = 0;; ++i) {
    const double v = lo + i * step;
    if (v > hi + 1e-9 * std::max(1.0, std::fabs(hi))) break;
    optim::Assignment a = fixed;
    a[name] = std::round(v * 1e9) / 1e9;  // 2 + 3 * 0.25 prints as 2.75, not 2.7500000000000004
    context->ParamsFor(a);                // validates names and values before any work
    batch.push_back(a);
  }
  std::error_code ec;
  std::filesystem::create_directories(args.out, ec);
  if (ec) throw InputError(args.out, 0, "cannot create output folder: " + ec.message());
  if (workers) {
    workers->Setup(WorkerSetup(args.inputs, {}, args.no_share, args.share_mb));
  }

  Progress progress(args.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto);
  const std::string parallelism =
      workers ? fmt::format("{} MPI ranks ({} evaluating on rank 0)", world.size(), args.jobs)
              : fmt::format("{} job{}", args.jobs, args.jobs == 1 ? "" : "s");
  progress.Update(fmt::format("sweeping {} over {} values on {} with {}", name, batch.size(), inputs.log_label,
                              parallelism),
                  true);
  progress.Finish();
  optim::BatchEvaluator evaluator([context](const optim::Assignment& a) { return optim::EvaluateSlam(*context, a); },
                                  nullptr, args.jobs);
  if (workers) evaluator.SetRemote(&*workers);
  evaluator.SetProgressCallback([&](const optim::EvaluationRecord& r, const optim::BatchEvaluatorStats& s) {
    progress.Update(fmt::format("{}/{} runs | last {}={:.4g}: {} loop closure{}", s.evaluated, batch.size(), name,
                                r.params.at(name), r.loop_closures, r.loop_closures == 1 ? "" : "s"));
  });
  const auto records = evaluator.Evaluate(batch);
  progress.Finish();
  if (workers) workers->Stop();
  std::vector<report::SweepPoint> points;
  for (std::size_t i = 0; i < batch.size(); ++i) points.push_back({batch[i].at(name), records[i]});
  report::SweepReportOptions options;
  options.log_path = inputs.log_label;
  options.log_input = inputs.log_input;
  const auto summary = report::WriteSweepReport(name, points, args.out, options);
  if (!args.quiet) {
    std::printf("%-10s %6s %10s %10s %9s%s\n", name.size() > 10 ? name.substr(0, 10).c_str() : name.c_str(), "loops",
                "eta", "corner_px", "enclosed", inputs.relations.empty() ? "" : "   trans_m  rot_deg");
    for (const auto& p : points) {
      std::printf("%-10.4g %6d %10.5f %10.0f %9.0f", p.value, p.record.loop_closures, p.record.occupied_ratio,
                  p.record.corner_pixels, p.record.enclosed_areas);
      if (p.record.has_gt) std::printf(" %9.4f %8.3f", p.record.trans_mean_m, p.record.rot_mean_deg);
      std::printf("%s\n", p.record.status == "ok" ? "" : ("  FAILED: " + p.record.reason).c_str());
    }
    std::printf("wrote %zu files to %s\n", summary.files.size(), args.out.c_str());
    if (workers) {
      std::printf("%zu of the SLAM runs ran on the %d worker ranks\n", evaluator.stats().remote, world.size() - 1);
    }
    std::printf("%s\n", optim::SharedWorkReport(*context).c_str());
  }
  return summary.failed > 0 ? 1 : 0;
}

const SubcommandRegistrar kRegistrar{{
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
      app.add_option("--jobs,-j", args->jobs,
                     "parallel SLAM runs (default: all cores; under mpirun: 1 on rank 0, each other rank runs one)");
      app.add_flag("--quiet,-q", args->quiet, "no progress output");
      app.add_flag("--no-share", args->no_share,
                   "do not share scan matches, solves and map scores between SLAM runs (same results, slower; for timing comparisons)");
      app.add_option("--share-mb", args->share_mb, "memory budget of the shared scan-match cache, MB (solves get half as much more, map scores a quarter, barycentres an eighth)")
          ->capture_default_str();
      args->inputs.AddTo(app);
      app.footer(
          "Examples:\n"
          "  slamtune sweep --vary r=2:6:0.5 --out runs/sweep_r             # the built-in world\n"
          "  slamtune sweep aces.clf.gz --vary g=4:20 --fix r=4 --relations aces.relations --out runs/aces_g");
      return [args, &app] { return RunSweep(*args, app); };
    },
}};

}  // namespace
}  // namespace slamtune::cli
