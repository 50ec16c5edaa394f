// `slamtune sweep [LOG] --vary NAME=LO:HI[:STEP] [--fix NAME=V]... --out DIR`: loop closures
// and the three map objectives (and errors, with relations) along one parameter — the seed
// paper's Figures 14-15 (g = 6..20 at r = 2; r = 2..6 by 0.25 at g = 18); the work is
// tune/sweep_command.h. Under mpirun, rank 0 writes and the other ranks evaluate, as for optimize
// (optim/evaluation/mpi_evaluation.h).
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <memory>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/progress.h"
#include "slamtune/tune/optimize/tuning_process.h"
#include "slamtune/tune/sweep_command.h"

namespace slamtune::cli {
namespace {

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

int RunSweep(tune::SweepOptions options, const CLI::App& app) {
  tune::TuningProcess process;
  if (process.is_worker()) return process.Serve();
  process.FitJobs(app.get_option("--jobs")->count() > 0, options.run);
  Progress progress(options.run.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto);
  tune::SweepHooks hooks;
  hooks.started = [&progress](const std::string& headline) {
    progress.Update(headline, true);
    progress.Finish();
  };
  hooks.evaluated = [&progress](const tune::SweepStep& s) {
    progress.Update(fmt::format("{}/{} runs | last {}={:.4g}: {} loop closure{}", s.done, s.total, s.name, s.value,
                                s.loop_closures, s.loop_closures == 1 ? "" : "s"));
  };
  const tune::SweepOutcome outcome = tune::RunSweep(options, process, hooks);
  progress.Finish();
  if (!options.run.quiet) {
    PrintSweepTable(outcome.name, outcome.points, outcome.with_errors);
    std::printf("wrote %zu files to %s\n", outcome.report.files.size(), options.out.c_str());
    const std::string workers = process.WorkersShare(outcome.evaluations);
    if (!workers.empty()) std::printf("%s\n", workers.c_str());
    std::printf("%s\n", outcome.shared_work.c_str());
  }
  return outcome.report.failed > 0 ? 1 : 0;
}

const SubcommandRegistrar kSweep{{
    "sweep",
    "Loop closures and map objectives along one parameter (the paper's Figures 14-15)",
    45,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<tune::SweepOptions>();
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
